// One binomial convention: the central exact test and the central Clopper–Pearson interval, checked against
// exact binomial tails computed with MPFR/GMP here, against R's published binom.test interval, and against each
// other (p < 1 − c exactly when the interval at confidence c excludes p0).
#include <gmp.h>
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <utility>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/binomial.hpp"

namespace dpdrng_test::stats_test_binomial {

using namespace dpdrng::stats;

namespace {

// P[X ≤ k] and P[X ≥ k] for X ~ Binomial(n, num/den), summed term by term in 256-bit floating point from exact
// binomial coefficients: an evaluation that shares nothing with GSL's incomplete beta function.
// p = num/den exactly when den > 0, else the double `p_double`.
std::pair<double, double> exact_tails(unsigned long k, unsigned long n, unsigned long num, unsigned long den,
                                      double p_double = 0) {
  mpfr_t p, q, term, low, high;
  mpz_t c;
  for (auto* v : {&p, &q, &term, &low, &high}) mpfr_init2(*v, 256);
  mpz_init(c);
  if (den > 0) {
    mpfr_set_ui(p, num, MPFR_RNDN);
    mpfr_div_ui(p, p, den, MPFR_RNDN);
  } else {
    mpfr_set_d(p, p_double, MPFR_RNDN);
  }
  mpfr_ui_sub(q, 1, p, MPFR_RNDN);
  mpfr_set_zero(low, 1);
  mpfr_set_zero(high, 1);
  mpfr_t pi, qi;
  mpfr_init2(pi, 256);
  mpfr_init2(qi, 256);
  for (unsigned long i = 0; i <= n; ++i) {
    mpz_bin_uiui(c, n, i);
    mpfr_set_z(term, c, MPFR_RNDN);
    mpfr_pow_ui(pi, p, i, MPFR_RNDN);
    mpfr_pow_ui(qi, q, n - i, MPFR_RNDN);
    mpfr_mul(term, term, pi, MPFR_RNDN);
    mpfr_mul(term, term, qi, MPFR_RNDN);
    if (i <= k) mpfr_add(low, low, term, MPFR_RNDN);
    if (i >= k) mpfr_add(high, high, term, MPFR_RNDN);
  }
  const std::pair<double, double> out{mpfr_get_d(low, MPFR_RNDN), mpfr_get_d(high, MPFR_RNDN)};
  for (auto* v : {&p, &q, &term, &low, &high, &pi, &qi}) mpfr_clear(*v);
  mpz_clear(c);
  return out;
}

bool interval_excludes(std::size_t k, std::size_t n, double p0, double confidence) {
  const auto [lo, hi] = clopper_pearson(k, n, confidence);
  return p0 < lo || p0 > hi;
}

}  // namespace

// The counts on which the study's two former conventions disagreed, at the χ² and lag-1 pass probability
// 0.99. Central P-values from exact tails (MPFR here; the same to 10 digits with Python's exact fractions:
// 0.01148518085, 0.01089924444, 0.01560717184, 0.01380998954). All lie above 0.01, and each 99 %
// Clopper–Pearson interval contains 0.99: a good generator's pass fraction, not a failure. (R's binom.test
// gives 0.00574, 0.00545, 0.00780 and 0.00958 for them: "different" at 1 % while its own interval says not.)
TEST(Binomial, CentralTestOnTheCountsThatSplitTheConventions) {
  const std::pair<unsigned long, unsigned long> counts[] = {{154, 160}, {311, 320}, {390, 400}, {981, 1000}};
  const double python[] = {0.01148518085, 0.01089924444, 0.01560717184, 0.01380998954};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto [k, n] = counts[i];
    const auto [le, ge] = exact_tails(k, n, 99, 100);
    const double expected = std::fmin(1.0, 2 * std::fmin(le, ge));
    const double p = binomial_test_p(k, n, 0.99);
    EXPECT_NEAR(p, expected, 1e-9 * expected) << k << "/" << n;
    EXPECT_NEAR(p, python[i], 1e-9) << k << "/" << n;
    EXPECT_GT(p, 0.01) << k << "/" << n;
    EXPECT_FALSE(interval_excludes(k, n, 0.99, 0.99)) << k << "/" << n;
  }
}

