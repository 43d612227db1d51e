#pragma once
// Anderson–Darling goodness of fit of a sample against a fully specified continuous distribution: the
// distribution ζ should follow, N(0,1) for Gaussian noise or U(−√3, √3) for Groot & Warren's uniform noise.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

enum class FitTarget { gauss, uniform };
FitTarget parse_fit_target(std::string_view name);  // "gauss" or "uniform"; throws InputError
std::string_view to_string(FitTarget t);

struct AndersonDarlingResult {
  std::size_t n = 0;
  FitTarget target = FitTarget::gauss;
  double statistic = 0;  // A² = −n − (1/n) Σ (2i − 1)[ln F(x_(i)) + ln(1 − F(x_(n+1−i)))]; ∞ when a value
                         // lies where F is 0 or 1 (outside a uniform's support)
  double p_value = 1;    // P(A²_n ≥ statistic)
  double alpha = 0.01;
  Verdict verdict = Verdict::not_applicable;
  std::string reason;
};

// P(A² < z) for n → ∞ and for finite n, after Marsaglia & Marsaglia (2004), "Evaluating the Anderson–Darling
// distribution", J. Stat. Software 9(2): their approximation ADinf of the limiting distribution and their
// correction errfix(n, ADinf) for finite n, stated there to be within 2e-6 (asymptotic) for every z.
double anderson_darling_cdf_limit(double z);
double anderson_darling_cdf(std::size_t n, double z);

// Throws InputError for NaN or infinite values and alpha outside (0,1). Fewer than 5 values: not applicable
// (the finite-n correction is not fitted below that).
AndersonDarlingResult anderson_darling(std::span<const double> x, FitTarget target, double alpha = 0.01);

}  // namespace dpdrng::stats
