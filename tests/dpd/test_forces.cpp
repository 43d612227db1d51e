// Pair forces against hand-worked numbers, ζ symmetry, momentum conservation and thread-count determinism.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "dpdrng/dpd/pair_loop.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "../rng/every_generator.hpp"
#include "scale.hpp"

namespace dpdrng_test::dpd_test_forces {

using namespace dpdrng;
using namespace dpdrng::dpd;

// One pair worked by hand from Groot & Warren (1997) eq. 2–4: r = 0.6, w = 0.4, a = 25, γ = 4.5, σ = 3,
// Δt = 0.04 (1/√Δt = 5), ζ = 0.5, j receding at dv = (1, 0, 0):
//   F^C_i = −a w = −10,  F^D_i = +γ w² (ê·dv) = +0.72,  F^R_i = −σ w ζ /√Δt = −3,  total −12.28 along x.
TEST(DpdKernel, OnePairByHand) {
  const DpdKernel k = make_kernel(25.0, 1.0, 4.5, 1.0, 0.04);
  EXPECT_DOUBLE_EQ(k.sigma, 3.0);
  const PairForce f = k(0.36, 0.6, 0.0, 0.0, 1.0, 0.0, 0.0, 25.0, 0.5);
  EXPECT_NEAR(f.s * 0.6, -12.28, 1e-12);
  EXPECT_NEAR(f.a_w, 25.0 * 0.4 * 0.6, 1e-12);  // r_ij·F^C_ij = a w r
  // Direction: a pair along a diagonal gives the same magnitude along ê.
  const double c = 0.6 / std::sqrt(3.0);
  const PairForce g = k(0.36, c, c, c, c / 0.6, c / 0.6, c / 0.6, 25.0, 0.5);
  EXPECT_NEAR(g.s * c * std::sqrt(3.0), -12.28, 1e-12);
}

// Two beads at one position have no direction: the kernel skips the pair (LAMMPS's pair style dpd skips r below
// 1e-10) with no force and no virial, where 1/r would make both NaN.
TEST(DpdKernel, CoincidentBeadsAreSkipped) {
  const DpdKernel k = make_kernel(25.0, 1.0, 4.5, 1.0, 0.04);
  const PairForce f = k(0.0, 0.0, 0.0, 0.0, 1.0, -2.0, 0.5, 25.0, 0.7);
  EXPECT_EQ(f.s, 0.0);
  EXPECT_EQ(f.a_w, 0.0);
  EXPECT_EQ(DpdKernel::conservative_weight(f, 0.0), 0.0);
  // A pair at r > 0 keeps its weight a·w/r: r = 0.6 gives 25·0.4/0.6.
  EXPECT_NEAR(DpdKernel::conservative_weight(k(0.36, 0.6, 0, 0, 0, 0, 0, 25.0, 0.0), 0.36), 25.0 * 0.4 / 0.6, 1e-12);
}

namespace {
WaterConfig zero_noise_config(PairMode mode) {
  WaterConfig cfg;
  cfg.noise_override = NoiseOverride::none;
  cfg.pairs = mode;
  cfg.threads = 1;
  return cfg;
}
}  // namespace

// Three beads on a line in a box of L, at rest, no noise: bead 0 at x = 0.2, bead 1 at 0.9 (r = 0.7),
// bead 2 at L − 0.2 whose image sits at −0.2 (r = 0.4 from bead 0); beads 1 and 2 are 1.1 apart (no force).
//   F_0 = −25·0.3 + 25·0.6 = +7.5,  F_1 = +7.5,  F_2 = −15;  Σ r·F^C = 25·0.3·0.7 + 25·0.6·0.4 = 11.25 (xx only).
// L = 5 gives cells mode a grid (5 × 5 × 4 cells); L = 2.5 is too small for one: a single cell owns every pair.
TEST(PairLoop, ThreeBeadsThroughThePeriodicBoundary) {
  for (double L : {5.0, 2.5}) {
    for (PairMode mode : {PairMode::all, PairMode::cells}) {
      System s;
      s.box = Box{{L, L, L}};
      s.resize(3);
      s.x = {0.2, 0.9, L - 0.2};
      s.y = {0.5, 0.5, 0.5};
      s.z = {0.5, 0.5, 0.5};
      const WaterConfig cfg = zero_noise_config(mode);
      auto pf = make_pair_forces(cfg, make_kernel(25, 1, 4.5, 1, 0.04), 3);
      Taps taps;
      const ForceSums f = pf->compute(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()}, 0, false, false, false, taps);
      EXPECT_NEAR(s.fx[0], 7.5, 1e-12) << to_string(mode) << " L = " << L;
      EXPECT_NEAR(s.fx[1], 7.5, 1e-12);
      EXPECT_NEAR(s.fx[2], -15.0, 1e-12);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(s.fy[i], 0.0);
        EXPECT_EQ(s.fz[i], 0.0);
      }
      EXPECT_NEAR(f.virial_cons[0], 11.25, 1e-12);
      EXPECT_NEAR(f.virial[0], 11.25, 1e-12);  // no velocity, no noise: the total is the conservative part
      EXPECT_EQ(f.virial_cons[1], 0.0);
      EXPECT_EQ(f.in_range, 2u);
      EXPECT_NEAR(f.min_r2, 0.16, 1e-12);
    }
  }
}

