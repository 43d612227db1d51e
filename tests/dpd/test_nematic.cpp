// The nematic order parameter S = λ_max⟨3/2 u uᵀ − 1/2 I⟩: aligned, hand-computed and isotropic cases, and the
// lipid axes it is measured on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/bilayer_observables.hpp"

namespace dpdrng::dpd::test_nematic {
namespace {

TEST(NematicOrder, ParallelAxesGiveOne) {
  // Either sense and any length: S depends on the line, not on the arrow.
  const std::vector<std::array<double, 3>> axes{{0.3, -0.2, 0.9}, {-0.6, 0.4, -1.8}, {0.03, -0.02, 0.09}};
  EXPECT_NEAR(nematic_order(axes), 1.0, 1e-14);
}

TEST(NematicOrder, TwoAxesByHand) {
  // x̂ and ŷ: Q = diag(1/4, 1/4, −1/2), S = 1/4.
  EXPECT_NEAR(nematic_order({{2, 0, 0}, {0, 1, 0}}), 0.25, 1e-15);
  // ẑ and (sin θ, 0, cos θ): ⟨u uᵀ⟩'s x–z block has eigenvalues (1 ± cos θ)/2, so S = (1 + 3 cos θ)/4.
  const double th = std::numbers::pi / 3;
  EXPECT_NEAR(nematic_order({{0, 0, 1}, {std::sin(th), 0, std::cos(th)}}), (1 + 3 * std::cos(th)) / 4, 1e-15);
}

TEST(NematicOrder, ZeroAxesAreSkipped) {
  EXPECT_EQ(nematic_order({}), 0.0);
  EXPECT_NEAR(nematic_order({{0, 0, 0}, {0, 0, 5}}), 1.0, 1e-15);
}

// Uniform directions (Archimedes: z uniform in [−1, 1], azimuth uniform). Q is traceless, so
// S ≤ √(2/3)‖Q‖_F, and for isotropic u E‖Q‖²_F = (9/4)(Σ_ab Var(u_a u_b))/N = 1.5/N: E[S] ≤ 1/√N. S > 0 always
// (a traceless symmetric matrix's largest eigenvalue), so a finite isotropic set is biased upward by O(1/√N).
TEST(NematicOrder, IsotropicAxesGiveZeroUpToTheFiniteSizeBias) {
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int N = 2000, sets = 40;
  double mean = 0;
  for (int t = 0; t < sets; ++t) {
    std::vector<std::array<double, 3>> axes;
    for (int k = 0; k < N; ++k) {
      const double z = 2 * u(gen) - 1, phi = 2 * std::numbers::pi * u(gen), r = std::sqrt(1 - z * z);
      axes.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    const double S = nematic_order(axes);
    EXPECT_GT(S, 0.0);
    EXPECT_LT(S, 4.0 / std::sqrt(double(N)));
    mean += S / sets;
  }
  EXPECT_LT(mean, 1.0 / std::sqrt(double(N)));
  EXPECT_GT(mean, 0.2 / std::sqrt(double(N)));  // the bias is there: a mean of 0 would mean S is not λ_max
}

// The pre-assembled bilayer's lipids are straight along ±z: every axis is parallel to z and S = 1.
TEST(NematicOrder, PreAssembledBilayerIsPerfectlyOrdered) {
  BilayerConfig c;
  const BilayerState st = build_bilayer(c);
  const auto axes = lipid_axes(st.system, st.lipids);
  ASSERT_EQ(axes.size(), st.lipids);
  for (const auto& a : axes) {
    EXPECT_NEAR(a[0], 0.0, 1e-12);
    EXPECT_NEAR(a[1], 0.0, 1e-12);
    EXPECT_NEAR(std::abs(a[2]), 8 * c.bond.r0, 1e-12);  // H1 at 8.5 r0 from the midplane, Ta6 at 0.5 r0
  }
  EXPECT_NEAR(nematic_order(axes), 1.0, 1e-12);
}

}  // namespace
}  // namespace dpdrng::dpd::test_nematic
