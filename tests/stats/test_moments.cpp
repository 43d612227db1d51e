// Moments against exact answers (a hand-worked sample; the discrete uniform lattice, whose moments have closed
// forms) and against GSL's gsl_stats_* on a random sample; the intervals against normal theory.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/moments.hpp"

namespace dpdrng_test::stats_test_moments {

using namespace dpdrng::stats;

namespace {

std::vector<double> gaussian_sample(std::size_t n, double sd, unsigned long seed) {
  gsl_rng* r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, seed);
  std::vector<double> x(n);
  for (auto& v : x) v = gsl_ran_gaussian(r, sd);
  gsl_rng_free(r);
  return x;
}

// {1, 2, 3, 4, 10}: mean 4, deviations −3 −2 −1 0 6, Σd² = 50, Σd³ = 180, Σd⁴ = 1394, Σx² = 130.
TEST(Moments, HandWorkedSample) {
  const std::vector<double> x{1, 2, 3, 4, 10};
  const auto r = moments(x);
  EXPECT_EQ(r.n, 5u);
  EXPECT_DOUBLE_EQ(r.mean, 4.0);
  EXPECT_DOUBLE_EQ(r.variance, 50.0 / 4);
  EXPECT_DOUBLE_EQ(r.skewness, (180.0 / 5) / std::pow(50.0 / 5, 1.5));
  EXPECT_DOUBLE_EQ(r.kurtosis, (1394.0 / 5) / ((50.0 / 5) * (50.0 / 5)) - 3);
  EXPECT_DOUBLE_EQ(r.second_moment, 130.0 / 5);
  EXPECT_TRUE(r.reason.empty());
}

// N points √3·((2i + 1)/N − 1): mean 0, population variance (N² − 1)/N², so s² = (N + 1)/N, skewness 0 and
// excess kurtosis −6(N² + 1)/(5(N² − 1)) (the discrete uniform distribution); → U(−√3, √3)'s 1 and −1.2.
TEST(Moments, UniformLatticeHasTheClosedFormMoments) {
  const int N = 1000;
  std::vector<double> x;
  for (int i = 0; i < N; ++i) x.push_back(std::numbers::sqrt3 * ((2.0 * i + 1) / N - 1));
  const auto r = moments(x);
  const double n = N;
  EXPECT_NEAR(r.mean, 0.0, 1e-14);  // the running mean's rounding
  EXPECT_NEAR(r.variance, (n + 1) / n, 1e-13);
  EXPECT_NEAR(r.skewness, 0.0, 1e-12);
  EXPECT_NEAR(r.kurtosis, -6 * (n * n + 1) / (5 * (n * n - 1)), 1e-12);
  EXPECT_NEAR(r.second_moment, (n * n - 1) / (n * n), 1e-13);
  // Var(x²) of the lattice is about 4/5 (U(−√3,√3): E x⁴ − 1 = 9/5 − 1), so ⟨x²⟩'s 95 % half-width is
  // 1.96·√(0.8/N); 1 − 1/N² lies far inside it.
  EXPECT_NEAR(r.second_moment_ci.high - r.second_moment, 1.959964 * std::sqrt(0.8 / n), 1e-3 * std::sqrt(0.8 / n));
  EXPECT_GT(r.second_moment_p, 0.99);
}

// GSL's definitions: gsl_stats_variance is s² (n − 1); gsl_stats_skew and gsl_stats_kurtosis standardise by
// that s, so skew = g1·((n − 1)/n)^{3/2} and kurtosis + 3 = (g2 + 3)·((n − 1)/n)².
TEST(Moments, AgreeWithGslStats) {
  auto x = gaussian_sample(20000, 1.7, 5);
  for (auto& v : x) v = v * v * (v > 0 ? 1 : 0.3) + 2.5;  // skewed, heavy-tailed, off-centre
  const auto r = moments(x);
  const std::size_t n = x.size();
  const double f = (n - 1.0) / n;
  EXPECT_NEAR(r.mean, gsl_stats_mean(x.data(), 1, n), 1e-13);
  EXPECT_NEAR(r.variance / gsl_stats_variance(x.data(), 1, n), 1.0, 1e-12);
  EXPECT_NEAR(r.skewness * std::pow(f, 1.5) / gsl_stats_skew(x.data(), 1, n), 1.0, 1e-12);
  EXPECT_NEAR((r.kurtosis + 3) * f * f / (gsl_stats_kurtosis(x.data(), 1, n) + 3), 1.0, 1e-12);
}

// Merging parts gives the one-pass result of the whole (to rounding), as threads would.
TEST(Moments, MergedPartsEqualTheWhole) {
  const auto x = gaussian_sample(10001, 3.0, 6);
  MomentSums whole, a, b, c;
  for (std::size_t i = 0; i < x.size(); ++i) {
    whole.add(x[i] + 100);
    (i < 17 ? a : i < 6000 ? b : c).add(x[i] + 100);
  }
  a.merge(b);
  a.merge(c);
  EXPECT_EQ(a.n, whole.n);
  EXPECT_NEAR(a.mean / whole.mean, 1, 1e-14);
  EXPECT_NEAR(a.m2 / whole.m2, 1, 1e-12);
  EXPECT_NEAR(a.m3 / whole.m3, 1, 1e-8);
  EXPECT_NEAR(a.m4 / whole.m4, 1, 1e-12);
}

// For Gaussian data the fourth-moment interval of s² must agree with normal theory, Var(s²) = 2σ⁴/(n − 1).
TEST(Moments, VarianceIntervalMatchesNormalTheoryForGaussians) {
  const std::size_t n = 200000;
  const auto r = moments(gaussian_sample(n, 1.0, 7));
  const double half = 0.5 * (r.variance_ci.high - r.variance_ci.low);
  EXPECT_NEAR(half / (1.959964 * std::sqrt(2.0 / (n - 1))), 1.0, 0.02);
  EXPECT_LT(r.variance_ci.low, 1.0);
  EXPECT_GT(r.variance_ci.high, 1.0);
  EXPECT_GT(r.second_moment_p, 0.001);
  EXPECT_NEAR(r.kurtosis, 0.0, 5 * std::sqrt(24.0 / n));
}

// What the test is for: noise of variance 0.965 (a fluid 3.5 % cold) is refused at 10^5 draws.
TEST(Moments, SecondMomentTestSeesAThreePercentDeficit) {
  const auto r = moments(gaussian_sample(100000, std::sqrt(0.965), 8));
  EXPECT_LT(r.second_moment_p, 1e-10);
  EXPECT_LT(r.second_moment_ci.high, 1.0);
}

TEST(Moments, SmallAndBadInput) {
  const std::vector<double> three{1, 2, 3};
  const auto r = moments(three);
  EXPECT_FALSE(r.reason.empty());
  EXPECT_TRUE(std::isnan(r.variance_ci.low));
  EXPECT_THROW(moments(std::vector<double>{}), dpdrng::InputError);
  EXPECT_THROW(moments(std::vector<double>{1, NAN, 2, 3}), dpdrng::InputError);
  EXPECT_THROW(moments(three, 1.5), dpdrng::InputError);
}

}  // namespace

}  // namespace dpdrng_test::stats_test_moments