// ζ_ij = ζ_ji: the pair loop visits i < j with d = r_j − r_i; seen from j the same pair is (j, i, −d), and
// canonical() must map it back to the same generator input for every generator and seeding.
// Beads 0 and 1 at one position, bead 2 at r = 0.5 from both, moving, under 32TEA(1) noise: every force and
// virial is finite, the conservative virial is the two r = 0.5 pairs' alone, and min_r2 reports the 0 so that
// the run's guard (min_distance) still sees it.
TEST(PairLoop, CoincidentBeadsGiveNoForceAndNoNaN) {
  for (PairMode mode : {PairMode::all, PairMode::cells}) {
    System s;
    s.box = Box{{5.0, 5.0, 5.0}};
    s.resize(3);
    s.x = {1.0, 1.0, 1.5};
    s.y = {2.0, 2.0, 2.0};
    s.z = {2.0, 2.0, 2.0};
    s.vx = {0.3, -0.4, 0.1};
    WaterConfig cfg;
    cfg.pairs = mode;
    cfg.threads = 1;
    cfg.generator = rng::validated({"tea32", 1});
    auto pf = make_pair_forces(cfg, make_kernel(25, 1, 4.5, 1, 0.04), 3);
    Taps taps;
    const ForceSums f = pf->compute(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()}, 7, false, false, false, taps);
    for (int i = 0; i < 3; ++i)
      EXPECT_TRUE(std::isfinite(s.fx[i]) && std::isfinite(s.fy[i]) && std::isfinite(s.fz[i])) << to_string(mode);
    for (int a = 0; a < 3; ++a) EXPECT_TRUE(std::isfinite(f.virial[a]) && std::isfinite(f.virial_cons[a]));
    // The conservative virial is that of the two r = 0.5 pairs alone: 2 · a w r = 2 · 25 · 0.5 · 0.5 (xx only).
    EXPECT_NEAR(f.virial_cons[0], 12.5, 1e-12) << to_string(mode);
    EXPECT_EQ(f.virial_cons[1], 0.0);
    EXPECT_EQ(f.min_r2, 0.0);
    // Alone, the coincident pair gives exactly zero force.
    System two;
    two.box = s.box;
    two.resize(2);
    two.x = {1.0, 1.0}, two.y = {2.0, 2.0}, two.z = {2.0, 2.0}, two.vx = {0.3, -0.4};
    auto pf2 = make_pair_forces(cfg, make_kernel(25, 1, 4.5, 1, 0.04), 2);
    const ForceSums g =
        pf2->compute(two, VelocityView{two.vx.data(), two.vy.data(), two.vz.data()}, 7, false, false, false, taps);
    for (int i = 0; i < 2; ++i) EXPECT_TRUE(two.fx[i] == 0.0 && two.fy[i] == 0.0 && two.fz[i] == 0.0) << to_string(mode);
    EXPECT_EQ(g.virial[0] + g.virial[1] + g.virial[2], 0.0);
    EXPECT_EQ(g.virial_cons[0] + g.virial_cons[1] + g.virial_cons[2], 0.0);
  }
}