// The defining property of the pair: for every count, "p < 1 − c" and "the central interval at c excludes p0"
// are the same statement (monotonicity of the tails in p). Checked on every k for several n, p0 and c.
TEST(Binomial, TestAndIntervalAgreeEverywhere) {
  for (const std::size_t n : {1u, 7u, 40u, 160u, 1000u})
    for (const double p0 : {0.5, 0.9, 0.99})
      for (const double c : {0.95, 0.99})
        for (std::size_t k = 0; k <= n; ++k) {
          const double p = binomial_test_p(k, n, p0);
          // Away from the boundary itself, where the two computations may round differently.
          const double margin = 1e-9;
          if (std::fabs(p - (1 - c)) < margin) continue;
          EXPECT_EQ(p < 1 - c, interval_excludes(k, n, p0, c)) << k << "/" << n << " p0 " << p0 << " c " << c;
        }
}

// Exact tails by MPFR for a spread of cases, including far tails and small n.
TEST(Binomial, MatchesExactTails) {
  const unsigned long cases[][4] = {{0, 10, 1, 2},          {3, 10, 1, 2},      {10, 10, 1, 2}, {90, 100, 99, 100},
                                    {9000, 10000, 99, 100}, {50, 1000, 1, 100}, {1, 2, 1, 3}};
  for (const auto& c : cases) {
    const auto [le, ge] = exact_tails(c[0], c[1], c[2], c[3]);
    const double expected = std::fmin(1.0, 2 * std::fmin(le, ge));
    EXPECT_NEAR(binomial_test_p(c[0], c[1], double(c[2]) / double(c[3])), expected, 1e-9 * expected + 1e-300)
        << c[0] << "/" << c[1];
  }
}

// By hand: 100 of 100 at 0.99: P[X ≥ 100] = 0.99^100, P[X ≤ 100] = 1, so p = 2 · 0.99^100. 10 of 10 at 1/2: 2/1024.
TEST(Binomial, ByHand) {
  EXPECT_NEAR(binomial_test_p(100, 100, 0.99), 2 * std::pow(0.99, 100), 1e-12);
  EXPECT_EQ(binomial_test_p(5, 10, 0.5), 1.0);
  EXPECT_NEAR(binomial_test_p(10, 10, 0.5), 2.0 / 1024.0, 1e-15);
  EXPECT_NEAR(binomial_test_p(0, 10, 0.5), 2.0 / 1024.0, 1e-15);
  EXPECT_EQ(binomial_test_p(0, 0, 0.5), 1.0);
  EXPECT_THROW(binomial_test_p(5, 4, 0.5), dpdrng::InputError);
}

// R's ?binom.test example (Conover 1971, p. 97f.): binom.test(c(682, 243), p = 3/4) prints the 95 percent
// confidence interval 0.7076683 0.7654066 — R's interval is the central Clopper–Pearson one.
TEST(Binomial, ClopperPearsonMatchesRsInterval) {
  const auto [lo, hi] = clopper_pearson(682, 925, 0.95);
  EXPECT_NEAR(lo, 0.7076683, 1e-7);
  EXPECT_NEAR(hi, 0.7654066, 1e-7);
}

// All n pass: the interval's lower end has the closed form ((1 − c)/2)^(1/n), the upper end is 1; none pass:
// the mirror image. (Clopper & Pearson 1934, the boundary cases of their construction.)
TEST(Binomial, ClopperPearsonBoundaryCases) {
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

// 792 of 800: GSL's beta inverse returns NaN for the lower end (a = 792, b = 9); the bisection fallback must
// still give the interval whose ends hit the tail probabilities, checked against the exact tails.
TEST(Binomial, ClopperPearsonWhereGslInverseFails) {
  const auto [lo, hi] = clopper_pearson(792, 800, 0.99);
  ASSERT_TRUE(std::isfinite(lo));
  EXPECT_GT(lo, 0.97);
  EXPECT_LT(lo, 0.98);
  EXPECT_NEAR(hi, 0.99678, 2e-4);
  // The definition: P[X ≥ 792 | p = lo] = P[X ≤ 792 | p = hi] = (1 − 0.99)/2.
  EXPECT_NEAR(exact_tails(792, 800, 0, 0, lo).second, 0.005, 1e-9);
  EXPECT_NEAR(exact_tails(792, 800, 0, 0, hi).first, 0.005, 1e-9);
}

// Large counts, where GSL's beta inverse is most stressed: the interval must still bracket the estimate and
// have about the normal approximation's width.
TEST(Binomial, ClopperPearsonLargeCounts) {
  const std::size_t n = 1000000, x = 990123;
  const auto [lo, hi] = clopper_pearson(x, n, 0.99);
  EXPECT_LT(lo, 0.990123);
  EXPECT_GT(hi, 0.990123);
  EXPECT_NEAR(hi - lo, 2 * 2.5758 * std::sqrt(0.990123 * 0.009877 / n), 2e-5);
}

}  // namespace dpdrng_test::stats_test_binomial
