// Anderson–Darling: the statistic on a hand-worked sample, the p-value against published percentage points, and
// the size of the test on samples drawn by GSL.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/anderson_darling.hpp"

namespace dpdrng_test::stats_test_anderson_darling {

using namespace dpdrng::stats;

namespace {

// Five values whose U(−√3, √3) CDF is 0.1, 0.3, 0.5, 0.7, 0.9. By symmetry 1 − F(x_(n+1−i)) = F(x_(i)), so
// A² = −5 − (2/5)·(1·ln 0.1 + 3·ln 0.3 + 5·ln 0.5 + 7·ln 0.7 + 9·ln 0.9) = 0.13008...
TEST(AndersonDarling, HandWorkedStatistic) {
  std::vector<double> x;
  for (double f : {0.7, 0.1, 0.9, 0.5, 0.3}) x.push_back(std::numbers::sqrt3 * (2 * f - 1));
  const auto r = anderson_darling(x, FitTarget::uniform);
  const double expect =
      -5 - 0.4 * (std::log(0.1) + 3 * std::log(0.3) + 5 * std::log(0.5) + 7 * std::log(0.7) + 9 * std::log(0.9));
  EXPECT_NEAR(r.statistic, expect, 1e-13);
  EXPECT_EQ(r.verdict, Verdict::pass);
  // The same CDF values through N(0,1): Φ⁻¹ of 0.1, 0.3, 0.5, 0.7, 0.9.
  const std::vector<double> z{-1.2815515655446004, -0.5244005127080407, 0.0, 0.5244005127080407, 1.2815515655446004};
  EXPECT_NEAR(anderson_darling(z, FitTarget::gauss).statistic, expect, 1e-12);
}

// The limiting distribution against an independent computation of it: A² → Σ Y_j²/(j(j+1)) (Anderson & Darling
// 1952), whose characteristic function tools/ad_limit_reference.py inverts numerically (Gil-Pelaez, mpmath).
// The two agree within 2e-5 (measured 1.9e-5 at z = 1). The 5 % point 2.492 of Anderson & Darling (1954),
// JASA 49:765, and the 10 % point 1.933 of Stephens (1974), JASA 69:730, Table 1 (case 0), are among them.
TEST(AndersonDarling, LimitMatchesAnIndependentInversionAndPublishedPoints) {
  const double reference[][2] = {{0.5, 0.7468144}, {1.0, 0.3572667}, {1.5, 0.1764754}, {1.933, 0.0999946},
                                 {2.492, 0.0500222}, {3.857, 0.0102411}, {6.0, 0.0009673}};
  for (const auto& [z, tail] : reference) EXPECT_NEAR(1 - anderson_darling_cdf_limit(z), tail, 2e-5) << z;
  EXPECT_NEAR(1 - anderson_darling_cdf_limit(1.933), 0.10, 1e-4);
  EXPECT_NEAR(1 - anderson_darling_cdf_limit(2.492), 0.05, 1e-4);
  // Beyond z = 8 the leading asymptotic term; the inversion gives 1.32759e-5 at z = 10 and 1.13709e-4 at z = 8.
  EXPECT_NEAR(anderson_darling_p(1000000, 10.0) / 1.32759e-5, 1.0, 0.02);
  EXPECT_NEAR(anderson_darling_p(1000000, 8.0) / 1.13709e-4, 1.0, 0.03);
  EXPECT_NEAR(anderson_darling_p(1000000, 8.0 + 1e-9) / 1.13709e-4, 1.0, 0.04);
  EXPECT_GT(anderson_darling_p(1000000, 30.0), 0.0);  // tiny, not a floor set by the correction's residual
  EXPECT_LT(anderson_darling_p(1000000, 30.0), 1e-12);
  // The finite-n correction vanishes as n grows and stays small at n = 10.
  EXPECT_NEAR(anderson_darling_cdf(1000000, 2.492), anderson_darling_cdf_limit(2.492), 1e-6);
  EXPECT_NEAR(anderson_darling_cdf(10, 2.492), anderson_darling_cdf_limit(2.492), 5e-3);
}

// Under the null the p-value is uniform: at n = 20 (where the finite-n correction matters) the share below 0.1
// over 2000 GSL Gaussian samples lies within 4 binomial standard deviations of 0.1.
TEST(AndersonDarling, SizeOfTheTestOnGslSamples) {
  gsl_rng* g = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(g, 9);
  int below = 0;
  const int trials = 2000;
  std::vector<double> x(20);
  for (int t = 0; t < trials; ++t) {
    for (auto& v : x) v = gsl_ran_gaussian(g, 1.0);
    below += anderson_darling(x, FitTarget::gauss).p_value < 0.1;
  }
  gsl_rng_free(g);
  EXPECT_NEAR(below / double(trials), 0.1, 4 * std::sqrt(0.09 / trials));
}

TEST(AndersonDarling, SeesAThreePercentVarianceDeficitAndASupportViolation) {
  gsl_rng* g = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(g, 10);
  std::vector<double> x(200000), y(200000);
  for (auto& v : x) v = gsl_ran_gaussian(g, std::sqrt(0.965));
  for (auto& v : y) v = gsl_ran_flat(g, -std::numbers::sqrt3, std::numbers::sqrt3);
  gsl_rng_free(g);
  EXPECT_EQ(anderson_darling(x, FitTarget::gauss).verdict, Verdict::fail);
  EXPECT_EQ(anderson_darling(y, FitTarget::uniform).verdict, Verdict::pass);
  y[3] = 1.8;  // outside U(−√3, √3)
  const auto r = anderson_darling(y, FitTarget::uniform);
  EXPECT_TRUE(std::isinf(r.statistic));
  EXPECT_EQ(r.p_value, 0.0);
}

TEST(AndersonDarling, SmallAndBadInput) {
  EXPECT_EQ(anderson_darling(std::vector<double>{0.1, 0.2}, FitTarget::gauss).verdict, Verdict::not_applicable);
  EXPECT_THROW(anderson_darling(std::vector<double>{0, 1, NAN, 2, 3}, FitTarget::gauss), dpdrng::InputError);
  EXPECT_THROW(parse_fit_target("cauchy"), dpdrng::InputError);
}

}  // namespace

}  // namespace dpdrng_test::stats_test_anderson_darling
