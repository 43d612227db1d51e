#pragma once
// χ² goodness-of-fit test of uniformity on [0,1) with equal-width bins (the paper's first test).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

// Sturges' rule as R's nclass.Sturges computes it: k = ceil(log2 n) + 1, in exact integer arithmetic so that
// powers of two are not at the mercy of log2 rounding. n = 32 640 (one step of the paper's 256 beads) -> 16.
int sturges_bins(std::size_t n);

// Cochran's rule: below five expected counts per bin the χ² approximation is not trusted.
inline constexpr double kMinExpectedPerBin = 5.0;

struct Chi2Options {
  int bins = 0;  // 0 = Sturges' rule; otherwise the bin count (>= 2)
  double alpha = 0.01;
};

struct Chi2Result {
  std::size_t n = 0;
  int bins = 0;
  double expected = 0.0;  // N = n / bins, the expected count per bin
  std::vector<std::uint64_t> counts;
  double statistic = 0.0;  // A = Σ (n_i − N)² / N
  int dof = 0;             // bins − 1
  double p_value = 1.0;    // P(χ²(dof) >= A)
  double alpha = 0.01;
  Verdict verdict = Verdict::not_applicable;
  std::string reason;  // why the test is not applicable; empty otherwise
};

// u01: values in [0,1). Throws InputError for NaN or a value outside [0,1) (naming its index), and for
// options.bins of 1 or negative. Too few values for the bins: verdict not_applicable with the reason.
Chi2Result chi2_uniform(std::span<const double> u01, const Chi2Options& options = {});
// The same test on generator words, each taken as rng::to_unit(w) (always in [0,1)): chi2_uniform of those
// values, without storing them.
Chi2Result chi2_uniform_words(std::span<const std::uint64_t> words, const Chi2Options& options = {});

// Upper tail of χ²(dof) through GSL's regularised incomplete gamma function Q(dof/2, x/2).
double chi2_upper_tail(double x, int dof);
// Pearson's statistic Σ (c − e)² / e for counts that all expect the same e.
double chi2_statistic_equal(std::span<const std::uint64_t> counts, double expected);

}  // namespace dpdrng::stats
