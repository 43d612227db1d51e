// The decomposition check against hand-built ghost configurations whose floating-point outcome is known, and
// against the undecomposed engine.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/decomposition.hpp"
#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/rng/seeding_repair.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng::dpd::test_decomposition {
namespace {

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// Two beads at rest in a cubic box of side L.
System two_beads(double L, std::array<double, 3> ri, std::array<double, 3> rj) {
  System s;
  s.box = Box{{L, L, L}};
  s.resize(2);
  s.x = {ri[0], rj[0]}, s.y = {ri[1], rj[1]}, s.z = {ri[2], rj[2]};
  return s;
}

DpdKernel paper_kernel() { return make_kernel(25.0, 1.0, 6.75, 1.0, 0.04); }

DecompNoise noise(const std::string& gen, int rounds, const std::string& seeding) {
  DecompNoise n;
  n.generator = rng::validated({gen, rounds});
  n.seeding = parse_decomp_seeding(seeding);
  return n;
}

struct Evaluation {
  BoundaryStats stats;
  std::vector<BoundaryPair> pairs;
  double net[3] = {0, 0, 0};
};

Evaluation evaluate(System& s, const DecompNoise& nz, const std::string& domains, std::uint64_t step = 7) {
  auto f = make_decomposed_forces(nz, paper_kernel(), parse_domains(domains));
  Evaluation e;
  f->compute(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()}, step, &e.stats, &e.pairs);
  for (std::size_t i = 0; i < s.size(); ++i) e.net[0] += s.fx[i], e.net[1] += s.fy[i], e.net[2] += s.fz[i];
  return e;
}

System paper_fluid(std::uint64_t seed = 2021) {
  const double L = std::cbrt(256 / 3.0);
  return make_fluid(256, Box{{L, L, L}}, 1.0, seed);
}

