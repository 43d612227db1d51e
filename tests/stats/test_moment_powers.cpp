// MomentSums::from_powers: the central sums from the power sums a hot loop accumulates agree with the one-pass
// (Pébay) sums of the same values, for ζ-like samples (mean near zero) and for a skewed one with a mean of 1.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/stats/moments.hpp"

namespace dpdrng::stats::test_moment_powers {
namespace {

void expect_same_moments(const std::vector<double>& x, double tol) {
  MomentSums pebay;
  double s[4] = {0, 0, 0, 0};
  for (double v : x) {
    pebay.add(v);
    s[0] += v, s[1] += v * v, s[2] += v * v * v, s[3] += v * v * v * v;
  }
  const MomentSums powers = MomentSums::from_powers(x.size(), s[0], s[1], s[2], s[3]);
  EXPECT_EQ(powers.n, pebay.n);
  EXPECT_NEAR(powers.mean, pebay.mean, 1e-13);
  EXPECT_NEAR(powers.m2, pebay.m2, tol * pebay.m2);
  EXPECT_NEAR(powers.m3, pebay.m3, tol * pebay.m2 * std::sqrt(pebay.m2 / double(x.size())));
  EXPECT_NEAR(powers.m4, pebay.m4, tol * pebay.m4);
  const MomentsResult a = moments_of(powers), b = moments_of(pebay);
  EXPECT_NEAR(a.variance, b.variance, tol);
  EXPECT_NEAR(a.second_moment, b.second_moment, tol);
  EXPECT_NEAR(a.kurtosis, b.kurtosis, 10 * tol);
}

TEST(MomentPowers, AgreeWithOnePassSums) {
  std::mt19937_64 g(11);
  std::normal_distribution<double> normal;
  std::exponential_distribution<double> expo(1.0);
  std::vector<double> z(200000), e(200000);
  for (auto& v : z) v = normal(g);
  for (auto& v : e) v = expo(g);
  expect_same_moments(z, 1e-12);
  expect_same_moments(e, 1e-10);
}

TEST(MomentPowers, HandComputed) {
  // 1, 2, 3, 4, 5: Σx = 15, Σx² = 55, Σx³ = 225, Σx⁴ = 979; central: m2 = 10, m3 = 0, m4 = 34.
  const MomentSums s = MomentSums::from_powers(5, 15, 55, 225, 979);
  EXPECT_DOUBLE_EQ(s.mean, 3);
  EXPECT_DOUBLE_EQ(s.m2, 10);
  EXPECT_DOUBLE_EQ(s.m3, 0);
  EXPECT_DOUBLE_EQ(s.m4, 34);
  EXPECT_EQ(MomentSums::from_powers(0, 0, 0, 0, 0).n, 0u);
}

}  // namespace
}  // namespace dpdrng::stats::test_moment_powers
