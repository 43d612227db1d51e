#pragma once
// What every SP800-22 test returns: its statistic(s) and P-value(s), the parameters it ran with, and, when the
// input cannot support it, "not applicable" with the reason and the minimum size instead of a made-up P-value.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dpdrng::stats::nist {

// The reference's order (its test numbers 1..15) and names (finalAnalysisReport, experiment directories).
enum class Test {
  Frequency,
  BlockFrequency,
  CumulativeSums,
  Runs,
  LongestRun,
  Rank,
  FFT,
  NonOverlappingTemplate,
  OverlappingTemplate,
  Universal,
  ApproximateEntropy,
  RandomExcursions,
  RandomExcursionsVariant,
  Serial,
  LinearComplexity,
};
inline constexpr int kTestCount = 15;

std::string_view test_name(Test t);
// Short command-line name (e.g. "runs", "non-overlapping-template").
std::string_view test_cli_name(Test t);
// Accepts the reference name or the command-line name, case-insensitively.
std::optional<Test> parse_test(std::string_view name);

struct PValue {
  std::string variant;  // "-" for single-valued tests; "forward", "x=-4", a template's bits, "p1"/"p2", ...
  double statistic = NAN;
  double p = NAN;  // NaN when the test is not applicable
};

struct TestResult {
  Test test{};
  std::size_t n = 0;                // bits the test saw
  bool applicable = true;
  std::string reason;               // why not, when not applicable
  std::size_t min_bits = 0;         // the smallest n for which the test can run with these parameters
  std::vector<std::pair<std::string, double>> parameters;
  std::vector<PValue> values;       // every P-value of the test, in the reference's order

  double p(std::size_t i = 0) const { return values.at(i).p; }
  double min_p() const;
};

}  // namespace dpdrng::stats::nist
