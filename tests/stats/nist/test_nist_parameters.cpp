// Parameter rules of the SP800-22 tests: a parameter outside its rule is the caller's error (std::invalid_argument,
// exit 2 at the CLI), never "not applicable" and never a P-value; the limits are where the test's mathematics
// stops holding, checked here against independent references.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/parameters.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng_test::stats_nist_test_nist_parameters {

using namespace dpdrng::stats::nist;
using NistTest = dpdrng::stats::nist::Test;

namespace {

BitSequence random_bits(std::size_t n, unsigned seed) {
  std::mt19937 g(seed);
  std::vector<std::uint8_t> bits(n);
  for (auto& b : bits) b = static_cast<std::uint8_t>(g() & 1);
  return BitSequence::from_bits(bits);
}

// Exact probabilities of the linear-complexity test's 7 classes for random M-bit blocks, from Rueppel's count of
// binary sequences of length M by linear complexity L (Rueppel, "Analysis and Design of Stream Ciphers", 1986:
// 1 sequence with L = 0, 2^(2L-1) for 1 <= L <= M/2, 2^(2(M-L)) above), binned with SP800-22 2.10's T.
std::vector<double> exact_linear_complexity_classes(int M) {
  std::vector<double> p(7, 0.0);
  const double sign1 = (M + 1) % 2 == 0 ? -1.0 : 1.0, sign2 = M % 2 == 0 ? 1.0 : -1.0;
  const double mean = M / 2.0 + (9.0 + sign1) / 36.0 - std::pow(2.0, -M) * (M / 3.0 + 2.0 / 9.0);
  for (int L = 0; L <= M; ++L) {
    const double count = L == 0 ? 1.0 : (2 * L <= M ? std::pow(2.0, 2 * L - 1) : std::pow(2.0, 2 * (M - L)));
    const double T = sign2 * (L - mean) + 2.0 / 9.0;
    const int k = T <= -2.5 ? 0 : T <= -1.5 ? 1 : T <= -0.5 ? 2 : T <= 0.5 ? 3 : T <= 1.5 ? 4 : T <= 2.5 ? 5 : 6;
    p[k] += count * std::pow(2.0, -M);
  }
  return p;
}

double worst_relative_error(int M) {
  constexpr double kTable[7] = {0.01047, 0.03125, 0.12500, 0.50000, 0.25000, 0.06250, 0.020833};
  const auto p = exact_linear_complexity_classes(M);
  double worst = 0;
  for (int k = 0; k < 7; ++k) worst = std::max(worst, std::fabs(p[k] - kTable[k]) / kTable[k]);
  return worst;
}

}  // namespace

TEST(NistParameters, LinearComplexityBlocksShorterThan12DoNotFollowTheTable) {
  // Rueppel's exact distribution sums to 1 (a check on the reference itself).
  for (int M : {12, 500}) {
    double total = 0;
    for (double x : exact_linear_complexity_classes(M)) total += x;
    EXPECT_NEAR(total, 1.0, 1e-12);
  }
  EXPECT_LT(worst_relative_error(12), 0.01);
  EXPECT_LT(worst_relative_error(500), 0.01);
  EXPECT_GT(worst_relative_error(11), 0.01);
  EXPECT_FALSE(check_linear_complexity(12));
  EXPECT_TRUE(check_linear_complexity(11));
  EXPECT_TRUE(check_linear_complexity(1));
  // M = 1: every block's class is 3 or 4, which must not give p = 0 for every sequence.
  EXPECT_THROW(linear_complexity(random_bits(5000, 1), 1), std::invalid_argument);
}

