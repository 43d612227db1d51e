// The number readers of chi2/ttest/corr (u64, f64, text; the first byte picks the format) and the statistics
// that consume whatever they accept: every accepted value is finite, and every applicable result is a real
// P-value with |r| <= 1, however extreme the numbers.
#include <cstdint>
#include <span>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/input.hpp"
#include "dpdrng/stats/ttest.hpp"
#include "fuzz_check.hpp"

using namespace dpdrng;
using fuzz::require;
using fuzz::require_probability;

namespace {

void check(const stats::Lag1Result& r) {
  if (r.verdict == stats::Verdict::not_applicable) return;
  require(r.r >= -1.0 && r.r <= 1.0, "lag-1 r outside [-1, 1]");
  require_probability(r.p_value, "lag-1 p outside [0, 1]");
}

void check(const stats::CorrelationResult& r) {
  if (r.verdict == stats::Verdict::not_applicable) return;
  require(r.r >= -1.0 && r.r <= 1.0, "correlation r outside [-1, 1]");
  require_probability(r.p_value, "correlation p outside [0, 1]");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  constexpr stats::InputFormat kFormats[] = {stats::InputFormat::u64, stats::InputFormat::f64,
                                             stats::InputFormat::text};
  const stats::InputFormat format = kFormats[data[0] % 3];
  const std::span<const char> bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  std::vector<double> x;
  try {
    x = stats::decode_values(bytes, format, "fuzz");
  } catch (const InputError&) {
    return 0;
  }
  require(!x.empty(), "decode_values accepted an input without values");
  for (const double v : x) {
    require(std::isfinite(v), "decode_values accepted a non-finite value");
    if (format == stats::InputFormat::u64) require(v >= 0.0 && v < 1.0, "u64 word mapped outside [0, 1)");
  }
  check(stats::lag1_ttest(x, 0.01));
  check(stats::across_time_correlation(stats::NoiseMatrix::pair_major(x, 1, x.size()), 1, 0.01));
  if (x.size() % 2 == 0)
    check(stats::cross_pair_correlation(stats::NoiseMatrix::step_major(x, 2, x.size() / 2), 1, 0.01));
  try {
    const stats::Chi2Result c = stats::chi2_uniform(x, {0, 0.01});
    if (c.verdict != stats::Verdict::not_applicable) require_probability(c.p_value, "chi2 p outside [0, 1]");
  } catch (const InputError&) {
    // values outside [0, 1): refused, as documented
  }
  return 0;
}
