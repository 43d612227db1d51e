// The decomposition sweep config reader (TOML): refused with an InputError naming the file, or a sweep whose
// every entry validates.
#include <cstdint>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/decomposition_sweep.hpp"
#include "fuzz_check.hpp"

using namespace dpdrng;
using fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dpd::DecompSweep s;
  try {
    s = dpd::parse_decomp_sweep(text, "fuzz.toml");
  } catch (const InputError& e) {
    require(std::string(e.what()).rfind("fuzz.toml", 0) == 0, "a config error that does not name the file");
    return 0;
  }
  require(!s.generators.empty() && !s.seedings.empty() && !s.domains.empty() && !s.distributions.empty(),
          "a sweep accepted with an empty axis");
  for (const auto& g : s.generators) {
    dpd::DecompConfig c = s.base;
    c.noise.generator = g;
    for (const auto& seeding : s.seedings) {
      c.noise.seeding = seeding;
      c.validate();  // an InputError here escapes: the parser accepted what a run refuses
    }
  }
  return 0;
}
