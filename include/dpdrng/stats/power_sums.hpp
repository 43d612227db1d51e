#pragma once
// Moments of a sample from its power sums n, Σx, Σx², Σx³, Σx⁴: what a run can accumulate in O(1) memory over
// millions of draws (and merge in a fixed order), and all that the moments and their large-sample confidence
// intervals need. Used for the ζ the DPD random force takes: its mean, variance (with a CI from the fourth
// moment), skewness, kurtosis, and ⟨ζ²⟩, which sets the kinetic temperature by fluctuation–dissipation.
#include <cstdint>
#include <span>
#include <string>

#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

struct PowerSums {
  std::uint64_t n = 0;
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;

  void add(double x) {
    const double x2 = x * x;
    ++n, s1 += x, s2 += x2, s3 += x2 * x, s4 += x2 * x2;
  }
  static PowerSums of(std::span<const double> x);  // throws InputError for a non-finite value
};

struct Interval {
  double lo = 0, hi = 0;
};

struct Moments {
  std::uint64_t n = 0;
  double mean = 0, mean_se = 0;
  double variance = 0;        // unbiased, Σ(x − x̄)²/(n − 1)
  Interval variance_ci;       // 95 %: variance ± z·√((m4 − m2²(n − 3)/(n − 1))/n), m_k central moments
  double second_moment = 0;   // ⟨x²⟩ = Σx²/n, the quantity the kinetic temperature is proportional to
  Interval second_moment_ci;  // 95 %: ⟨x²⟩ ± z·√((⟨x⁴⟩ − ⟨x²⟩²)/n)
  double skewness = 0;        // m3 / m2^{3/2}
  double kurtosis = 0;        // m4 / m2² (3 for a Gaussian, 1.8 for a uniform)
  double skewness_se = 0, kurtosis_se = 0;  // √(6/n), √(24/n): their normal-theory standard errors
  // ⟨x²⟩ = target (1 for the DPD noise) against the large-sample normal law of the mean of x²: two-sided.
  double second_moment_z = 0, second_moment_p = 1;
  Verdict verdict = Verdict::not_applicable;  // of that test at alpha
  std::string reason;                          // why not applicable
};

// Fewer than 4 values, or a sample with no spread: not_applicable (values left at zero but n and mean).
Moments moments(const PowerSums& s, double second_moment_target = 1.0, double alpha = 0.01);

}  // namespace dpdrng::stats
