// Moments from power sums: hand-computed small samples, GSL's gsl_stats_* as the reference on a larger one, and
// the coverage of the variance's 95 % confidence interval on normal and uniform samples.
#include <gsl/gsl_statistics_double.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/power_sums.hpp"

namespace dpdrng::stats {
namespace {

TEST(PowerSums, HandComputedSample) {
  const std::vector<double> x{1, 2, 3, 4, 5};
  const Moments m = moments(PowerSums::of(x));
  EXPECT_EQ(m.n, 5u);
  EXPECT_DOUBLE_EQ(m.mean, 3.0);
  EXPECT_DOUBLE_EQ(m.variance, 2.5);
  EXPECT_NEAR(m.skewness, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.kurtosis, 1.7);  // central m4 = 34/5, m2 = 2
  EXPECT_DOUBLE_EQ(m.second_moment, 11.0);
}

// GSL's skew and kurtosis divide by the (n − 1) standard deviation; ours by the n one: convert.
TEST(PowerSums, AgreesWithGslOnASkewedSample) {
  std::mt19937_64 g(7);
  std::exponential_distribution<double> e(1.0);
  std::vector<double> x(10000);
  for (auto& v : x) v = e(g);
  const Moments m = moments(PowerSums::of(x));
  const double n = double(x.size());
  const double to_n = std::pow((n - 1) / n, 1.5);
  EXPECT_NEAR(m.mean, gsl_stats_mean(x.data(), 1, x.size()), 1e-12);
  EXPECT_NEAR(m.variance, gsl_stats_variance(x.data(), 1, x.size()), 1e-11);
  EXPECT_NEAR(m.skewness * to_n, gsl_stats_skew(x.data(), 1, x.size()), 1e-10);
  EXPECT_NEAR(m.kurtosis * std::pow((n - 1) / n, 2.0) - 3, gsl_stats_kurtosis(x.data(), 1, x.size()), 1e-9);
  EXPECT_GT(m.skewness, 1.8);  // an exponential's is 2
}

// The CI from the fourth moment covers the true variance about 95 % of the time for a normal (kurtosis 3) and a
// uniform of unit variance (kurtosis 1.8), where a normal-theory interval would be too wide; 400 samples of 2 000:
// coverage within 0.95 ± 3·√(0.95·0.05/400).
TEST(PowerSums, VarianceIntervalCoversAtItsLevel) {
  std::mt19937_64 g(2021);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uni(-std::sqrt(3.0), std::sqrt(3.0));
  for (int kind = 0; kind < 2; ++kind) {
    int covered = 0, second_covered = 0, passed = 0;
    for (int rep = 0; rep < 400; ++rep) {
      PowerSums s;
      for (int k = 0; k < 2000; ++k) s.add(kind == 0 ? normal(g) : uni(g));
      const Moments m = moments(s);
      covered += m.variance_ci.lo <= 1.0 && 1.0 <= m.variance_ci.hi;
      second_covered += m.second_moment_ci.lo <= 1.0 && 1.0 <= m.second_moment_ci.hi;
      passed += m.verdict == Verdict::pass;
    }
    const double tol = 3 * std::sqrt(0.95 * 0.05 / 400);
    EXPECT_NEAR(covered / 400.0, 0.95, tol) << kind;
    EXPECT_NEAR(second_covered / 400.0, 0.95, tol) << kind;
    EXPECT_NEAR(passed / 400.0, 0.99, 3 * std::sqrt(0.99 * 0.01 / 400)) << kind;
  }
}

// A variance 3.5 % low (32TEA(1)'s halves) is seen with 10⁵ draws: z ≈ −0.035 / √(2/10⁵) ≈ −7.8.
TEST(PowerSums, FlagsASecondMomentOffByThreePointFivePercent) {
  std::mt19937_64 g(3);
  std::normal_distribution<double> normal(0.0, std::sqrt(0.965));
  PowerSums s;
  for (int k = 0; k < 100000; ++k) s.add(normal(g));
  const Moments m = moments(s);
  EXPECT_EQ(m.verdict, Verdict::fail);
  EXPECT_LT(m.second_moment_z, -5);
  EXPECT_LT(m.variance_ci.hi, 0.975);
}

TEST(PowerSums, TooFewOrConstantIsNotApplicable) {
  EXPECT_EQ(moments(PowerSums::of(std::vector<double>{1, 2, 3})).verdict, Verdict::not_applicable);
  EXPECT_EQ(moments(PowerSums::of(std::vector<double>(10, 2.0))).verdict, Verdict::not_applicable);
  EXPECT_EQ(moments(PowerSums{}).reason, "empty sample");
  EXPECT_THROW(PowerSums::of(std::vector<double>{1, NAN}), InputError);
}

}  // namespace
}  // namespace dpdrng::stats