TEST(PairNoise, SymmetricForEverySeedingAndGenerator) {
  for (const rng::GeneratorSpec& spec : every_generator(false))
    for (rng::Seeding seeding : {rng::Seeding::distance, rng::Seeding::pair_step})
      for (rng::Distribution dist : {rng::Distribution::gauss, rng::Distribution::uniform})
        rng::with_pair_noise(spec, seeding, dist, 77, [&](auto pn) {
          for (int k = 0; k < 50; ++k) {
            const double dx = 0.013 * k - 0.31, dy = 0.7 - 0.011 * k, dz = 0.002 * k;
            const rng::PairInput ij{3, 9, dx, dy, dz, std::uint64_t(100 + k)};
            const rng::PairInput ji{9, 3, -dx, -dy, -dz, std::uint64_t(100 + k)};
            const double a = pn(ij), b = pn(rng::canonical(ji));
            EXPECT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b))
                << rng::describe(spec) << " " << rng::to_string(seeding) << " k=" << k;
          }
          return 0;
        });
}

namespace {
// A 64-bead run of `steps` steps (`equilibrate` of them before production) on one thread, tapping every pair's
// words on raw_steps and the series of `pairs`.
WaterConfig tapped_run(const rng::GeneratorSpec& generator, std::int64_t steps, std::int64_t equilibrate,
                       std::vector<std::int64_t> raw_steps,
                       std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs) {
  WaterConfig cfg;
  cfg.particles = 64;
  cfg.steps = steps;
  cfg.equilibrate = equilibrate;
  cfg.generator = rng::validated(generator);
  cfg.taps.raw_steps = std::move(raw_steps);
  cfg.threads = 1;
  cfg.taps.pairs = std::move(pairs);
  return cfg;
}
}  // namespace

// The raw words the engine taps for a pair are those of the canonical input: i < j and d = r_j − r_i.
TEST(PairLoop, TappedWordsAreTheCanonicalPairsHash) {
  const WaterConfig cfg = tapped_run({"tea32", 1}, 3, 1, {2}, {{5, 40}});
  const RunResult r = run_water(cfg);
  ASSERT_EQ(r.taps.raw.size(), 1u);
  EXPECT_EQ(r.taps.raw[0].words[0].size(), 64u * 63u / 2u);
  ASSERT_EQ(r.taps.series.size(), 1u);
  ASSERT_EQ(r.taps.series[0].steps.size(), 2u);  // production steps 2 and 3
  EXPECT_EQ(r.taps.series[0].steps[0], 2);
  EXPECT_EQ(r.taps.series[0].words[0][0], r.taps.raw[0].words[0][pair_slot(5, 40, 64)]);
  // And ζ is the distribution applied to that word.
  const double zeta = rng::draw<rng::Distribution::gauss>(std::array<std::uint64_t, 1>{r.taps.series[0].words[0][0]});
  EXPECT_EQ(r.taps.series[0].zeta[0], zeta);
}

// The reference stream's series read their pairs' slots of the step, in one batch: each tapped pair's word is
// the one the raw tap holds at its slot, and its ζ that word's.
TEST(PairLoop, TheStreamsSeriesReadTheirPairsSlots) {
  const WaterConfig cfg = tapped_run({"mt19937", 0}, 3, 1, {3}, {{0, 1}, {5, 40}, {5, 41}, {62, 63}});
  const RunResult r = run_water(cfg);
  ASSERT_EQ(r.taps.raw.size(), 1u);
  ASSERT_EQ(r.taps.series.size(), cfg.taps.pairs.size());
  for (const PairSeries& ser : r.taps.series) {
    ASSERT_EQ(ser.steps.size(), 2u);  // production steps 2 and 3
    EXPECT_EQ(ser.steps[1], 3);
    EXPECT_EQ(ser.words[0][1], r.taps.raw[0].words[0][pair_slot(ser.i, ser.j, 64)]) << ser.i << "," << ser.j;
    const double zeta = rng::draw<rng::Distribution::gauss>(std::array<std::uint64_t, 1>{ser.words[0][1]});
    EXPECT_EQ(ser.zeta[1], zeta);
  }
}

