// The decomposition sweep config reader (TOML): refused with an InputError naming the file, or a sweep whose
// every entry validates.
#include <cstdint>

#include "dpdrng/study/decomposition_sweep.hpp"
#include "fuzz_check.hpp"

using dpdrng::fuzz::require;
namespace study = dpdrng::study;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto sweep = dpdrng::fuzz::parse_or_refuse(data, size, study::parse_decomp_sweep);
  if (!sweep) return 0;
  const study::DecompSweep& s = *sweep;
  require(!s.generators.empty() && !s.seedings.empty() && !s.domains.empty() && !s.distributions.empty(),
          "a sweep accepted with an empty axis");
  for (const auto& g : s.generators) {
    study::DecompConfig c = s.base;
    c.noise.generator = g;
    for (const auto& seeding : s.seedings) {
      c.noise.seeding = seeding;
      c.validate();  // an InputError here escapes: the parser accepted what a run refuses
    }
  }
  return 0;
}