TEST(Decomposition, ParsesDomainsAndSeedings) {
  EXPECT_EQ(parse_domains("2").n, (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(parse_domains("2,2").n, (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(parse_domains("2,3,4").n, (std::array<int, 3>{2, 3, 4}));
  EXPECT_EQ(to_string(parse_domains("2,2,1")), "2x2x1");
  for (const char* bad : {"", "0", "2,", ",2", "2,2,2,2", "a", "-1", "65", "2;2"})
    EXPECT_THROW(parse_domains(bad), InputError) << bad;
  EXPECT_EQ(parse_decomp_seeding("grid").grid_bits, 32);
  EXPECT_EQ(parse_decomp_seeding("grid:8").grid_bits, 8);
  EXPECT_EQ(to_string(parse_decomp_seeding("grid:20")), "grid:20");
  EXPECT_EQ(parse_decomp_seeding("canonical").kind, DecompSeedingKind::canonical);
  EXPECT_EQ(parse_decomp_seeding("pair-step").kind, DecompSeedingKind::pair_step);
  for (const char* bad : {"grid:7", "grid:41", "grid:", "grid:x", "counter", "Distance"})
    EXPECT_THROW(parse_decomp_seeding(bad), InputError) << bad;
}

TEST(Decomposition, DomainOfCoversTheBoxEdges) {
  const DomainGrid g = parse_domains("2,2,1");
  const Box box{{4.4, 4.4, 4.4}};
  EXPECT_EQ(g.domain_of(box, 0.0, 0.0, 0.0), 0);
  EXPECT_EQ(g.domain_of(box, 2.2, 0.0, 0.0), 2);
  EXPECT_EQ(g.domain_of(box, 0.0, 2.3, 3.0), 1);
  EXPECT_EQ(g.domain_of(box, std::nextafter(4.4, 0.0), std::nextafter(4.4, 0.0), 1.0), 3);
}

TEST(SeedingRepair, GridRoundingIsAntisymmetricAndHasNoNegativeZero) {
  for (double d : {0.3, -0.3, 0.123456789, 1e-3, 0.5 + 0x1p-33, 0x1p-40})
    EXPECT_EQ(bits(rng::round_to_grid(-d, 32)), bits(0.0 - rng::round_to_grid(d, 32))) << d;
  EXPECT_EQ(bits(rng::round_to_grid(-0x1p-40, 32)), bits(0.0));
  EXPECT_EQ(bits(rng::round_to_grid(-0.0, 32)), bits(0.0));
  EXPECT_EQ(rng::round_to_grid(0.3, 8), 77.0 / 256);
  EXPECT_TRUE(rng::near_grid_midpoint(76.5 / 256 + 1e-12, 8, 1e-6));
  EXPECT_FALSE(rng::near_grid_midpoint(77.0 / 256, 8, 1e-6));
}

// x_i = 0.1 and x_j = 3.9 in a 4.4 box: (x_j − L) − x_i and x_j − (x_i + L) differ in the last bits, so the two
// owners hash different seeds. y differs by 0.25 (no shift), z coincides (0 on both sides, with the same sign).
TEST(Decomposition, DistanceSeedingMismatchesWhereTheGhostRoundingDiffers) {
  const double L = 4.4, xi = 0.1, xj = 3.9;
  const double seen_a = (xj - L) - xi, seen_b = xj - (xi + L);
  ASSERT_NE(bits(seen_a), bits(seen_b)) << "precondition: the two ghost expressions must differ";
  System s = two_beads(L, {xi, 1.0, 2.0}, {xj, 1.25, 2.0});
  // Eight rounds: one round barely mixes a last-bit change into the output (Δζ ~ 1e-7 here), eight do.
  const Evaluation e = evaluate(s, noise("tea32", 8, "distance"), "2");
  EXPECT_EQ(e.stats.in_range, 1u);
  EXPECT_EQ(e.stats.boundary, 1u);
  EXPECT_EQ(e.stats.shifted, 1u);
  EXPECT_EQ(e.stats.separation_mismatch, 1u);
  EXPECT_EQ(e.stats.zeta_mismatch, 1u);
  ASSERT_EQ(e.pairs.size(), 1u);
  const BoundaryPair& p = e.pairs[0];
  EXPECT_EQ(p.domain_i, 0);
  EXPECT_EQ(p.domain_j, 1);
  EXPECT_EQ(bits(p.a.d[0]), bits(seen_a));
  EXPECT_EQ(bits(p.b.d[0]), bits(seen_b));
  EXPECT_EQ(bits(p.a.d[2]), bits(0.0));
  EXPECT_EQ(bits(p.b.d[2]), bits(0.0));
  EXPECT_EQ(p.a.shift, (std::array<int, 3>{-1, 0, 0}));
  // The ζ each owner draws is the generator's on its own separation.
  const rng::Tea32<8> tea;
  const double za = rng::draw<rng::Distribution::gauss>(tea.distance(seen_a, 0.25, 0.0));
  const double zb = rng::draw<rng::Distribution::gauss>(tea.distance(seen_b, 0.25, 0.0));
  EXPECT_EQ(bits(p.zeta_a), bits(za));
  EXPECT_EQ(bits(p.zeta_b), bits(zb));
  EXPECT_DOUBLE_EQ(e.stats.zeta_diff_max, std::fabs(za - zb));
  // The random forces do not cancel: the pair pushes the centre of mass by σ w |Δζ| / √Δt along ê.
  const double r = std::sqrt(seen_a * seen_a + 0.0625);
  const DpdKernel k = paper_kernel();
  const double expected = k.sigma * k.inv_sqrt_dt * (1 - r / k.rc) * std::fabs(za - zb);
  ASSERT_GT(std::fabs(za - zb), 1e-3);
  // The conservative forces differ too, by round-off of the ulp-sized separation difference.
  EXPECT_NEAR(std::hypot(e.net[0], e.net[1], e.net[2]), expected, 1e-9 * expected + 1e-12);
}

TEST(Decomposition, DistanceSeedingAgreesWhenBothGhostsAreExact) {
  const double L = 4.4, xi = 0.25, xj = 3.75;
  ASSERT_EQ(bits((xj - L) - xi), bits(xj - (xi + L))) << "precondition: the two ghost expressions must agree";
  System s = two_beads(L, {xi, 1.0, 2.0}, {xj, 1.25, 2.0});
  const Evaluation e = evaluate(s, noise("tea32", 1, "distance"), "2");
  EXPECT_EQ(e.stats.boundary, 1u);
  EXPECT_EQ(e.stats.shifted, 1u);
  EXPECT_EQ(e.stats.separation_mismatch, 0u);
  EXPECT_EQ(e.stats.zeta_mismatch, 0u);
  // Identical ζ and separations: the two owners' forces cancel exactly.
  EXPECT_EQ(e.net[0], 0.0);
  EXPECT_EQ(e.net[1], 0.0);
  EXPECT_EQ(e.net[2], 0.0);
}

TEST(Decomposition, InnerBoundariesNeedNoShiftAndAgree) {
  System s = two_beads(4.4, {2.1, 1.0, 2.0}, {2.3000000000000003, 1.1, 2.05});
  const Evaluation e = evaluate(s, noise("tea32", 1, "distance"), "2");
  EXPECT_EQ(e.stats.boundary, 1u);
  EXPECT_EQ(e.stats.shifted, 0u);
  EXPECT_EQ(e.stats.zeta_mismatch, 0u);
  EXPECT_EQ(e.stats.separation_mismatch, 0u);
}

TEST(Decomposition, UncutAxisUsesTheMinimumImage) {
  // Across the periodic x boundary, but x is not cut: both owners (one domain) take min_image(x_j − x_i).
  System s = two_beads(4.4, {0.1, 1.0, 2.0}, {3.9, 1.25, 2.0});
  const Evaluation e = evaluate(s, noise("tea32", 1, "distance"), "1,2,1");
  EXPECT_EQ(e.stats.boundary, 0u);
  EXPECT_EQ(e.stats.in_range, 1u);
  EXPECT_EQ(e.net[0], 0.0);
}

TEST(Decomposition, PairStepSeedingAgreesBitForBitOnTheWaterScene) {
  for (const char* gen : {"tea32", "tea64", "philox4x32"}) {
    for (const char* dom : {"2", "2,2,1", "2,2,2"}) {
      System s = paper_fluid();
      const Evaluation e = evaluate(s, noise(gen, gen == std::string("philox4x32") ? 10 : 1, "pair-step"), dom);
      SCOPED_TRACE(std::string(gen) + " " + dom);
      ASSERT_GT(e.stats.shifted, 50u);
      // Not vacuous: the separations do differ, the numbers do not.
      EXPECT_GT(e.stats.separation_mismatch, 0u);
      EXPECT_EQ(e.stats.zeta_mismatch, 0u);
      for (const auto& p : e.pairs) {
        if (p.in_a && p.in_b) {
          ASSERT_EQ(bits(p.zeta_a), bits(p.zeta_b)) << p.i << "," << p.j;
        }
      }
    }
  }
}

// tea32 hashes dx alone and philox4x32 (dx, dy); both are bijections, so ζ differs exactly when a hashed
// component does.
TEST(Decomposition, DistanceSeedingMismatchesExactlyWhereTheHashedComponentsDiffer) {
  for (const char* gen : {"tea32", "philox4x32"}) {
    System s = paper_fluid();
    const Evaluation e = evaluate(s, noise(gen, gen == std::string("tea32") ? 8 : 10, "distance"), "2,2,1");
    const int hashed = gen == std::string("tea32") ? 1 : 2;
    std::uint64_t expected = 0;
    for (const auto& p : e.pairs) {
      if (!(p.in_a && p.in_b)) continue;
      bool differs = false;
      for (int c = 0; c < hashed; ++c) differs |= bits(p.a.d[c]) != bits(p.b.d[c]);
      expected += differs;
      EXPECT_EQ(differs, bits(p.zeta_a) != bits(p.zeta_b)) << gen << " " << p.i << "," << p.j;
    }
    EXPECT_EQ(e.stats.zeta_mismatch, expected);
    EXPECT_GT(e.stats.zeta_mismatch, e.stats.shifted / 4) << gen;
  }
}

TEST(Decomposition, GridRepairAgreesAwayFromMidpointsAndNotAcrossOne) {
  {
    // The mismatching configuration above, seeded from the separation on a 2^-32 grid.
    System s = two_beads(4.4, {0.1, 1.0, 2.0}, {3.9, 1.25, 2.0});
    ASSERT_FALSE(rng::near_grid_midpoint((3.9 - 4.4) - 0.1, 32, 1e-3));
    const Evaluation e = evaluate(s, noise("tea32", 1, "grid"), "2");
    EXPECT_EQ(e.stats.separation_mismatch, 1u);
    EXPECT_EQ(e.stats.zeta_mismatch, 0u);
    EXPECT_GT(e.stats.grid_straddle_expected, 0.0);
    EXPECT_LT(e.stats.grid_straddle_expected, 1e-5);
  }
  {
    // x_j chosen so that x_j − (x_i + L) is exactly the grid midpoint −153.5/256 (ties to even: −154/256)
    // and (x_j − L) − x_i lies an ulp above it (rounds to −153/256).
    const double L = 4.4, xi = 0.15, xj = 0x1.f9a6666666668p+1;
    ASSERT_EQ((xj - (xi + L)), -153.5 / 256);
    ASSERT_GT((xj - L) - xi, -153.5 / 256);
    System s = two_beads(L, {xi, 1.0, 2.0}, {xj, 1.25, 2.0});
    const Evaluation e = evaluate(s, noise("tea32", 1, "grid:8"), "2");
    ASSERT_EQ(e.pairs.size(), 1u);
    EXPECT_EQ(e.stats.zeta_mismatch, 1u);
  }
}

TEST(Decomposition, CanonicalRepairAgreesAndGivesTheUndecomposedNumbers) {
  System s = paper_fluid();
  const Evaluation e = evaluate(s, noise("tea32", 1, "canonical"), "2,2,1");
  EXPECT_GT(e.stats.separation_mismatch, 0u);
  EXPECT_EQ(e.stats.zeta_mismatch, 0u);
  auto canon = make_decomposed_forces(noise("tea32", 1, "canonical"), paper_kernel(), parse_domains("2,2,1"));
  auto plain = make_decomposed_forces(noise("tea32", 1, "distance"), paper_kernel(), DomainGrid{});
  for (std::uint32_t j = 1; j < 256; j += 7) EXPECT_EQ(canon->raw(s, 0, j, 3), plain->raw(s, 0, j, 3));
}

// One domain per axis is the undecomposed engine: the same ζ and forces as PairLoop, up to summation order.
TEST(Decomposition, OneDomainReproducesTheEngine) {
  for (const char* seeding : {"distance", "pair-step"}) {
    System a = paper_fluid(), b = paper_fluid();
    WaterConfig cfg;
    cfg.generator = rng::validated({"tea32", 1});
    cfg.seeding = rng::parse_seeding(seeding);
    cfg.pairs = PairMode::cells;
    cfg.threads = 1;
    auto engine = make_pair_forces(cfg, paper_kernel(), a.size());
    Taps taps;
    const ForceSums fe = engine->compute(a, VelocityView{a.vx.data(), a.vy.data(), a.vz.data()}, 7, false, false, false, taps);
    auto mine = make_decomposed_forces(noise("tea32", 1, seeding), paper_kernel(), DomainGrid{});
    BoundaryStats st;
    const ForceSums fm = mine->compute(b, VelocityView{b.vx.data(), b.vy.data(), b.vz.data()}, 7, &st, nullptr);
    EXPECT_EQ(st.boundary, 0u);
    EXPECT_EQ(fm.in_range, fe.in_range);
    double fmax = 0;
    for (std::size_t i = 0; i < a.size(); ++i) fmax = std::max(fmax, std::fabs(a.fx[i]));
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_NEAR(b.fx[i], a.fx[i], 1e-12 * fmax) << seeding << " bead " << i;
      ASSERT_NEAR(b.fy[i], a.fy[i], 1e-12 * fmax);
      ASSERT_NEAR(b.fz[i], a.fz[i], 1e-12 * fmax);
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fm.virial[c], fe.virial[c], 1e-9 * std::fabs(fe.virial[c]));
  }
}

TEST(Decomposition, RejectsStreamsAndBadConfigs) {
  DecompNoise n;
  n.generator = rng::validated({"mt19937", 0});
  EXPECT_THROW(make_decomposed_forces(n, paper_kernel(), DomainGrid{}), InputError);
}

}  // namespace
}  // namespace dpdrng::dpd::test_decomposition
