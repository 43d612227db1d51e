#pragma once
// The whole SP800-22 battery on one sequence or many (OpenMP across sequences, results independent of the
// thread count), and the second-level assessment over many sequences.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "dpdrng/stats/nist/bitseq.hpp"
#include "dpdrng/stats/nist/parameters.hpp"
#include "dpdrng/stats/nist/result.hpp"

namespace dpdrng::stats::nist {

// All 15 tests in the reference's order.
std::vector<Test> all_tests();

TestResult run_test(Test t, const BitSequence& s, const Parameters& p = {});

// The chosen tests (all when empty) on one sequence, in the reference's order: 188 P-values for the defaults.
std::vector<TestResult> run_battery(const BitSequence& s, const Parameters& p = {}, std::span<const Test> tests = {});

// The battery on many sequences in parallel, on `threads` OpenMP threads (0: OpenMP's default); result[i]
// belongs to sequences[i], whatever the thread count.
std::vector<std::vector<TestResult>> run_battery(std::span<const BitSequence> sequences, const Parameters& p = {},
                                                 std::span<const Test> tests = {}, int threads = 0);

// SP800-22 4.2.1: the proportion of m sequences passing at level alpha must lie within
// (1-alpha) -+ 3 sqrt(alpha(1-alpha)/m). The one computation of that range, for the battery, its report and the
// study's.
struct ProportionRange {
  double low, high;
};
ProportionRange proportion_range(double alpha, double m);

// Second level for one P-value column (a test and variant) over m sequences (SP800-22 4.2).
struct Assessment {
  Test test{};
  std::string variant;
  int sample_size = 0;             // sequences where the test applied (Random Excursions: enough cycles)
  int passed = 0;                  // P >= alpha
  int reference_passed = 0;        // the same on P-values as the reference reads them back ("%f", then float)
  std::array<int, 10> bins{};      // C1..C10: P-values in [0,0.1), ..., [0.9,1]
  double uniformity_p = NAN;       // chi^2 over the 10 bins with the exact expectation m/10
  double reference_uniformity_p = NAN;  // the reference's: integer expectation m/10 truncated, P printed to 6 places
  double proportion_low = NAN, proportion_high = NAN;  // (1-alpha) -+ 3 sqrt(alpha(1-alpha)/m), as fractions
  int reference_min_pass = 0, reference_max_pass = 0;  // the reference's bounds: counts truncated to integers
  bool proportion_ok = false;      // exact bounds
  bool reference_proportion_ok = false;
  bool uniformity_ok = false;      // P_T >= 0.0001
  bool reference_uniformity_ok = false;
  bool ok() const { return proportion_ok && uniformity_ok; }
  bool reference_ok() const { return reference_proportion_ok && reference_uniformity_ok; }
};

// One row per P-value column (188 for the defaults), in the order of the first sequence's results.
std::vector<Assessment> assess(std::span<const std::vector<TestResult>> per_sequence, double alpha = 0.01);

}  // namespace dpdrng::stats::nist
