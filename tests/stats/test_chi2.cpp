// χ² uniformity test: bin rule, statistic, P-values against published values, input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/chi2.hpp"

namespace dpdrng_test::stats_test_chi2 {

using namespace dpdrng;
using namespace dpdrng::stats;

namespace {

// Values at the centres of equal-width bins, counts[i] of them in bin i.
std::vector<double> with_counts(const std::vector<int>& counts) {
  std::vector<double> u;
  const double k = static_cast<double>(counts.size());
  for (std::size_t i = 0; i < counts.size(); ++i)
    for (int c = 0; c < counts[i]; ++c) u.push_back((static_cast<double>(i) + 0.5) / k);
  return u;
}
}  // namespace

// R: nclass.Sturges(x) = ceiling(log2(length(x)) + 1); the paper: 32 640 numbers -> 16 bins.
TEST(Chi2Uniform, SturgesBinsFollowRAndThePaper) {
  EXPECT_EQ(sturges_bins(32640), 16);
  EXPECT_EQ(sturges_bins(1024), 11);  // exact power of two: log2 = 10, no rounding up
  EXPECT_EQ(sturges_bins(1025), 12);
  EXPECT_EQ(sturges_bins(2), 2);
  EXPECT_EQ(sturges_bins(100), 8);    // R: nclass.Sturges(1:100) = 8
}

// Upper critical values of χ² at 0.01 from the NIST/SEMATECH e-Handbook table 1.3.6.7.4:
// ν = 1: 6.635, ν = 15: 30.578 (the paper's 16 bins), ν = 100: 135.807.
TEST(Chi2Uniform, UpperTailMatchesPublishedCriticalValues) {
  EXPECT_NEAR(chi2_upper_tail(6.635, 1), 0.01, 2e-5);
  EXPECT_NEAR(chi2_upper_tail(30.578, 15), 0.01, 2e-5);
  EXPECT_NEAR(chi2_upper_tail(135.807, 100), 0.01, 2e-5);
  EXPECT_EQ(chi2_upper_tail(0.0, 15), 1.0);
  EXPECT_EQ(chi2_upper_tail(1e6, 15), 0.0);  // underflow is an answer, not an error
}

// Hand computation: counts 30, 20, 25, 25 in 4 bins, N = 25 -> A = (25 + 25) / 25 = 2 on 3 dof.
// For odd ν the tail has a closed form (Abramowitz & Stegun 26.4.4):
// Q(2 | 3) = erfc(1) + sqrt(4/π) e^{-1} = 0.5724067.
TEST(Chi2Uniform, StatisticAndPValueOfAHandExample) {
  const auto u = with_counts({30, 20, 25, 25});
  const Chi2Result r = chi2_uniform(u, {.bins = 4, .alpha = 0.01});
  EXPECT_EQ(r.n, 100u);
  EXPECT_EQ(r.dof, 3);
  EXPECT_DOUBLE_EQ(r.expected, 25.0);
  EXPECT_EQ(r.counts, (std::vector<std::uint64_t>{30, 20, 25, 25}));
  EXPECT_DOUBLE_EQ(r.statistic, 2.0);
  EXPECT_NEAR(r.p_value, std::erfc(1.0) + std::sqrt(4.0 / M_PI) * std::exp(-1.0), 1e-12);
  EXPECT_NEAR(r.p_value, 0.5724067, 1e-7);
  EXPECT_EQ(r.verdict, Verdict::pass);
}

TEST(Chi2Uniform, LopsidedCountsFail) {
  const Chi2Result r = chi2_uniform(with_counts({60, 10, 15, 15}), {.bins = 4});
  // A = (35² + 15² + 10² + 10²) / 25 = 66 on 3 dof: p ≈ 3e-14.
  EXPECT_DOUBLE_EQ(r.statistic, 66.0);
  EXPECT_LT(r.p_value, 1e-10);
  EXPECT_EQ(r.verdict, Verdict::fail);
}

TEST(Chi2Uniform, BinEdgesAreHalfOpen) {
  std::vector<double> u(20, 0.25);
  u.insert(u.end(), 20, 0.5);                  // exactly on an edge: the upper bin
  u.insert(u.end(), 20, 1.0 - 0x1p-53);        // the largest value to_unit can give: the last bin
  const Chi2Result r = chi2_uniform(u, {.bins = 3});
  EXPECT_EQ(r.counts, (std::vector<std::uint64_t>{20, 20, 20}));
}

// The counts of shuffled values, lengths with every remainder modulo four, against a count of each bin by the
// definition (floor(u·k)) value after value.
TEST(Chi2Uniform, CountsOfShuffledValuesAreTheDefinitions) {
  std::uint64_t x = 88172645463325252ull;  // xorshift64 (Marsaglia 2003): any scattering of bins will do
  for (std::size_t n : {400, 401, 402, 403}) {
    std::vector<double> u(n);
    std::vector<std::uint64_t> expected(5, 0);
    for (auto& v : u) {
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      v = rng::to_unit(x);
      ++expected[static_cast<std::size_t>(std::floor(v * 5))];
    }
    EXPECT_EQ(chi2_uniform(u, {.bins = 5}).counts, expected) << n;
  }
}

// On generator words the test is the test on their to_unit values: the same counts, statistic and P-value, with
// Sturges' bins and with a count that is not a power of two (where u·k rounds).
TEST(Chi2Uniform, WordsGiveTheTestOfTheirUniforms) {
  std::uint64_t x = 2463534242ull;
  std::vector<std::uint64_t> words(32641);
  for (auto& w : words) x ^= x << 13, x ^= x >> 7, x ^= x << 17, w = x;
  words[5] = 0, words[6] = ~std::uint64_t{0};  // the ends of [0,1)
  std::vector<double> u(words.size());
  for (std::size_t t = 0; t < u.size(); ++t) u[t] = rng::to_unit(words[t]);
  for (const int bins : {0, 7, 1000}) {
    const Chi2Result a = chi2_uniform_words(words, {.bins = bins}), b = chi2_uniform(u, {.bins = bins});
    EXPECT_EQ(a.bins, b.bins);
    EXPECT_EQ(a.counts, b.counts) << bins;
    EXPECT_EQ(a.statistic, b.statistic);
    EXPECT_EQ(a.p_value, b.p_value);
  }
  EXPECT_EQ(chi2_uniform_words(std::span(words).first(16)).verdict, Verdict::not_applicable);
  EXPECT_THROW(chi2_uniform_words(words, {.bins = 1}), InputError);
}

// A plain counter i/n fills every bin exactly: the histogram is perfect although the sequence is as far from
// random as it gets. χ² cannot see this (the correlation checks can; see test_correlation.cpp).
TEST(Chi2Uniform, PlainCounterHasAPerfectHistogram) {
  const std::size_t n = 32640;
  std::vector<double> u(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = static_cast<double>(i) / static_cast<double>(n);
  const Chi2Result r = chi2_uniform(u);
  EXPECT_EQ(r.bins, 16);
  EXPECT_DOUBLE_EQ(r.statistic, 0.0);
  EXPECT_EQ(r.p_value, 1.0);
  EXPECT_EQ(r.verdict, Verdict::pass);
}

TEST(Chi2Uniform, RejectsValuesOutsideTheUnitIntervalAndNaN) {
  for (const double bad : {1.0, -0.1, 2.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    std::vector<double> u(100, 0.5);
    u[37] = bad;
    EXPECT_THROW(chi2_uniform(u), InputError) << bad;
  }
  EXPECT_THROW(chi2_uniform(std::vector<double>(100, 0.5), {.bins = 1}), InputError);
  EXPECT_THROW(chi2_uniform(std::vector<double>(100, 0.5), {.alpha = 0.0}), InputError);
}

TEST(Chi2Uniform, TooFewValuesIsNotApplicable) {
  const Chi2Result r = chi2_uniform(std::vector<double>(16, 0.5));  // Sturges: 5 bins, 3.2 expected each
  EXPECT_EQ(r.verdict, Verdict::not_applicable);
  EXPECT_FALSE(r.reason.empty());
  EXPECT_EQ(chi2_uniform(std::vector<double>{}).verdict, Verdict::not_applicable);
  EXPECT_EQ(chi2_uniform(std::vector<double>(39, 0.5), {.bins = 8}).verdict, Verdict::not_applicable);
  EXPECT_NE(chi2_uniform(std::vector<double>(40, 0.5), {.bins = 8}).verdict, Verdict::not_applicable);
}

// The paper's setting with a well-mixed generator (32TEA at 32 rounds on a counter): one step's 32 640 values.
// Fixed input, so the verdict is fixed; its p-value is far from alpha.
TEST(Chi2Uniform, GoodGeneratorPassesThePapersSetting) {
  rng::GeneratorSpec spec;
  spec.name = "tea32";
  spec.rounds = 32;
  std::vector<std::uint64_t> w(32640);
  rng::fill_stream(rng::validated(spec), 12345, 0, w);
  std::vector<double> u(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) u[i] = rng::to_unit(w[i]);
  const Chi2Result r = chi2_uniform(u);
  EXPECT_EQ(r.bins, 16);
  EXPECT_EQ(r.dof, 15);
  EXPECT_GT(r.p_value, 0.05);
  EXPECT_EQ(r.verdict, Verdict::pass);
}

}  // namespace dpdrng_test::stats_test_chi2
