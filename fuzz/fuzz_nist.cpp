// The SP800-22 battery on arbitrary short bit strings with parameters drawn from the input around the edges of
// their rules. A parameter set that check_validity() accepts, inside SP800-22's recommended ranges or not, must run
// and give real P-values (or "not applicable" with a reason); one it refuses must make the test throw
// std::invalid_argument, not run.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/tests.hpp"
#include "fuzz_check.hpp"

using namespace dpdrng::stats::nist;
using dpdrng::fuzz::require;
using dpdrng::fuzz::require_probability;

namespace {

constexpr std::size_t kParameterBytes = 16;

// Small ranges that straddle every rule (the costly ends, m = 21 templates or 2^24 serial counts, are covered by
// the unit tests; here they would only slow the search down).
Parameters parameters_from(const std::uint8_t* b) {
  Parameters p;
  p.block_frequency_M = int(b[0]) - 4;
  p.non_overlapping_m = b[1] % 14;
  p.non_overlapping_blocks = b[2] % 20 - 1;
  if (b[3] & 1) p.non_overlapping_templates = {static_cast<std::uint32_t>(b[3] >> 1)};
  p.overlapping_m = b[4] % 34;
  p.overlapping_M = int(b[5]) * 8 - 16;
  p.overlapping_K = b[6] % 70 - 1;
  p.universal_L = b[7] % 18;
  p.universal_Q = int(static_cast<std::int8_t>(b[8])) * 4;
  p.approximate_entropy_m = b[9] % 20 - 1;
  p.serial_m = b[10] % 20 - 1;
  p.linear_complexity_M = int(b[11]) - 4 + 256 * (b[12] & 3);
  return p;
}

void check(const TestResult& r) {
  const std::string name(test_name(r.test));
  require(!r.values.empty(), name + " returned no P-value slot");
  if (!r.applicable) {
    require(!r.reason.empty(), name + " not applicable without a reason");
    return;
  }
  for (const auto& v : r.values)
    require_probability(v.p, name + " " + v.variant + " on " + std::to_string(r.n) + " bits: P outside [0, 1]");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < kParameterBytes) return 0;
  const Parameters p = parameters_from(data);
  const BitSequence s = BitSequence::from_bytes({data + kParameterBytes, size - kParameterBytes});
  for (const Test t : all_tests()) {
    // Outside SP800-22's recommended ranges (check_recommended) the tests still run and must still give
    // probabilities; outside their mathematics (check_validity) they must refuse.
    if (check_validity(t, p)) {
      try {
        run_test(t, s, p);
      } catch (const std::invalid_argument&) {
        continue;
      }
      dpdrng::fuzz::fail(std::string(test_name(t)) + " ran with parameters check_validity() refuses");
    }
    check(run_test(t, s, p));
  }
  return 0;
}
