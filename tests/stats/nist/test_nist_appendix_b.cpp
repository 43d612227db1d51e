// SP800-22 rev1a Appendix B: P-values of the reference implementation on the binary expansions of e, pi,
// sqrt 2 and sqrt 3 (10^6 bits, defaults M = 128, m = 9 with template 000000001, m = 9, ApEn m = 10,
// Serial m = 16, LinearComplexity M = 500). Numbers from the published table (NIST SP800-22 rev1a,
// Appendix B, "Reference Distributions"); every one is matched to 1e-6.
#include <gtest/gtest.h>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/tests.hpp"
#include "nist_test_util.hpp"

namespace dpdrng_test::stats_nist_test_nist_appendix_b {

using namespace dpdrng::stats::nist;
using testing_::Constant;

namespace {

struct Row {
  Test test;
  std::size_t index;  // which P-value of the test
  double e, pi, sqrt2, sqrt3;
};

// Appendix B. CumulativeSums on e is printed as 0.669887 / 0.724266; the reference code gives
// 0.6698865 / 0.7242653, within the table's rounding, so the 1e-6 check holds with the printed values.
const Row kTable[] = {
    {Test::Frequency, 0, 0.953749, 0.578211, 0.811881, 0.610051},
    {Test::BlockFrequency, 0, 0.211072, 0.380615, 0.833222, 0.473961},
    {Test::CumulativeSums, 0, 0.669887, 0.628308, 0.879009, 0.917121},
    {Test::CumulativeSums, 1, 0.724266, 0.663369, 0.957206, 0.689519},
    {Test::Runs, 0, 0.561917, 0.419268, 0.313427, 0.261123},
    {Test::LongestRun, 0, 0.718945, 0.024390, 0.012117, 0.446726},
    {Test::Rank, 0, 0.306156, 0.083553, 0.823810, 0.314498},
    {Test::FFT, 0, 0.847187, 0.010186, 0.581909, 0.776046},
    {Test::NonOverlappingTemplate, 0, 0.078790, 0.165757, 0.569461, 0.532235},
    {Test::OverlappingTemplate, 0, 0.110434, 0.296897, 0.791982, 0.082716},
    {Test::Universal, 0, 0.282568, 0.669012, 0.130805, 0.165981},
    {Test::ApproximateEntropy, 0, 0.700073, 0.361595, 0.884740, 0.180481},
    {Test::RandomExcursions, 4, 0.786868, 0.844143, 0.216235, 0.783283},         // x = +1
    {Test::RandomExcursionsVariant, 8, 0.826009, 0.760966, 0.566118, 0.155066},  // x = -1
    {Test::LinearComplexity, 0, 0.826335, 0.255475, 0.317127, 0.346469},
    {Test::Serial, 0, 0.766182, 0.143005, 0.861925, 0.157500},
};

double expected(const Row& r, Constant c) {
  switch (c) {
    case Constant::e: return r.e;
    case Constant::pi: return r.pi;
    case Constant::sqrt2: return r.sqrt2;
    case Constant::sqrt3: return r.sqrt3;
  }
  return NAN;
}

bool expensive(Test t) {
  return t == Test::FFT || t == Test::NonOverlappingTemplate || t == Test::LinearComplexity;
}

class AppendixB : public ::testing::TestWithParam<Constant> {};

TEST_P(AppendixB, MatchesThePublishedTable) {
  const Constant c = GetParam();
  // Under the sanitizer run the full table costs minutes; e and pi keep every test, sqrt 2/3 the cheap ones.
  const bool cheap_only = testing_::small_scale() && (c == Constant::sqrt2 || c == Constant::sqrt3);
  const BitSequence& s = testing_::cached_expansion(c);
  ASSERT_EQ(s.size(), 1000000u);
  for (const Row& row : kTable) {
    if (cheap_only && expensive(row.test)) continue;
    const TestResult r = run_test(row.test, s);
    ASSERT_TRUE(r.applicable) << test_name(row.test) << ": " << r.reason;
    EXPECT_NEAR(r.p(row.index), expected(row, c), 1e-6) << test_name(row.test) << " " << r.values[row.index].variant;
  }
}

std::string constant_name(const ::testing::TestParamInfo<Constant>& info) {
  static const char* const kNames[] = {"e", "pi", "sqrt2", "sqrt3"};
  return kNames[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Constants, AppendixB,
                         ::testing::Values(Constant::e, Constant::pi, Constant::sqrt2, Constant::sqrt3),
                         constant_name);

TEST(AppendixB, BatteryGives188PValuesForAMillionBits) {
  const auto results = run_battery(testing_::cached_expansion(Constant::e));
  std::size_t count = 0;
  for (const auto& r : results) {
    EXPECT_TRUE(r.applicable) << test_name(r.test) << ": " << r.reason;
    count += r.values.size();
  }
  EXPECT_EQ(results.size(), 15u);
  EXPECT_EQ(count, 188u);
}

}  // namespace

}  // namespace dpdrng_test::stats_nist_test_nist_appendix_b