// A run's pair series hold every production step in order, the words of each the step's own: across the
// pair loop's stage of the latest steps and what is left in it at the end of the run.
TEST(PairLoop, PairSeriesKeepEveryProductionStepInOrder) {
  WaterConfig cfg = tapped_run({"tea64", 2}, 150, 10, {11, 75, 130, 150}, {{0, 1}, {5, 40}, {62, 63}});
  cfg.feed = rng::Feed::blocks;
  const RunResult r = run_water(cfg);
  ASSERT_EQ(r.taps.raw.size(), cfg.taps.raw_steps.size());
  for (const PairSeries& ser : r.taps.series) {
    ASSERT_EQ(ser.steps.size(), 140u);
    ASSERT_EQ(ser.zeta.size(), 140u);
    for (std::size_t c = 0; c < ser.steps.size(); ++c) EXPECT_EQ(ser.steps[c], std::int64_t(11 + c));
    for (const RawTap& raw : r.taps.raw)
      for (int w = 0; w < 2; ++w)
        EXPECT_EQ(ser.words[w][std::size_t(raw.step - 11)], raw.words[w][pair_slot(ser.i, ser.j, 64)])
            << ser.i << "," << ser.j << " step " << raw.step << " word " << w;
  }
}

// A raw hook sees every raw tap as its step is done, with the words a run without it keeps; what it takes is not
// kept, and the storage it gives back serves the later taps: all mode writes every slot over it, cells mode
// (125 beads: three cells of r_c a side) starts each step's list afresh.
TEST(PairLoop, ARawHookSeesEveryTapAndKeepsWhatItLeaves) {
  for (PairMode mode : {PairMode::all, PairMode::cells}) {
    WaterConfig cfg = tapped_run({"tea64", 1}, 12, 2, {3, 5, 6, 9, 12}, {});
    cfg.particles = 125;
    cfg.pairs = mode;
    const RunResult plain = run_water(cfg);
    std::vector<RawTap> seen;
    RunHooks hooks;
    hooks.raw = [&seen](const RawTap& tap) {
      seen.push_back(tap);
      return tap.step != 9;
    };
    const RunResult hooked = run_water(cfg, hooks);
    ASSERT_EQ(plain.taps.raw.size(), 5u);
    ASSERT_EQ(seen.size(), 5u);
    for (std::size_t k = 0; k < seen.size(); ++k) {
      EXPECT_EQ(seen[k].step, plain.taps.raw[k].step);
      EXPECT_EQ(seen[k].words, plain.taps.raw[k].words) << to_string(mode) << " step " << seen[k].step;
    }
    ASSERT_EQ(hooked.taps.raw.size(), 1u);
    EXPECT_EQ(hooked.taps.raw[0].step, 9);
    EXPECT_EQ(hooked.taps.raw[0].words, plain.taps.raw[3].words);
    EXPECT_TRUE(hooked.taps.recycled.empty());
  }
}

namespace {
struct Snapshot {
  std::vector<double> x, v;
};
Snapshot run_snapshot(WaterConfig cfg) {
  Snapshot snap;
  RunHooks hooks;
  hooks.observe = [&](std::int64_t step, const System& s) {
    if (step != cfg.steps) return;
    snap.x = s.x, snap.x.insert(snap.x.end(), s.y.begin(), s.y.end()), snap.x.insert(snap.x.end(), s.z.begin(), s.z.end());
    snap.v = s.vx, snap.v.insert(snap.v.end(), s.vy.begin(), s.vy.end());
  };
  const RunResult r = run_water(cfg, hooks);
  EXPECT_TRUE(r.ok()) << r.status;
  return snap;
}
}  // namespace

// Bitwise-identical trajectories for 1 and 2 threads, for a hash and for the mt19937 stream, both pair modes,
// under GW-MVV, the self-consistent VV (its dissipative passes) and the pairwise Nosé–Hoover–Langevin thermostat
// (its coloured friction sweeps).
TEST(Determinism, OneAndTwoThreadsGiveTheSameBits) {
  for (const char* integrator : {"mvv", "scmvv:3", "pnhln"})
  for (const char* gen : {"tea32", "mt19937"})
    for (PairMode mode : {PairMode::all, PairMode::cells}) {
      WaterConfig cfg;
      set_integrator(cfg, integrator, "integrator");
      cfg.particles = 500;
      // The other integrators' steps hold several pair passes each, with a barrier per colour of their sweeps.
      cfg.steps = cfg.integrator == Integrator::mvv ? test_scale::scaled(100, 30) : test_scale::scaled(30, 15);
      cfg.equilibrate = 0;
      cfg.pairs = mode;
      cfg.generator = rng::validated({gen, 0});
      cfg.observables = false;
      cfg.team_beads = 0;  // 500 beads: under the one-thread size
      cfg.threads = 1;
      const Snapshot a = run_snapshot(cfg);
      cfg.threads = 2;
      const Snapshot b = run_snapshot(cfg);
      ASSERT_EQ(a.x.size(), 1500u);
      for (std::size_t k = 0; k < a.x.size(); ++k)
        ASSERT_EQ(std::bit_cast<std::uint64_t>(a.x[k]), std::bit_cast<std::uint64_t>(b.x[k]))
            << integrator << " " << gen << " " << to_string(mode) << " coordinate " << k;
      for (std::size_t k = 0; k < a.v.size(); ++k)
        ASSERT_EQ(std::bit_cast<std::uint64_t>(a.v[k]), std::bit_cast<std::uint64_t>(b.v[k])) << integrator;
    }
}

