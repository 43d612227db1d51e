// Pass fractions: Clopper–Pearson intervals and the exact binomial test against R's binom.test, chunking.
#include <gtest/gtest.h>
#include <gsl/gsl_errno.h>

#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/pass_fraction.hpp"
#include "dpdrng/stats/ttest.hpp"

using namespace dpdrng;
using namespace dpdrng::stats;

namespace {
const bool gsl_quiet = (gsl_set_error_handler_off(), true);

std::vector<double> unit_stream(int rounds, std::uint64_t start, std::size_t n) {
  rng::GeneratorSpec spec;
  spec.name = "tea32";
  spec.rounds = rounds;
  std::vector<std::uint64_t> w(n);
  rng::fill_stream(rng::validated(spec), start, 0, w);
  std::vector<double> u(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = rng::to_unit(w[i]);
  return u;
}
}  // namespace

// The example of R's ?binom.test (Conover 1971, p. 97f.): binom.test(c(682, 243), p = 3/4) prints
// p-value = 0.3825 and the 95 percent confidence interval 0.7076683 0.7654066.
TEST(PassFraction, MatchesRsBinomTestExample) {
  EXPECT_NEAR(binomial_test_p(682, 925, 0.75), 0.3825, 5e-5);
  const auto [lo, hi] = clopper_pearson(682, 925, 0.95);
  EXPECT_NEAR(lo, 0.7076683, 1e-7);
  EXPECT_NEAR(hi, 0.7654066, 1e-7);
}

// All n pass: the interval's lower end has the closed form ((1 − c)/2)^(1/n), the upper end is 1; none pass:
// the mirror image. (Clopper & Pearson 1934, the boundary cases of their construction.)
TEST(PassFraction, ClopperPearsonBoundaryCases) {
  auto [lo, hi] = clopper_pearson(100, 100, 0.95);
  EXPECT_NEAR(lo, std::pow(0.025, 0.01), 1e-12);
  EXPECT_EQ(hi, 1.0);
  std::tie(lo, hi) = clopper_pearson(0, 100, 0.95);
  EXPECT_EQ(lo, 0.0);
  EXPECT_NEAR(hi, 1.0 - std::pow(0.025, 0.01), 1e-12);
  std::tie(lo, hi) = clopper_pearson(0, 0, 0.95);
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, 1.0);
}

// Large counts, where GSL's beta inverse is most stressed: the interval must still bracket the estimate and
// its ends must hit the tail probabilities of the definition.
TEST(PassFraction, ClopperPearsonLargeCountsSatisfyTheDefinition) {
  const std::size_t n = 1000000, x = 990123;
  const auto [lo, hi] = clopper_pearson(x, n, 0.99);
  EXPECT_LT(lo, 0.990123);
  EXPECT_GT(hi, 0.990123);
  EXPECT_NEAR(hi - lo, 2 * 2.5758 * std::sqrt(0.990123 * 0.009877 / n), 2e-5);  // normal approximation
}

// 100 of 100 pass at α = 0.01: P(100) = 0.99^100 = 0.3660; every outcome but 99 (P = 0.99^99 = 0.3697) is no
// more likely, so R's two-sided p is 1 − 0.99^99 (hand computation of binom.test's definition).
TEST(PassFraction, BinomialTestByHand) {
  EXPECT_NEAR(binomial_test_p(100, 100, 0.99), 1.0 - std::pow(0.99, 99), 1e-12);
  EXPECT_NEAR(binomial_test_p(5, 10, 0.5), 1.0, 0.0);
  // 10 of 10 at p = 0.5: only 0 and 10 are as unlikely: 2 / 1024.
  EXPECT_NEAR(binomial_test_p(10, 10, 0.5), 2.0 / 1024.0, 1e-15);
  EXPECT_NEAR(binomial_test_p(0, 10, 0.5), 2.0 / 1024.0, 1e-15);
}

TEST(PassFraction, VerdictsAndNotApplicableCounting) {
  std::vector<Verdict> v(1000, Verdict::pass);
  for (int i = 0; i < 9; ++i) v[static_cast<std::size_t>(i) * 100] = Verdict::fail;
  v[1] = Verdict::not_applicable;
  v[2] = Verdict::not_applicable;
  const PassFraction ok = pass_fraction(v, {.alpha = 0.01, .confidence = 0.99});
  EXPECT_EQ(ok.trials, 998u);
  EXPECT_EQ(ok.passed, 989u);
  EXPECT_EQ(ok.not_applicable, 2u);
  EXPECT_NEAR(ok.fraction, 989.0 / 998.0, 1e-15);
  EXPECT_LE(ok.ci_low, 0.99);
  EXPECT_GE(ok.ci_high, 0.99);
  EXPECT_EQ(ok.verdict, Verdict::pass);

  for (int i = 0; i < 80; ++i) v[static_cast<std::size_t>(i) * 12 + 5] = Verdict::fail;
  const PassFraction bad = pass_fraction(v, {.alpha = 0.01, .confidence = 0.99});
  EXPECT_LT(bad.binomial_p, 1e-10);
  EXPECT_LT(bad.ci_high, 0.99);
  EXPECT_EQ(bad.verdict, Verdict::fail);

  EXPECT_EQ(pass_fraction(std::vector<Verdict>(3, Verdict::not_applicable)).verdict, Verdict::not_applicable);
  EXPECT_THROW(pass_fraction(5, 4), InputError);
}

TEST(PassFraction, PerChunkSplitsAndLeavesTheTail) {
  std::vector<double> x(1050, 0.5);
  std::vector<std::size_t> sizes;
  const auto out = per_chunk(x, 100, [&](std::span<const double> c) {
    sizes.push_back(c.size());
    return lag1_ttest(c);
  });
  EXPECT_EQ(out.size(), 10u);
  EXPECT_EQ(sizes, std::vector<std::size_t>(10, 100));
  EXPECT_EQ(verdicts_of(out), std::vector<Verdict>(10, Verdict::not_applicable));  // constant chunks
}

// How the study uses the tests: 200 chunks of one generator. 32TEA(32) is consistent with α; 32TEA(1) on a
// counter fails nearly every chunk. Fixed streams, so the verdicts are fixed.
TEST(PassFraction, GoodAndWeakGeneratorsOverManyChunks) {
  const std::size_t per = 2048, chunks = 200;
  const auto good = unit_stream(32, 1, per * chunks);
  const auto good_results = per_chunk(good, per, [](auto c) { return chi2_uniform(c); });
  const PassFraction g = pass_fraction(verdicts_of(good_results));
  EXPECT_EQ(g.trials, chunks);
  EXPECT_EQ(g.verdict, Verdict::pass);
  EXPECT_GT(g.binomial_p, 0.05);

  const auto weak = unit_stream(1, 1, per * chunks);
  const auto weak_results = per_chunk(weak, per, [](auto c) { return lag1_ttest(c); });
  const PassFraction w = pass_fraction(verdicts_of(weak_results));
  EXPECT_LT(w.fraction, 0.5);
  EXPECT_EQ(w.verdict, Verdict::fail);
}
