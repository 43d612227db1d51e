// Summaries and t-tests against R's published outputs for the sleep data (Cushny & Peebles 1905, R's
// `sleep`; the outputs are those of ?t.test and ?sleep) and hand computations for the pooled run errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/summary.hpp"

namespace dpdrng_test::stats_test_mean_tests {

using namespace dpdrng::stats;

namespace {

const std::vector<double> kGroup1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kGroup2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};

// Two-sided P of Student's t by Simpson integration of its density: shares nothing with GSL.
double t_two_sided(double t, double dof) {
  const double c = std::exp(std::lgamma((dof + 1) / 2) - std::lgamma(dof / 2)) / std::sqrt(dof * M_PI);
  const auto f = [&](double x) { return c * std::pow(1 + x * x / dof, -(dof + 1) / 2); };
  const int n = 200000;
  const double a = 0, b = std::fabs(t), h = (b - a) / n;
  double s = f(a) + f(b);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * f(a + k * h);
  return 1 - 2 * s * h / 3;
}

}  // namespace

TEST(Summary, MeanSdMedian) {
  EXPECT_DOUBLE_EQ(mean(kGroup1), 0.75);
  EXPECT_NEAR(sample_sd(kGroup1), 1.789010, 1e-6);
  EXPECT_EQ(median(std::vector<double>{3, 1, 2}), 2.0);
  EXPECT_EQ(median(std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_TRUE(std::isnan(median(std::vector<double>{})));
  EXPECT_TRUE(std::isnan(sample_sd(std::vector<double>{1.0})));
}

// R: t.test(sleep$extra[1:10]) gives mean 0.75 and the 95 percent confidence interval -0.5297804 2.0297804.
TEST(Summary, MeanConfidenceIntervalMatchesR) {
  const MeanCI ci = mean_ci(kGroup1, 0.95);
  EXPECT_EQ(ci.n, 10u);
  EXPECT_NEAR(ci.mean - ci.half_width, -0.5297804, 1e-7);
  EXPECT_NEAR(ci.mean + ci.half_width, 2.0297804, 1e-7);
  EXPECT_TRUE(std::isnan(mean_ci(std::vector<double>{1.0}, 0.95).half_width));
}

// R: t.test(extra ~ group, data = sleep, var.equal = TRUE): t = -1.8608, df = 18, p-value = 0.07919, 95 percent
// confidence interval -3.363874 0.203874.
TEST(MeanTests, PooledMatchesR) {
  const TTest t = pooled_t(kGroup1, kGroup2);
  EXPECT_NEAR(t.t, -1.8608, 5e-5);
  EXPECT_EQ(t.dof, 18.0);
  EXPECT_NEAR(t.p_value, 0.07919, 5e-6);
  EXPECT_NEAR(t.diff - t.ci_half_width(0.95), -3.363874, 1e-6);
  EXPECT_NEAR(t.diff + t.ci_half_width(0.95), 0.203874, 1e-6);
}

// R: t.test(extra ~ group, data = sleep, paired = TRUE): t = -4.0621, df = 9, p-value = 0.002833, mean
// difference -1.58, 95 percent confidence interval -2.4598858 -0.7001142.
TEST(MeanTests, PairedMatchesR) {
  std::vector<double> d;
  for (std::size_t i = 0; i < kGroup1.size(); ++i) d.push_back(kGroup1[i] - kGroup2[i]);
  const TTest t = paired_t(d);
  EXPECT_NEAR(t.diff, -1.58, 1e-12);
  EXPECT_NEAR(t.t, -4.0621, 5e-5);
  EXPECT_EQ(t.dof, 9.0);
  EXPECT_NEAR(t.p_value, 0.002833, 5e-7);
  EXPECT_NEAR(t.diff - t.ci_half_width(0.95), -2.4598858, 1e-7);
  EXPECT_NEAR(t.diff + t.ci_half_width(0.95), -0.7001142, 1e-7);
}

// By hand: x = {1,2,3,4}, y = {2,4,6,8} have sums of squares 5 and 20 on 6 degrees of freedom; two runs that
// each report a variance of 2 on 5 degrees of freedom bring the pool to (25 + 20)/16 = 2.8125 on 16, so
// se = √(2.8125 · (1/4 + 1/4)) and t = −2.5 / se = −2.10819 on 16 degrees of freedom.
TEST(MeanTests, ExtraVarianceEstimatesArePooledByTheirDegreesOfFreedom) {
  const std::vector<double> x = {1, 2, 3, 4}, y = {2, 4, 6, 8};
  const std::vector<VarianceEstimate> runs = {{2.0, 5.0}, {2.0, 5.0}, {7.0, 0.0}};  // a 0-dof estimate is no estimate
  const TTest t = pooled_t(x, y, runs);
  EXPECT_EQ(t.dof, 16.0);
  EXPECT_NEAR(t.sd * t.sd, 2.8125, 1e-14);
  EXPECT_NEAR(t.t, -2.5 / std::sqrt(2.8125 * 0.5), 1e-12);
  EXPECT_NEAR(t.p_value, t_two_sided(t.t, 16), 1e-8);
  // One value a side: only the extra estimates give a variance.
  const TTest one = pooled_t(std::vector<double>{1.0}, std::vector<double>{2.0}, runs);
  EXPECT_EQ(one.dof, 10.0);
  EXPECT_NEAR(one.p_value, t_two_sided(-1.0 / std::sqrt(2.0 * 2.0), 10), 1e-8);
  EXPECT_TRUE(std::isnan(pooled_t(std::vector<double>{1.0}, std::vector<double>{2.0}).p_value));
  // No spread at all: equal means are certainly equal, different ones certainly not.
  EXPECT_EQ(pooled_t(std::vector<double>{1, 1}, std::vector<double>{1, 1}).p_value, 1.0);
  EXPECT_EQ(pooled_t(std::vector<double>{1, 1}, std::vector<double>{2, 2}).p_value, 0.0);
}

TEST(MeanTests, PairedPoolsExtraEstimates) {
  // d = {1, 2, 3}: sum of squares 2 on 2 dof; plus a variance 4 on 6 dof: (2 + 24)/8 = 3.25, se = √(3.25/3).
  const std::vector<double> d = {1, 2, 3};
  const std::vector<VarianceEstimate> runs = {{4.0, 6.0}};
  const TTest t = paired_t(d, runs);
  EXPECT_EQ(t.dof, 8.0);
  EXPECT_NEAR(t.t, 2.0 / std::sqrt(3.25 / 3.0), 1e-12);
  EXPECT_NEAR(t.p_value, t_two_sided(t.t, 8), 1e-8);
}

// Observations that vary far more than the extra estimates say (sd ≈ 13 against 1): the runs' errors miss a
// source of variation, so only the spread counts and the test is Student's own.
TEST(MeanTests, InconsistentExtraEstimatesAreLeftOut) {
  const std::vector<double> x = {0, 10, 20, 30}, y = {5, 15, 25, 35};
  const std::vector<VarianceEstimate> runs = {{1.0, 50.0}, {1.0, 50.0}};
  const TTest t = pooled_t(x, y, runs);
  EXPECT_FALSE(t.extra_pooled);
  EXPECT_EQ(t.dof, 6.0);
  EXPECT_EQ(t.p_value, pooled_t(x, y).p_value);
  // 25/6 against 3: F = 1.39 on (6, 100) degrees of freedom, P = 0.23: consistent, pooled.
  const std::vector<VarianceEstimate> closer = {{3.0, 50.0}, {3.0, 50.0}};
  EXPECT_TRUE(pooled_t(std::vector<double>{1, 2, 3, 4}, std::vector<double>{2, 4, 6, 8}, closer).extra_pooled);
}

// d = {0.5, 1.0, 1.5}: mean 1, s = 0.5, t = 1/(0.5/√3) = 2√3 with 2 dof. Student t with 2 dof has the
// closed-form tail Q(t) = (1 − t/√(t² + 2))/2 (Abramowitz & Stegun 26.7.3 for ν = 2), so p = 1 − √(12/14);
// t_{0.975, 2} = 4.302653 (any t table), CI half-width 4.302653 · 0.5/√3.
TEST(MeanTests, PairedClosedFormForTwoDegreesOfFreedom) {
  const TTest t = paired_t(std::vector<double>{0.5, 1.0, 1.5});
  EXPECT_DOUBLE_EQ(t.diff, 1.0);
  EXPECT_NEAR(t.p_value, 1 - std::sqrt(12.0 / 14.0), 1e-10);
  EXPECT_NEAR(t.ci_half_width(0.95), 4.302653 * 0.5 / std::sqrt(3.0), 1e-6);
  EXPECT_TRUE(std::isnan(paired_t(std::vector<double>{1.0}).p_value));
}

// z_{0.975} + z_{0.8} = 1.959964 + 0.841621 (any normal table): the factor 2.8 behind Lehr's rule n = 16/Δ² for
// two groups at α = 0.05 and 80 % power, reached as the degrees of freedom grow.
TEST(DetectableDifference, NormalLimitIsLehrsFactor) {
  EXPECT_NEAR(detectable_difference(1.0, 1e9, 0.05, 0.8), 1.959964 + 0.841621, 1e-5);
  EXPECT_NEAR(detectable_difference(0.25, 1e9, 0.05, 0.8), 0.25 * (1.959964 + 0.841621), 1e-5);
}

// Student t with 2 dof inverts in closed form: t_p = (2p − 1)/√(2p(1 − p)) (from Abramowitz & Stegun 26.7.3).
TEST(DetectableDifference, ClosedFormForTwoDegreesOfFreedom) {
  const auto t2 = [](double p) { return (2 * p - 1) / std::sqrt(2 * p * (1 - p)); };
  EXPECT_NEAR(detectable_difference(1.0, 2.0, 0.01, 0.9), t2(0.995) + t2(0.9), 1e-9);
}

// The approximation against the power it promises: t-tests of a true difference of that size, simulated with
// the standard library's generators (nothing shared with GSL), reject about 90 % of the time.
TEST(DetectableDifference, SimulatedPowerIsAsPromised) {
  const double dof = 20, alpha = 0.01, se = 1.0;
  const double delta = detectable_difference(se, dof, alpha, 0.9);
  const double crit = detectable_difference(1.0, dof, alpha, 0.5);  // t_{dof,1−α/2} (t_{dof,0.5} = 0)
  std::mt19937_64 g(7);
  std::normal_distribution<double> z;
  std::chi_squared_distribution<double> chi2(dof);
  const int n = 200000;
  int rejected = 0;
  for (int k = 0; k < n; ++k) {
    const double t = (delta + se * z(g)) / (se * std::sqrt(chi2(g) / dof));
    rejected += std::fabs(t) > crit;
  }
  EXPECT_NEAR(double(rejected) / n, 0.9, 0.01);  // binomial 1σ at n = 2·10⁵: 0.0007
}

TEST(DetectableDifference, UndefinedWithoutDegreesOfFreedom) {
  EXPECT_TRUE(std::isnan(detectable_difference(1.0, 0.0, 0.01, 0.9)));
  EXPECT_TRUE(std::isnan(detectable_difference(NAN, 5.0, 0.01, 0.9)));
  EXPECT_TRUE(std::isnan(detectable_difference(1.0, 5.0, 0.0, 0.9)));
}

}  // namespace dpdrng_test::stats_test_mean_tests