// A system under team_beads runs on one thread whatever was asked; the run says which count it used.
TEST(TeamThreads, SmallSystemsRunOnOneThread) {
  EXPECT_EQ(team_threads(2, 256), 1);
  EXPECT_EQ(team_threads(2, kTeamBeads - 1), 1);
  EXPECT_EQ(team_threads(2, kTeamBeads), 2);
  EXPECT_EQ(team_threads(3, 24000), 3);
  EXPECT_EQ(team_threads(2, 256, 0), 2);
  EXPECT_GE(team_threads(0, 24000), 1);
  WaterConfig cfg;
  cfg.steps = 3;
  cfg.equilibrate = 0;
  cfg.observables = false;
  cfg.threads = 2;
  EXPECT_EQ(run_water(cfg).timings.threads, 1);
  cfg.team_beads = 0;
  EXPECT_EQ(run_water(cfg).timings.threads, 2);
}

// The defect generator reads its base at the step before as well: still a pure function of pair and step.
TEST(Determinism, DefectGeneratorOneAndTwoThreads) {
  for (PairMode mode : {PairMode::all, PairMode::cells}) {
    WaterConfig cfg;
    cfg.particles = 500;
    cfg.steps = test_scale::scaled(60, 20);
    cfg.equilibrate = 0;
    cfg.pairs = mode;
    cfg.generator = rng::validated({"defect:variance=0.05,lag1=0.3,mean=0.01", 0});
    cfg.seeding = rng::Seeding::pair_step;
    cfg.observables = false;
    cfg.team_beads = 0;
    cfg.threads = 1;
    const Snapshot a = run_snapshot(cfg);
    cfg.threads = 2;
    const Snapshot b = run_snapshot(cfg);
    ASSERT_EQ(a.x.size(), 1500u);
    for (std::size_t k = 0; k < a.x.size(); ++k)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a.x[k]), std::bit_cast<std::uint64_t>(b.x[k])) << to_string(mode);
  }
}

// The pair forces cancel in pairs, so the total momentum (zero at the start) only collects round-off: per
// step about Δt·ε·Σ|F| ≈ 0.04 · 1e-16 · (N·40) ≈ 1e-13 for N = 256, a random walk over the run. 1e-11 per
// bead after 500 steps is a loose bound on round-off and far below any real leak (one unpaired force would
// move it by ~Δt·|F|/N ≈ 1e-3 in one step).
// The same holds under the self-consistent VV (its dissipative passes are pair forces too) and the pairwise
// Nosé–Hoover–Langevin thermostat (each pair's friction update moves its two beads by opposite amounts).
TEST(Momentum, ConservedToRoundOff) {
  for (const char* integrator : {"mvv", "scmvv:5", "pnhln"})
  for (PairMode mode : {PairMode::all, PairMode::cells}) {
    WaterConfig cfg;
    set_integrator(cfg, integrator, "integrator");
    cfg.steps = test_scale::scaled(500, 100);
    cfg.equilibrate = 0;
    cfg.pairs = mode;
    cfg.generator = rng::validated({"tea64", 2});
    cfg.observables = false;
    cfg.threads = 1;
    const RunResult r = run_water(cfg);
    ASSERT_TRUE(r.ok()) << r.status;
    EXPECT_LT(r.momentum_drift, 1e-11) << integrator << " " << to_string(mode);
  }
}

}  // namespace dpdrng_test::dpd_test_forces
