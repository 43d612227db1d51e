// Correlation checks of pair noise: Pearson against a published example, the matrix layouts, and the point of
// the exercise: neighbouring-input weakness that χ² cannot see.
#include <gtest/gtest.h>

#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/tea.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/noise_tests.hpp"
#include "dpdrng/stats/pass_fraction.hpp"

namespace dpdrng_test::stats_test_correlation {

using namespace dpdrng;
using namespace dpdrng::stats;

namespace {

constexpr std::size_t kPairs = 2048, kSteps = 64;

// ζ(i = 0, j = p + 1, t) in [0,1) with the pair-step seeding of 32TEA(R): neighbouring pairs differ by one in
// the hash input, neighbouring steps by one in the key. Stored step-major, as a per-step tap writes it.
template <int R>
std::vector<double> pair_step_noise() {
  const rng::Tea32<R> g;
  std::vector<double> z(kPairs * kSteps);
  for (std::size_t t = 0; t < kSteps; ++t)
    for (std::size_t p = 0; p < kPairs; ++p)
      z[t * kPairs + p] = rng::to_unit(g.pair_step(0, static_cast<std::uint32_t>(p + 1), t, 7)[0]);
  return z;
}

PassFraction chi2_pass_fraction(const std::vector<double>& z) {
  return pass_fraction(verdicts_of(chi2_per_step(NoiseMatrix::step_major(z, kPairs, kSteps))));
}
}  // namespace

// Anscombe (1973), "Graphs in statistical analysis", data set I: r = 0.816; R's cor.test on it prints
// t = 4.2415, df = 9, p-value = 0.00217.
TEST(NoiseCorrelation, AnscombeQuartetSetOne) {
  const std::vector<double> x{10, 8, 13, 9, 11, 14, 6, 4, 12, 7, 5};
  const std::vector<double> y{8.04, 6.95, 7.58, 8.81, 8.33, 9.96, 7.24, 4.26, 10.84, 4.82, 5.68};
  const CorrelationResult r = correlation_ttest(x, y);
  EXPECT_EQ(r.n, 11u);
  EXPECT_EQ(r.dof, 9u);
  EXPECT_NEAR(r.r, 0.81642, 1e-5);
  EXPECT_NEAR(r.statistic, 4.2415, 1e-4);
  EXPECT_NEAR(r.p_value, 0.00217, 1e-5);
  EXPECT_EQ(r.verdict, Verdict::fail);
  EXPECT_EQ(correlation_ttest(x, y, 0.001).verdict, Verdict::pass);
}

TEST(NoiseCorrelation, DegenerateInputs) {
  const std::vector<double> x{1, 2, 3, 4}, c(4, 2.5);
  EXPECT_EQ(correlation_ttest(x, c).verdict, Verdict::not_applicable);
  EXPECT_EQ(correlation_ttest(std::vector<double>{1, 2}, std::vector<double>{2, 1}).verdict, Verdict::not_applicable);
  EXPECT_THROW(correlation_ttest(x, std::vector<double>{1, 2, 3}), InputError);
  const CorrelationResult perfect = correlation_ttest(x, std::vector<double>{3, 5, 7, 9});
  EXPECT_DOUBLE_EQ(perfect.r, 1.0);
  EXPECT_EQ(perfect.p_value, 0.0);
  EXPECT_EQ(perfect.verdict, Verdict::fail);
}

TEST(NoiseCorrelation, MatrixLayoutsAgree) {
  // 3 pairs x 4 steps; value = 10 * pair + step.
  const std::vector<double> pm{0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23};
  const std::vector<double> sm{0, 10, 20, 1, 11, 21, 2, 12, 22, 3, 13, 23};
  const auto a = NoiseMatrix::pair_major(pm, 3, 4), b = NoiseMatrix::step_major(sm, 3, 4);
  for (std::size_t p = 0; p < 3; ++p)
    for (std::size_t t = 0; t < 4; ++t) {
      EXPECT_EQ(a(p, t), 10.0 * p + t);
      EXPECT_EQ(b(p, t), 10.0 * p + t);
    }
  EXPECT_THROW(NoiseMatrix::pair_major(pm, 5, 4), InputError);
  // Couples pooled: (pairs − offset) × steps and pairs × (steps − lag).
  EXPECT_EQ(cross_pair_correlation(a, 1).n, 8u);
  EXPECT_EQ(across_time_correlation(a, 2).n, 6u);
  const std::vector<std::pair<std::size_t, std::size_t>> rows{{0, 2}};
  EXPECT_EQ(cross_pair_correlation(a, rows).n, 4u);
  EXPECT_THROW(cross_pair_correlation(a, std::vector<std::pair<std::size_t, std::size_t>>{{0, 3}}), InputError);
}

// A pitfall of docs/design.md in its purest form: a counter mapped to [0,1) gives every step a perfect histogram,
// and neighbouring pairs and steps are almost equal.
TEST(NoiseCorrelation, PlainCounterPassesChi2ButNotTheCorrelations) {
  std::vector<double> z(kPairs * kSteps);
  for (std::size_t t = 0; t < kSteps; ++t)
    for (std::size_t p = 0; p < kPairs; ++p)
      z[t * kPairs + p] = (static_cast<double>(p) + 0.001 * static_cast<double>(t)) / kPairs;
  EXPECT_EQ(chi2_pass_fraction(z).fraction, 1.0);
  const auto m = NoiseMatrix::step_major(z, kPairs, kSteps);
  const CorrelationResult cross = cross_pair_correlation(m), time = across_time_correlation(m);
  EXPECT_GT(cross.r, 0.99);
  EXPECT_EQ(cross.verdict, Verdict::fail);
  EXPECT_GT(time.r, 0.99);
  EXPECT_EQ(time.verdict, Verdict::fail);
}

// A real weak hash: 32TEA with 4 rounds, pair-step seeding. Every step's 2 048 values pass χ² (a pass fraction
// consistent with α) and neighbouring pairs look independent, but the same pair at consecutive steps is
// correlated (r ≈ 0.08 over 129 024 couples, p ~ 1e-200): only the across-time check catches it.
TEST(NoiseCorrelation, WeakHashPassesChi2ButFailsAcrossTime) {
  const auto z = pair_step_noise<4>();
  EXPECT_EQ(chi2_pass_fraction(z).verdict, Verdict::pass);
  const auto m = NoiseMatrix::step_major(z, kPairs, kSteps);
  const CorrelationResult time = across_time_correlation(m);
  EXPECT_GT(time.r, 0.05);
  EXPECT_LT(time.p_value, 1e-100);
  EXPECT_EQ(time.verdict, Verdict::fail);
}

// 1 round: neighbouring pairs and steps give nearly equal outputs (r > 0.99 both ways).
TEST(NoiseCorrelation, OneRoundHashIsCaughtBothWays) {
  const auto m_data = pair_step_noise<1>();
  const auto m = NoiseMatrix::step_major(m_data, kPairs, kSteps);
  EXPECT_GT(cross_pair_correlation(m).r, 0.99);
  EXPECT_GT(across_time_correlation(m).r, 0.99);
}

// 32 rounds: nothing to see, at any of the offsets and lags checked. Fixed inputs, so never flaky.
TEST(NoiseCorrelation, GoodHashPasses) {
  const auto z = pair_step_noise<32>();
  const auto m = NoiseMatrix::step_major(z, kPairs, kSteps);
  EXPECT_EQ(chi2_pass_fraction(z).verdict, Verdict::pass);
  for (std::size_t k : {1, 2}) {
    EXPECT_EQ(cross_pair_correlation(m, k).verdict, Verdict::pass) << "offset " << k;
    EXPECT_EQ(across_time_correlation(m, k).verdict, Verdict::pass) << "lag " << k;
  }
}

// The per-step and per-pair runners must test exactly the rows of the matrix, in either storage order.
TEST(NoiseCorrelation, PerStepAndPerPairRunnersTestTheRightRows) {
  const auto z = pair_step_noise<32>();
  const auto m = NoiseMatrix::step_major(z, kPairs, kSteps);
  const auto steps = chi2_per_step(m);
  ASSERT_EQ(steps.size(), kSteps);
  EXPECT_EQ(steps[5].statistic, chi2_uniform(std::span(z).subspan(5 * kPairs, kPairs)).statistic);

  std::vector<double> transposed(z.size());
  for (std::size_t p = 0; p < kPairs; ++p)
    for (std::size_t t = 0; t < kSteps; ++t) transposed[p * kSteps + t] = m(p, t);
  const auto pairs = lag1_per_pair(m);
  ASSERT_EQ(pairs.size(), kPairs);
  EXPECT_EQ(pairs[77].r, lag1_ttest(std::span(transposed).subspan(77 * kSteps, kSteps)).r);
  const auto pairs_pm = lag1_per_pair(NoiseMatrix::pair_major(transposed, kPairs, kSteps));
  EXPECT_EQ(pairs_pm[77].r, pairs[77].r);
  EXPECT_EQ(pass_fraction(verdicts_of(pairs)).verdict, Verdict::pass);
}

}  // namespace dpdrng_test::stats_test_correlation