TEST(NistParameters, UniversalRefusesL1WhereTheVarianceFactorIsNegative) {
  // Coron's c(L, K) = 0.7 - 0.8/L + (4 + 32/L) K^(-3/L) / 15 (SP800-22 2.9.4): negative at L = 1 for every
  // K >= 3, which made sigma negative and P = erfc(-x) up to 2.
  for (const double K : {3.0, 100.0, 1e7}) EXPECT_LT(0.7 - 0.8 + 36.0 * std::pow(K, -3.0) / 15.0, 0.0);
  EXPECT_GT(0.7 - 0.4 + 20.0 * std::pow(2.0, -1.5) / 15.0, 0.0);  // L = 2, the smallest K
  EXPECT_TRUE(check_universal(1, 0));
  EXPECT_FALSE(check_universal(2, 4));
  EXPECT_FALSE(check_universal(0, 0));
  EXPECT_TRUE(check_universal(17, 0));
  EXPECT_TRUE(check_universal(6, -1));  // a negative Q indexed before the sequence: a crash, once
  EXPECT_THROW(universal(random_bits(4000, 2), 1), std::invalid_argument);
  EXPECT_THROW(universal(random_bits(4000, 2), 5, -1), std::invalid_argument);
  // Valid L on too few bits is still "not applicable", with the bits needed.
  const TestResult r = universal(random_bits(100, 3), 6, 640);
  EXPECT_FALSE(r.applicable);
  EXPECT_EQ(r.min_bits, 641u * 6u);
}

TEST(NistParameters, BlockFrequencyOfOneBitBlocksCannotFail) {
  // With M = 1 each block's proportion is 0 or 1, so chi^2 = 4 M sum (pi - 1/2)^2 = N for every sequence.
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 g(seed);
    std::vector<std::uint8_t> bits(1000);
    for (auto& b : bits) b = static_cast<std::uint8_t>(g() % 7 == 0);  // heavily biased
    double chi2 = 0;
    for (auto b : bits) chi2 += 4.0 * (b - 0.5) * (b - 0.5);
    EXPECT_EQ(chi2, 1000.0);
  }
  EXPECT_TRUE(check_block_frequency(1));
  EXPECT_FALSE(check_block_frequency(2));
  EXPECT_THROW(block_frequency(random_bits(1000, 4), 1), std::invalid_argument);
  EXPECT_THROW(block_frequency(random_bits(1000, 4), -5), std::invalid_argument);
}

TEST(NistParameters, TemplateAndEntropyRules) {
  EXPECT_TRUE(check_non_overlapping(40, {}, 8));
  EXPECT_TRUE(check_non_overlapping(9, {}, 0));
  const std::vector<std::uint32_t> too_wide = {1u << 9};
  EXPECT_TRUE(check_non_overlapping(9, too_wide, 8));
  EXPECT_FALSE(check_non_overlapping(9, {}, 8));
  EXPECT_TRUE(check_overlapping(9, 8, 5));     // M < m
  EXPECT_TRUE(check_overlapping(9, 1032, 0));  // no classes
  EXPECT_TRUE(check_overlapping(9, 1032, 65));
  EXPECT_FALSE(check_overlapping(9, 1032, 5));
  EXPECT_FALSE(check_overlapping(2, 10, 2));  // SP800-22 2.8.4's example
  EXPECT_TRUE(check_approximate_entropy(-1));
  EXPECT_TRUE(check_serial(1));
  EXPECT_FALSE(check_serial(16));
}

TEST(NistParameters, CheckParametersNamesTheFieldOfEveryTest) {
  Parameters p;
  for (const NistTest t : all_tests()) EXPECT_FALSE(check_parameters(t, p)) << test_name(t);
  p.universal_Q = -1;
  const auto problem = check_parameters(NistTest::Universal, p);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->field, "universal_Q");
  EXPECT_EQ(problem->value, -1);
  EXPECT_FALSE(check_parameters(NistTest::Runs, p));  // Runs has no parameters
  p = {};
  p.overlapping_K = 0;
  EXPECT_EQ(check_parameters(NistTest::OverlappingTemplate, p)->field, "overlapping_K");
}

TEST(NistParameters, AperiodicTemplatesAsCountedBySp80022) {
  // SP800-22 rev1a 2.7.7 / Appendix: 148 aperiodic templates of length 9, 284 of length 10 (and the sts-2.1.2
  // template files hold as many lines).
  for (const auto& [m, expected] : {std::pair{2, 2}, {9, 148}, {10, 284}}) {
    int count = 0;
    for (std::uint32_t t = 0; t < (1u << m); ++t) count += is_aperiodic(t, m);
    EXPECT_EQ(count, expected) << "m = " << m;
  }
  EXPECT_TRUE(is_aperiodic(0b000000001, 9));   // the reference's first template
  EXPECT_FALSE(is_aperiodic(0b111111111, 9));  // periodic: p = 0 for every random sequence
  EXPECT_FALSE(is_aperiodic(0b101, 3));
}

