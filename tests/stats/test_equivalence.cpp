// Schuirmann's two one-sided tests, the normal score of a t statistic and the χ² interval of a dispersion,
// against the Student-t and χ² tables of the NIST/SEMATECH e-Handbook of Statistical Methods (§1.3.6.7.2:
// t_{0.95,10} = 1.812, t_{0.975,10} = 2.228; §1.3.6.7.4: χ²_{0.025,10} = 3.247, χ²_{0.975,10} = 20.483).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/stats/equivalence.hpp"

namespace dpdrng_test::stats_test_equivalence {

using namespace dpdrng::stats;

// A shift of 0 with a margin of t_{0.95,10} standard errors sits exactly on the 5 % boundary, from either side;
// a shift of 0.5 with the margin 0.5 + 1.812 is held back by the upper test alone.
TEST(Equivalence, TwoOneSidedTestsAgainstTheTTable) {
  EXPECT_NEAR(equivalence_p(0.0, 1.0, 10, 1.812), 0.05, 1e-4);
  EXPECT_NEAR(equivalence_p(0.5, 1.0, 10, 2.312), 0.05, 1e-4);
  EXPECT_NEAR(equivalence_p(-0.5, 1.0, 10, 2.312), 0.05, 1e-4);
  EXPECT_NEAR(equivalence_p(0.0, 2.0, 10, 2 * 1.812), 0.05, 1e-4);  // scale-free
  // Outside the margin it can never reject.
  EXPECT_GT(equivalence_p(3.0, 0.1, 1000, 2.0), 0.5);
}

// Rejecting at α is the (1 − 2α) CI lying inside ±margin (the test's defining duality), on both sides.
TEST(Equivalence, RejectsExactlyWhenTheCiLiesInsideTheMargin) {
  const double t95 = 1.812461;  // t_{0.95,10} to more digits than the table's three
  for (double diff : {-1.0, -0.3, 0.0, 0.2, 0.9})
    for (double margin : {0.5, 1.5, 2.0, 2.5, 3.0}) {
      const bool inside = std::abs(diff) + t95 < margin;
      EXPECT_EQ(equivalence_p(diff, 1.0, 10, margin) < 0.05, inside) << diff << " " << margin;
    }
}

TEST(Equivalence, NotApplicableInputsGiveNan) {
  EXPECT_TRUE(std::isnan(equivalence_p(0, 1, 0, 1)));
  EXPECT_TRUE(std::isnan(equivalence_p(0, 1, 10, 0)));
  EXPECT_TRUE(std::isnan(equivalence_p(0, NAN, 10, 1)));
  EXPECT_EQ(equivalence_p(0.1, 0, 10, 1), 0.0);
  EXPECT_EQ(equivalence_p(1.1, 0, 10, 1), 1.0);
}

// The power of the two one-sided tests at Δ = 0 (Chow, Shao & Wang, Sample Size Calculations in Clinical Research,
// 2nd ed., 2008, §3.2.3): a margin of t_{0.95,10} + t_{0.95,10} = 3.624 standard errors passes 2 × 0.95 − 1 = 90 %
// of the time; on the normal law, z_{0.95} + z_{0.95} = 3.2897 likewise. A margin inside t_{0.95} se never passes.
TEST(Equivalence, PowerAtZeroShiftAgainstTheTTable) {
  EXPECT_NEAR(equivalence_power(1.0, 10, 0.05, 3.624), 0.90, 2e-3);
  EXPECT_NEAR(equivalence_power(2.0, 10, 0.05, 2 * 3.624), 0.90, 2e-3);  // scale-free
  EXPECT_NEAR(equivalence_power(1.0, 1e9, 0.05, 3.2897), 0.90, 1e-4);
  EXPECT_EQ(equivalence_power(1.0, 10, 0.05, 1.8), 0.0);
  EXPECT_LT(equivalence_power(1.0, 10, 0.01, 3.624), equivalence_power(1.0, 10, 0.05, 3.624));
  EXPECT_TRUE(std::isnan(equivalence_power(0.0, 10, 0.05, 1)));
  EXPECT_TRUE(std::isnan(equivalence_power(1.0, 0, 0.05, 1)));
  EXPECT_TRUE(std::isnan(equivalence_power(1.0, 10, 1.5, 1)));
}

// Chow, Shao & Wang §3.2.3, two parallel groups of n with true difference 0: n = (z_{1−α} + z_{1−β/2})² 2σ²/δ².
// σ = 1, δ = 0.5, α = 0.05, power 80 % (z_{0.9} = 1.2816): n = (1.6449 + 1.2816)² × 8 = 68.5, so 69; a reference
// with 4 × R replicas of the same spread: (1 + 1/4) in place of 2, 42.8, so 43.
TEST(Equivalence, ReplicasForEquivalenceAgainstTheSampleSizeFormula) {
  EXPECT_EQ(replicas_for_equivalence(1.0, 1.0, 1e9, 0.05, 0.5, 0.8), 69);
  EXPECT_EQ(replicas_for_equivalence(1.0, 4.0, 1e9, 0.05, 0.5, 0.8), 43);
  EXPECT_EQ(replicas_for_equivalence(1.0, 1.0, 1e9, 0.05, 100.0, 0.8), 2);  // the fewest a spread needs
  EXPECT_EQ(replicas_for_equivalence(1.0, 1.0, 1e9, 0.05, 0.5, 0.8, 50), 0);  // out of reach
  EXPECT_EQ(replicas_for_equivalence(0.0, 1.0, 1e9, 0.05, 0.5, 0.8), -1);
  EXPECT_EQ(replicas_for_equivalence(1.0, 1.0, 1e9, 0.05, 0.5, 1.0), -1);
}

// t_{0.975,10} = 2.228 maps to z_{0.975} = 1.95996; far-out t keeps its digits through the tail.
TEST(Equivalence, NormalScoreOfATStatistic) {
  EXPECT_NEAR(normal_score(2.228, 10), 1.959964, 2e-4);
  EXPECT_NEAR(normal_score(-2.228, 10), -1.959964, 2e-4);
  EXPECT_EQ(normal_score(0.0, 4), 0.0);
  EXPECT_EQ(normal_score(1.5, 1e9), 1.5);
  EXPECT_GT(normal_score(40.0, 4), 4.0);
  EXPECT_TRUE(std::isnan(normal_score(1.0, 0)));
}

// Ten scores of ±1: ratio 1, interval [10/20.483, 10/3.247].
TEST(Equivalence, DispersionChiSquareInterval) {
  const std::vector<double> z = {1, -1, 1, -1, 1, -1, 1, -1, 1, -1, NAN};
  const Dispersion d = score_dispersion(z, 0.95);
  EXPECT_EQ(d.k, 10u);
  EXPECT_DOUBLE_EQ(d.ratio, 1.0);
  EXPECT_NEAR(d.low, 10 / 20.483, 1e-4);
  EXPECT_NEAR(d.high, 10 / 3.247, 1e-3);
  EXPECT_TRUE(std::isnan(score_dispersion(std::vector<double>{}).ratio));
}

}  // namespace dpdrng_test::stats_test_equivalence
