#pragma once
// Moments of a sample of the numbers the DPD force uses (ζ): mean, variance, skewness, excess kurtosis, and the
// raw second moment ⟨ζ²⟩, which sets the kinetic temperature through the fluctuation–dissipation theorem.
// Confidence intervals are distribution-free (central limit theorem with the sample's own higher moments), so a
// non-Gaussian ζ gets an honest interval.
#include <cstddef>
#include <span>
#include <string>

namespace dpdrng::stats {

// Running central moments, one value at a time or merged from parts (Pébay 2008, "Formulas for robust, one-pass
// parallel computation of covariances and arbitrary-order statistical moments", eqs. 1.1–1.4): no raw power sums,
// so a large mean does not cancel the spread.
struct MomentSums {
  std::size_t n = 0;
  double mean = 0, m2 = 0, m3 = 0, m4 = 0;  // m_k = Σ (x − mean)^k
  void add(double x);
  void merge(const MomentSums& other);
  // From the power sums n, Σx, Σx², Σx³, Σx⁴, which a hot loop accumulates with additions alone (the DPD engine's
  // ζ): fine when |mean| is small against the spread, as for ζ (|mean| ~ 1e-3, spread 1), where the cancellation
  // costs a few units in the last digit.
  static MomentSums from_powers(std::size_t n, double s1, double s2, double s3, double s4);
};

struct Interval {
  double low = 0, high = 0;
};

struct MomentsResult {
  std::size_t n = 0;
  double confidence = 0.95;
  double mean = 0;
  Interval mean_ci;      // mean ± z·s/√n
  double variance = 0;   // s² = Σ(x − mean)²/(n − 1)
  Interval variance_ci;  // s² ± z·√((m4/n − s⁴(n − 3)/(n − 1))/n): the fourth moment, not the normal theory
  double skewness = 0;   // g1 = (m3/n)/(m2/n)^{3/2}
  double kurtosis = 0;   // excess, g2 = (m4/n)/(m2/n)² − 3 (0 for a Gaussian, −1.2 for a uniform)
  // ⟨x²⟩ = Σx²/n against a stated value (1 for unit-variance noise): its interval and the two-sided z-test p.
  double second_moment = 0;
  Interval second_moment_ci;
  double second_moment_target = 1;
  double second_moment_p = 1;
  std::string reason;  // why the intervals are NaN (fewer than 4 values); empty otherwise
  // moments() of values so large or small that the variance or <x^2> (or their interval ends) cannot be held in
  // a double: those are NaN, and this says why; the test of <x^2> still holds (computed on scaled values).
  std::string out_of_range;
};

MomentsResult moments_of(const MomentSums& s, double confidence = 0.95, double second_moment_target = 1.0);
// Throws InputError for no values, a non-finite value, or confidence outside (0,1).
MomentsResult moments(std::span<const double> x, double confidence = 0.95, double second_moment_target = 1.0);

}  // namespace dpdrng::stats
