#pragma once
// Lag-1 serial-correlation t-test (the paper's second test): r = lag-1 autocorrelation of one series,
// B = r √(n−2) / √(1−r²) against Student's t with n−2 degrees of freedom, two-sided.
#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

// The sample autocorrelation at lag 1 as NIST/SEMATECH e-Handbook §1.3.5.12 and R's acf() define it:
// r = Σ_{t=1}^{n-1} (x_t − x̄)(x_{t+1} − x̄) / Σ_{t=1}^{n} (x_t − x̄)². It is the paper's formula with x̄²
// restored, (1/(n−1) Σ x_t x_{t+1} − x̄²) / (1/n Σ x_t² − x̄²), up to O(1/n) end terms, and computed in the
// centred form because the moment form loses digits when x̄² ≈ the mean square. |r| < 1 always.
// nullopt when r is undefined: fewer than two values, or all values equal.
std::optional<double> lag1_autocorrelation(std::span<const double> x);

struct Lag1Result {
  std::size_t n = 0;
  double r = 0.0;
  double statistic = 0.0;  // B
  std::size_t dof = 0;     // n − 2
  double p_value = 1.0;    // two-sided
  double alpha = 0.01;
  Verdict verdict = Verdict::not_applicable;
  std::string reason;
};

// Throws InputError for a non-finite value. Fewer than 3 values or a constant series: not_applicable.
Lag1Result lag1_ttest(std::span<const double> x, double alpha = 0.01);

// Two-sided P-value of a correlation coefficient r estimated from n pairs: t = r √(n−2)/√(1−r²) on n−2
// degrees of freedom (exact for bivariate normal data, asymptotically right for any finite variance).
// Also returns t through *t_out when given. Requires n >= 3.
double correlation_p_value(double r, std::size_t n, double* t_out = nullptr);

}  // namespace dpdrng::stats
