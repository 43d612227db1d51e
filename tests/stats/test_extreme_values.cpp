// Correlations of extreme values: a correlation does not change when a series is scaled, so values near ±1e300
// (whose squares overflow) or ±1e-300 (whose squares underflow) must give the r of the same numbers near 1.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/ttest.hpp"

namespace dpdrng_test::stats_test_extreme_values {

using namespace dpdrng::stats;

namespace {

std::vector<double> uniform(std::size_t n, unsigned seed, double lo, double hi) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> x(n);
  for (auto& v : x) v = u(g);
  return x;
}

std::vector<double> scaled(std::vector<double> x, double k) {
  for (auto& v : x) v *= k;
  return x;
}

// The textbook two-pass lag-1 autocorrelation, unscaled: the reference for ordinary data.
double plain_lag1(const std::vector<double>& x) {
  double m = 0;
  for (double v : x) m += v;
  m /= double(x.size());
  double c0 = 0, c1 = 0;
  for (std::size_t t = 0; t < x.size(); ++t) {
    c0 += (x[t] - m) * (x[t] - m);
    if (t + 1 < x.size()) c1 += (x[t] - m) * (x[t + 1] - m);
  }
  return c1 / c0;
}

}  // namespace

TEST(ExtremeValues, Lag1IsScaleInvariantUpToTheEdgesOfDouble) {
  const auto x = uniform(2000, 7, -1.0, 1.0);
  const Lag1Result ref = lag1_ttest(x, 0.01);
  ASSERT_NE(ref.verdict, Verdict::not_applicable);
  for (const double k : {1e300, -1e300, 1e-300, 1e-310}) {
    const Lag1Result r = lag1_ttest(scaled(x, k), 0.01);
    ASSERT_NE(r.verdict, Verdict::not_applicable) << k;
    EXPECT_NEAR(r.r, ref.r, 1e-12) << k;
    EXPECT_NEAR(r.p_value, ref.p_value, 1e-9) << k;
  }
  // A power of two is exact: the same bits.
  EXPECT_EQ(lag1_ttest(scaled(x, std::ldexp(1.0, 1000)), 0.01).r, ref.r);
}

TEST(ExtremeValues, OrdinaryDataGiveTheTextbookBits) {
  // Uniforms in [0, 1) and unit Gaussians: the scaling is exact, so nothing moves in the study's stored values.
  for (const auto& x : {uniform(5000, 1, 0.0, 1.0), scaled(uniform(5000, 2, -1.0, 1.0), 3.7)})
    EXPECT_EQ(lag1_ttest(x, 0.01).r, plain_lag1(x));
}

TEST(ExtremeValues, AlternatingHugeValuesAreAnticorrelated) {
  for (const double a : {1.0, 1e200, 1e300, 1e-300}) {
    std::vector<double> x(1000);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = i % 2 ? a : -a;
    const auto c = across_time_correlation(NoiseMatrix::pair_major(x, 1, x.size()), 1, 0.01);
    EXPECT_EQ(c.r, -1.0) << a;
    EXPECT_EQ(c.verdict, Verdict::fail) << a;
    // The lag-1 estimator sums n - 1 products over n squares: r = -(n - 1)/n for a perfect alternation.
    EXPECT_NEAR(lag1_ttest(x, 0.01).r, -999.0 / 1000.0, 1e-12) << a;
  }
}

TEST(ExtremeValues, CorrelationOfHugeUnrelatedSeriesIsSmall) {
  const auto x = scaled(uniform(4000, 3, -1.0, 1.0), 1.5e308), y = scaled(uniform(4000, 4, -1.0, 1.0), 1e-305);
  const auto c = correlation_ttest(x, y, 0.01);
  ASSERT_NE(c.verdict, Verdict::not_applicable);
  EXPECT_TRUE(std::isfinite(c.r));
  EXPECT_NEAR(c.r, correlation_ttest(scaled(x, 1e-308), scaled(y, 1e305), 0.01).r, 1e-12);
  EXPECT_LT(std::fabs(c.r), 0.1);
}

}  // namespace dpdrng_test::stats_test_extreme_values
