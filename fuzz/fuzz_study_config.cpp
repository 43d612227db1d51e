// The study config reader (TOML): any text is either refused with an InputError naming the problem or gives a
// config whose cells can be enumerated and whose canonical form reads back to the same hash.
#include <cstdint>

#include "dpdrng/study/config.hpp"
#include "dpdrng/study/sweep.hpp"
#include "fuzz_check.hpp"

using namespace dpdrng;
using fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parsed = fuzz::parse_or_refuse(data, size, study::parse_config);
  if (!parsed) return 0;
  const study::StudyConfig& c = *parsed;
  require(!c.name.empty() && !c.generators.empty(), "a config accepted without a name or a generator");
  const auto cells = study::enumerate_cells(c);
  require(!cells.empty(), "a config accepted with no cells");
  for (const auto& cell : cells) require(!cell.id().empty(), "a cell without an id");
  require(study::parse_config(c.source_text, "fuzz.toml").hash == c.hash, "the same text gave two hashes");
  return 0;
}
