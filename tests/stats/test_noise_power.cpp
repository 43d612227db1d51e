// The shift of two independent estimates against R's Welch t-test on the sleep data (Cushny & Peebles 1905, R's
// `sleep`; ?t.test prints t = −1.8608, df = 17.776, 95 % CI −3.3654832 … 0.2054832), and the noise-power
// prediction against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/stats/noise_power.hpp"
#include "dpdrng/stats/summary.hpp"

namespace dpdrng_test::stats_test_noise_power {

using namespace dpdrng::stats;

namespace {
const std::vector<double> kGroup1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kGroup2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
Measured of(const std::vector<double>& x) {
  return {mean(x), sample_sd(x) / std::sqrt(double(x.size())), double(x.size() - 1)};
}
}  // namespace

// Welch's interval is exactly the independent-runs shift: se² adds, Welch–Satterthwaite ν.
TEST(NoisePower, ShiftMatchesWelchOnSleepData) {
  const Shift s = independent_shift(of(kGroup1), of(kGroup2));
  EXPECT_NEAR(s.delta, -1.58, 1e-12);
  EXPECT_NEAR(s.delta / s.se, -1.8608, 5e-5);
  EXPECT_NEAR(s.dof, 17.776, 5e-4);
  EXPECT_NEAR(s.low, -3.3654832, 5e-7);
  EXPECT_NEAR(s.high, 0.2054832, 5e-7);
}

// Normal errors (ν = ∞): the half-width is 1.959964 standard errors (the normal 97.5 % quantile).
TEST(NoisePower, ShiftWithNormalErrorsUsesNormalQuantile) {
  const Shift s = independent_shift({1.04, 0.003}, {1.0, 0.004});
  EXPECT_NEAR(s.se, 0.005, 1e-15);
  EXPECT_NEAR(s.high - s.delta, 1.959964 * 0.005, 1e-8);
}

// ρ_k = φ^k (an AR(1) sequence) gives 1 + 2Σρ_k → (1 + φ)/(1 − φ) as K → ∞ (the integrated autocorrelation
// time of AR(1), e.g. Sokal, Monte Carlo Methods in Statistical Mechanics (1996), eq. 2.20); φ = 1/2: 3.
TEST(NoisePower, AutocorrelationFactorOfAr1) {
  std::vector<Measured> rho;
  for (int k = 1; k <= 60; ++k) rho.push_back({std::pow(0.5, k), 0.0});
  const NoisePower p = effective_noise_power({0.966, 0.0}, rho);
  EXPECT_NEAR(p.value, 0.966 * 3.0, 1e-12);
}

// T/T_ref is the ratio of the powers: 32TEA(1)'s halves feed (⟨ζ²⟩ = 0.966, uncorrelated) against an ideal
// reference predicts −3.4 %; errors add in quadrature relative to each power.
TEST(NoisePower, PredictedRatioAndItsError) {
  const std::vector<Measured> none;
  const NoisePower v = effective_noise_power({0.966, 0.002}, none);
  const NoisePower ref = effective_noise_power({1.0, 0.002}, none);
  const NoisePower r = predicted_temperature_ratio(v, ref);
  EXPECT_NEAR(r.value, 0.966, 1e-12);
  EXPECT_NEAR(r.se, 0.966 * std::hypot(0.002 / 0.966, 0.002), 1e-12);
  // A lag-1 correlation of 0.1 with se 0.01 raises the power by 20 % and adds 2·0.01 relative error.
  const std::vector<Measured> one = {{0.1, 0.01}};
  const NoisePower c = effective_noise_power({1.0, 0.0}, one);
  EXPECT_NEAR(c.value, 1.2, 1e-12);
  EXPECT_NEAR(c.se, 0.02, 1e-12);
}

}  // namespace dpdrng_test::stats_test_noise_power