TEST(NistParameters, RecommendedRangesOfSp80022) {
  Parameters p;
  for (const NistTest t : all_tests()) EXPECT_FALSE(check_recommended(t, p)) << test_name(t);
  // 2.8.7: m = 9 or 10, lambda = (M - m + 1) / 2^m ~ 2.
  p.overlapping_m = 2;
  EXPECT_EQ(check_parameters(NistTest::OverlappingTemplate, p)->field, "overlapping_m");
  EXPECT_FALSE(check_validity(NistTest::OverlappingTemplate, p));  // the mathematics holds; the spec advises against
  p = {};
  p.overlapping_m = 10;
  EXPECT_FALSE(check_recommended(NistTest::OverlappingTemplate, p));  // the reference's M = 1032: lambda ~ 1
  p = {};
  p.overlapping_M = 20;
  EXPECT_EQ(check_parameters(NistTest::OverlappingTemplate, p)->field, "overlapping_M");
  // 2.2.7: M >= 20; 2.10.7: 500 <= M <= 5000.
  p = {};
  p.block_frequency_M = 19;
  EXPECT_TRUE(check_recommended(NistTest::BlockFrequency, p));
  p.block_frequency_M = 20;
  EXPECT_FALSE(check_recommended(NistTest::BlockFrequency, p));
  p = {};
  for (const int M : {499, 5001}) {
    p.linear_complexity_M = M;
    EXPECT_TRUE(check_recommended(NistTest::LinearComplexity, p)) << M;
  }
  // 2.7: aperiodic templates only.
  p = {};
  p.non_overlapping_templates = {0b111111111};
  EXPECT_EQ(check_parameters(NistTest::NonOverlappingTemplate, p)->field, "non_overlapping_templates");
  // The spec's worked examples (x.8) use parameters outside these ranges: the test functions still run them.
  EXPECT_FALSE(check_overlapping(2, 10, 2));
  EXPECT_FALSE(check_block_frequency(3));
}

TEST(NistParameters, LengthRulesMakeATestNotApplicable) {
  const Parameters p;
  // 2.12.7: m < floor(log2 n) - 5; 2.11.7: m < floor(log2 n) - 2 (defaults m = 10 and 16).
  EXPECT_FALSE(check_length(NistTest::ApproximateEntropy, p, 1u << 16));
  EXPECT_TRUE(check_length(NistTest::ApproximateEntropy, p, (1u << 16) - 1));
  EXPECT_EQ(check_length(NistTest::ApproximateEntropy, p, 1000)->min_bits, 1u << 16);
  EXPECT_FALSE(check_length(NistTest::Serial, p, 1u << 19));
  EXPECT_TRUE(check_length(NistTest::Serial, p, (1u << 19) - 1));
  // 2.10.7: N >= 200 blocks.
  EXPECT_FALSE(check_length(NistTest::LinearComplexity, p, 200 * 500));
  EXPECT_TRUE(check_length(NistTest::LinearComplexity, p, 200 * 500 - 1));
  // 2.8.7: N * min(pi_i) > 5; pi_4 = 0.070 at the defaults (sts-2.1.2), so N >= 72 blocks of 1032 bits.
  EXPECT_NEAR(min_overlapping_class(9, 1032, 5), 0.0703, 0.0005);
  EXPECT_FALSE(check_length(NistTest::OverlappingTemplate, p, 72 * 1032));
  EXPECT_TRUE(check_length(NistTest::OverlappingTemplate, p, 71 * 1032));
  // run_test applies them: approximate entropy m = 16 on 1.3 Mbit (was p = 0 for good data) has no P-value.
  Parameters big;
  big.approximate_entropy_m = 16;
  const TestResult r = run_test(NistTest::ApproximateEntropy, random_bits(1300000, 9), big);
  EXPECT_FALSE(r.applicable);
  EXPECT_NE(r.reason.find("2.12.7"), std::string::npos) << r.reason;
  EXPECT_TRUE(std::isnan(r.p()));
}

}  // namespace dpdrng_test::stats_nist_test_nist_parameters
