// Lag-1 correlation t-test: the estimator, the t distribution's tails, "not applicable" cases.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/ttest.hpp"

namespace dpdrng_test::stats_test_ttest {

using namespace dpdrng;
using namespace dpdrng::stats;

namespace {

std::vector<double> iota_series(std::size_t n) {
  std::vector<double> x(n);
  std::iota(x.begin(), x.end(), 1.0);
  return x;
}
}  // namespace

// R: acf(1:10)$acf[2] = 0.7 and acf(1:5)$acf[2] = 0.4 (the estimator of the NIST/SEMATECH e-Handbook
// §1.3.5.12; by hand: Σ d_t d_{t+1} / Σ d_t² = 57.75 / 82.5 and 4 / 10).
TEST(Lag1, EstimatorMatchesRsAcf) {
  EXPECT_NEAR(*lag1_autocorrelation(iota_series(10)), 0.7, 1e-15);
  EXPECT_NEAR(*lag1_autocorrelation(iota_series(5)), 0.4, 1e-15);
}

// Alternating ±1 (even n): Σ d_t² = n and Σ d_t d_{t+1} = −(n−1), so r = −(n−1)/n.
TEST(Lag1, AlternatingSeriesIsNegativelyCorrelated) {
  std::vector<double> x(100);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = i % 2 ? 1.0 : -1.0;
  EXPECT_NEAR(*lag1_autocorrelation(x), -0.99, 1e-15);
  const Lag1Result r = lag1_ttest(x);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_LT(r.statistic, 0.0);
}

// Student t critical values (two-sided 0.01, i.e. the 0.995 quantile), NIST/SEMATECH e-Handbook table
// 1.3.6.7.2: ν = 10: 3.169; ν = 100: 2.626; and ν = 9498 (the paper's 9 500 numbers) is within 0.001 of the
// normal quantile 2.576. r is chosen so that B equals the critical value.
TEST(Lag1, PValueMatchesPublishedTCriticalValues) {
  const auto r_for = [](double t, double dof) { return t / std::sqrt(dof + t * t); };
  double t = 0.0;
  EXPECT_NEAR(correlation_p_value(r_for(3.169, 10), 12, &t), 0.01, 2e-5);
  EXPECT_NEAR(t, 3.169, 1e-12);
  EXPECT_NEAR(correlation_p_value(r_for(2.626, 100), 102), 0.01, 2e-5);
  EXPECT_NEAR(correlation_p_value(r_for(2.576, 9498), 9500), 0.01, 1e-4);
}

TEST(Lag1, StatisticIsTheCorrelationsT) {
  const Lag1Result r = lag1_ttest(iota_series(10));
  EXPECT_EQ(r.dof, 8u);
  EXPECT_NEAR(r.r, 0.7, 1e-15);
  EXPECT_NEAR(r.statistic, 0.7 * std::sqrt(8.0) / std::sqrt(1.0 - 0.49), 1e-12);
  // t = 2.772 on 8 dof lies between the 0.975 and 0.99 quantiles 2.306 and 2.896 (e-Handbook 1.3.6.7.2).
  EXPECT_GT(r.p_value, 0.02);
  EXPECT_LT(r.p_value, 0.05);
  EXPECT_EQ(r.verdict, Verdict::pass);
}

TEST(Lag1, ConstantSeriesIsNotApplicableNeverNaN) {
  // 0.1 is not exactly representable: a naive mean would leave tiny equal residues and r ≈ (n−1)/n.
  for (const double v : {0.0, 0.1, 1e300}) {
    const Lag1Result r = lag1_ttest(std::vector<double>(1000, v));
    EXPECT_EQ(r.verdict, Verdict::not_applicable);
    EXPECT_FALSE(std::isnan(r.r));
    EXPECT_FALSE(std::isnan(r.p_value));
    EXPECT_FALSE(r.reason.empty());
  }
  EXPECT_FALSE(lag1_autocorrelation(std::vector<double>(5, 0.1)).has_value());
}

TEST(Lag1, ShortSeriesIsNotApplicable) {
  EXPECT_EQ(lag1_ttest(std::vector<double>{0.1, 0.2}).verdict, Verdict::not_applicable);
  EXPECT_EQ(lag1_ttest(std::vector<double>{}).verdict, Verdict::not_applicable);
  EXPECT_NE(lag1_ttest(std::vector<double>{0.1, 0.2, 0.7}).verdict, Verdict::not_applicable);
}

TEST(Lag1, NonFiniteInputIsAnInputError) {
  std::vector<double> x(100, 0.5);
  x[3] = std::nan("");
  EXPECT_THROW(lag1_ttest(x), InputError);
  x[3] = -INFINITY;
  EXPECT_THROW(lag1_ttest(x), InputError);
}

// The paper's setting: 9 500 consecutive numbers. A good generator passes; a plain counter (a perfect histogram)
// has r ≈ 1 and fails by a mile.
TEST(Lag1, GoodGeneratorPassesCounterFails) {
  rng::GeneratorSpec spec;
  spec.name = "tea32";
  spec.rounds = 32;
  std::vector<std::uint64_t> w(9500);
  rng::fill_stream(rng::validated(spec), 777, 0, w);
  std::vector<double> u(w.size()), c(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) {
    u[i] = rng::to_unit(w[i]);
    c[i] = static_cast<double>(i) / static_cast<double>(w.size());
  }
  const Lag1Result good = lag1_ttest(u);
  EXPECT_EQ(good.dof, 9498u);
  EXPECT_EQ(good.verdict, Verdict::pass);
  EXPECT_GT(good.p_value, 0.05);
  const Lag1Result bad = lag1_ttest(c);
  EXPECT_GT(bad.r, 0.99);
  EXPECT_EQ(bad.verdict, Verdict::fail);
}

}  // namespace dpdrng_test::stats_test_ttest
