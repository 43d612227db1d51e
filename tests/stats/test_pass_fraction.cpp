// Pass fractions: counting verdicts, their interval and test (binomial.hpp, tested in test_binomial.cpp), chunking.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/pass_fraction.hpp"
#include "dpdrng/stats/ttest.hpp"

namespace dpdrng_test::stats_test_pass_fraction {

using namespace dpdrng;
using namespace dpdrng::stats;

namespace {

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

// The verdict is the interval's: 154 of 160 at α = 0.01 lies inside the 99 % interval [0.905, 0.998] of a
// good generator's 0.99, so it passes (the R-style test once called it a failure at p = 0.0057).
TEST(PassFraction, VerdictAgreesWithItsInterval) {
  const PassFraction pf = pass_fraction(154, 160, {.alpha = 0.01, .confidence = 0.99});
  EXPECT_LE(pf.ci_low, 0.99);
  EXPECT_GE(pf.ci_high, 0.99);
  EXPECT_GT(pf.binomial_p, 0.01);
  EXPECT_EQ(pf.verdict, Verdict::pass);
  const PassFraction low = pass_fraction(152, 160, {.alpha = 0.01, .confidence = 0.99});
  EXPECT_LT(low.ci_high, 0.99);
  EXPECT_EQ(low.verdict, Verdict::fail);
}

}  // namespace dpdrng_test::stats_test_pass_fraction
