// Holm's adjustment and Stouffer's combination, by hand from their definitions.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/multiple.hpp"

namespace dpdrng_test::stats_test_multiple {

using namespace dpdrng::stats;

namespace {
}

// p = (0.01, 0.02, 0.03, 0.04, 0.05): 5·0.01, 4·0.02, 3·0.03, then max(0.09, 2·0.04), max(0.09, 0.05); the same
// as R's p.adjust(p, "holm"). The input order is kept and NaN stays out of the family (m = 5, not 6).
TEST(Multiple, HolmByHand) {
  const std::vector<double> p = {0.05, NAN, 0.01, 0.04, 0.02, 0.03};
  const auto a = holm_adjust(p);
  ASSERT_EQ(a.size(), 6u);
  EXPECT_NEAR(a[0], 0.09, 1e-15);
  EXPECT_TRUE(std::isnan(a[1]));
  EXPECT_NEAR(a[2], 0.05, 1e-15);
  EXPECT_NEAR(a[3], 0.09, 1e-15);
  EXPECT_NEAR(a[4], 0.08, 1e-15);
  EXPECT_NEAR(a[5], 0.09, 1e-15);
  // Capped at 1, and a single test is left alone.
  EXPECT_EQ(holm_adjust(std::vector<double>{0.6, 0.7})[0], 1.0);
  EXPECT_EQ(holm_adjust(std::vector<double>{0.003})[0], 0.003);
  EXPECT_TRUE(holm_adjust(std::vector<double>{}).empty());
}

// Two replicas each at p = 0.05 pointing the same way: z = 1.959964 each, Z = 2·1.959964/√2 = 2.771808,
// two-sided P = 0.005574; pointing opposite ways they cancel to Z = 0, P = 1.
TEST(Multiple, StoufferByHand) {
  EXPECT_NEAR(stouffer_two_sided(std::vector<double>{0.05, 0.05}, std::vector<double>{0.1, 0.3}), 0.005574, 2e-6);
  EXPECT_NEAR(stouffer_two_sided(std::vector<double>{0.05, 0.05}, std::vector<double>{-0.1, 0.3}), 1.0, 1e-12);
  EXPECT_NEAR(stouffer_two_sided(std::vector<double>{0.05}, std::vector<double>{-1.0}), 0.05, 1e-12);
  EXPECT_TRUE(std::isnan(stouffer_two_sided(std::vector<double>{NAN}, std::vector<double>{1.0})));
  EXPECT_THROW(stouffer_two_sided(std::vector<double>{0.1}, std::vector<double>{}), dpdrng::InputError);
}

}  // namespace dpdrng_test::stats_test_multiple
