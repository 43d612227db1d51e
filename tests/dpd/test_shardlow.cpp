// Shardlow's S1 splitting (--integrator shardlow) against published findings, its momentum conservation and
// its determinism. Sources and tolerances beside each test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "dpdrng/dpd/shardlow.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "scale.hpp"

namespace dpdrng_test::dpd_test_shardlow {

using namespace dpdrng;
using namespace dpdrng::dpd;

namespace {
// ρ = 3, a = 25, γ = 4.5 (σ = 3), k_BT = 1: the system of Groot & Warren (1997) Figs. 2–3 and of Nikunen,
// Karttunen & Vattulainen (2003). 500 beads (box 5.5: the sweep's cell path).
WaterConfig s1_config(double dt, std::int64_t steps) {
  WaterConfig cfg;
  cfg.particles = 500;
  cfg.pairs = PairMode::cells;
  cfg.gamma = 4.5;
  cfg.dt = dt;
  cfg.integrator = Integrator::shardlow;
  cfg.steps = steps;
  cfg.equilibrate = steps / 10;
  cfg.generator = rng::validated({"philox4x32", 10});
  cfg.seeding = rng::Seeding::pair_step;
  cfg.sample_every = 5;
  cfg.threads = 1;
  return cfg;
}

std::vector<double> velocities(const System& s) {
  std::vector<double> v(s.vx);
  v.insert(v.end(), s.vy.begin(), s.vy.end());
  v.insert(v.end(), s.vz.begin(), s.vz.end());
  return v;
}

const RunResult& s1_run_dt004() {
  static const RunResult r = [] {
    WaterConfig cfg = s1_config(0.04, test_scale::scaled(1500, 500));
    cfg.particles = 1000;  // 500 leave the standard error of ⟨k_BT⟩ near the 0.006 the 1 % claim needs
    return run_water(cfg);
  }();
  return r;
}
}  // namespace

// Nikunen, Karttunen & Vattulainen, Comput. Phys. Commun. 153, 407 (2003): with S1 the kinetic temperature
// stays within about 1 % of k_BT at Δt = 0.04, where Groot–Warren's λ = 0.5 runs a few per cent hot. Run: 1000
// beads, 1500 steps (150 equilibration, T every step, 20 block averages); tolerance 0.01 plus 3 standard errors.
TEST(Shardlow, TemperatureWithinOnePercentAtDt004) {
  const RunResult& r = s1_run_dt004();
  ASSERT_TRUE(r.ok()) << r.status;
  EXPECT_EQ(r.integrator, "shardlow");
  EXPECT_NEAR(r.temperature.mean, 1.0, 0.01 + 3 * r.temperature.sem);
  if (!test_scale::small_scale()) {
    EXPECT_LT(r.temperature.sem, 0.006);  // else the 1 % claim is not tested
  }
}

// Shardlow (2003) and Peters, Europhys. Lett. 66, 311 (2004): each pair's S1 update leaves the Maxwell–Boltzmann
// distribution invariant for any Δt, so any remaining temperature error comes from velocity-Verlet's treatment
// of the conservative force. Without one (a = 0) ⟨k_BT⟩ must be 1 at a time step as large as Δt = 0.06, where
// λ = 0.5 runs about 6 % hot; tolerance 0.005 plus 3 standard errors (500 beads, 1000 steps).
TEST(Shardlow, ThermostatAloneIsExactAtLargeTimeStep) {
  WaterConfig cfg = s1_config(0.06, test_scale::scaled(1000, 400));
  cfg.a = 0;
  const RunResult r = run_water(cfg);
  ASSERT_TRUE(r.ok()) << r.status;
  EXPECT_NEAR(r.temperature.mean, 1.0, 0.005 + 3 * r.temperature.sem);
}

// At Δt = 0.06 with a = 25 velocity-Verlet's conservative error shows in S1 too (3000 steps: +1.9 ± 0.3 %,
// against +5.8 ± 0.3 % for λ = 0.5 with the same noise and start; not the 1 % the brief expected): S1's
// deviation must be smaller than λ = 0.5's by more than two standard errors of each.
TEST(Shardlow, BeatsLambdaHalfAtDt006) {
  WaterConfig cfg = s1_config(0.06, test_scale::scaled(1000, 400));
  const RunResult s1 = run_water(cfg);
  cfg.integrator = Integrator::mvv;
  const RunResult mvv = run_water(cfg);
  ASSERT_TRUE(s1.ok() && mvv.ok()) << s1.status << " / " << mvv.status;
  const double err_s1 = std::abs(s1.temperature.mean - 1), err_mvv = std::abs(mvv.temperature.mean - 1);
  EXPECT_LT(err_s1 + 2 * (s1.temperature.sem + mvv.temperature.sem), err_mvv)
      << s1.temperature.mean << " vs " << mvv.temperature.mean;
}

// Allen & Tildesley, examples repository, python_examples/GUIDE.md "DPD program": P = 23.636(2) at ρ = 3,
// a = 25, k_BT = 1 with Shardlow's scheme. The S1 run reports the conservative pressure (kinetic + conservative
// virial); at Δt = 0.04 its temperature is within ~1 % of 1, which moves P by ≤ 0.1. Tolerance 0.15 plus 4
// standard errors, as the velocity-Verlet pressure test at Δt = 0.01 (test_physics.cpp).
TEST(Shardlow, PressureMatchesAllenTildesleysShardlowRun) {
  const RunResult& r = s1_run_dt004();
  ASSERT_TRUE(r.ok()) << r.status;
  EXPECT_NEAR(r.pressure_conservative.mean, 23.64, 0.15 + 4 * r.pressure_conservative.sem);
  // No dissipative or random virial in S1: equal but for the rounding of two virial sums.
  EXPECT_NEAR(r.pressure.mean, r.pressure_conservative.mean, 1e-9);
}

// Each pair update adds +Δ to v_i and −Δ to v_j, and velocity-Verlet's conservative kicks cancel pair by pair:
// the total momentum changes by round-off only (velocity-Verlet alone: ≈ 6e-16 per bead; bound 1e-13).
TEST(Shardlow, ConservesMomentumToRoundOff) {
  for (const char* gen : {"philox4x32", "mt19937"}) {
    WaterConfig cfg = s1_config(0.06, 300);
    cfg.generator = rng::validated({gen, 0});
    const RunResult r = run_water(cfg);
    ASSERT_TRUE(r.ok()) << r.status;
    EXPECT_LT(r.momentum_drift, 1e-13) << gen;
  }
}

// Velocities after `steps` steps of a run with `threads` threads, and its result.
std::pair<std::vector<double>, RunResult> run_velocities(WaterConfig cfg, int threads) {
  cfg.threads = threads;
  cfg.team_beads = 0;  // 500 beads: under the one-thread size
  std::vector<double> v;
  RunHooks hooks;
  hooks.observe = [&](std::int64_t step, const System& s) {
    if (step == cfg.steps) v = velocities(s);
  };
  RunResult r = run_water(cfg, hooks);
  return {std::move(v), std::move(r)};
}

// The coloured sweep's result is defined by its colours, blocks and pair order, not by the threads: 300 steps
// give bitwise the same velocities with 1, 2 and 3 threads, for an odd axis (500 beads: 5 cells a side, the
// wrapping third colour), an even one (768 beads: 6 a side), the mt19937 stream (drawn on one thread) and the
// all-pairs sweep of a box with 2 cells a side (64 beads).
TEST(Shardlow, BitwiseIdenticalForOneTwoAndThreeThreads) {
  struct Case {
    int particles;
    const char* gen;
  };
  for (const Case c : {Case{500, "tea32"}, Case{768, "philox4x32"}, Case{500, "mt19937"}, Case{64, "tea32"}}) {
    WaterConfig cfg = s1_config(0.04, 300);
    cfg.particles = c.particles;
    cfg.generator = rng::validated({c.gen, 0});
    cfg.seeding = rng::Seeding::distance;
    const auto [v1, r1] = run_velocities(cfg, 1);
    ASSERT_TRUE(r1.ok()) << r1.status;
    for (int t : {2, 3}) {
      const auto [vt, rt] = run_velocities(cfg, t);
      ASSERT_TRUE(rt.ok()) << rt.status;
      ASSERT_EQ(vt.size(), v1.size());
      EXPECT_EQ(std::memcmp(vt.data(), v1.data(), v1.size() * sizeof(double)), 0)
          << c.particles << " " << c.gen << " " << t << " threads";
      EXPECT_EQ(rt.temperature.mean, r1.temperature.mean) << c.particles << " " << c.gen << " " << t;
      EXPECT_EQ(rt.pressure.mean, r1.pressure.mean) << c.particles << " " << c.gen << " " << t;
      EXPECT_EQ(std::memcmp(&rt.zeta, &r1.zeta, sizeof(ZetaSums)), 0) << c.particles << " " << c.gen << " " << t;
    }
  }
}

// Every pair inside r_c is updated once per sweep, on the coloured path (3, 4 and 5 cells a side, and a box
// with 3, 4 and 7) and on the all-pairs path (a side of 2 cells: a cell would neighbour another twice). Each
// pair's ζ is a hash of (i, j, step), so the count and the sums Σζ, Σζ² of the sweep against a direct loop over
// all pairs i < j identify the set of pairs visited (up to the order of the sums: 1e-12 relative).
TEST(Shardlow, SweepUpdatesEveryPairInsideTheCutOffOnce) {
  WaterConfig cfg;
  cfg.generator = rng::validated({"philox4x32", 10});
  cfg.seeding = rng::Seeding::pair_step;
  cfg.threads = 2;
  for (const Box box : {Box{{3.2, 3.2, 3.2}}, Box{{4.5, 4.5, 4.5}}, Box{{5.9, 5.9, 5.9}}, Box{{3.5, 4.1, 7.3}},
                        Box{{2.9, 6.0, 6.0}}, Box{{6.0, 6.0, 2.1}}}) {
    const auto n = static_cast<std::size_t>(3.0 * box.volume());
    System s = make_fluid(n, box, 1.0, 11);
    const double p0x = std::accumulate(s.vx.begin(), s.vx.end(), 0.0);
    ShardlowSweep sweep(cfg);
    sweep.sweep(s, 3);
    ZetaSums direct;
    rng::with_pair_noise(cfg.generator, cfg.seeding, cfg.distribution, cfg.seed, [&](auto noise) {
      for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = i + 1; j < n; ++j) {
          const double dx = min_image(s.x[j] - s.x[i], box.L[0], 0.5 * box.L[0]),
                       dy = min_image(s.y[j] - s.y[i], box.L[1], 0.5 * box.L[1]),
                       dz = min_image(s.z[j] - s.z[i], box.L[2], 0.5 * box.L[2]);
          const double r2 = dx * dx + dy * dy + dz * dz;
          if (r2 < 1.0 && r2 > 0) direct.add(noise(rng::PairInput{i, j, dx, dy, dz, 3}));
        }
      return 0;
    });
    const std::string at = std::to_string(box.L[0]) + "x" + std::to_string(box.L[1]) + "x" + std::to_string(box.L[2]);
    ASSERT_GT(direct.n, 5 * n) << at;
    EXPECT_EQ(sweep.zeta_sums().n, direct.n) << at;
    EXPECT_NEAR(sweep.zeta_sums().s1, direct.s1, 1e-12 * direct.s2) << at;
    EXPECT_NEAR(sweep.zeta_sums().s2, direct.s2, 1e-12 * direct.s2) << at;
    EXPECT_NEAR(std::accumulate(s.vx.begin(), s.vx.end(), 0.0), p0x, 1e-12) << at;
  }
}

// The S1 update of one isolated pair against the closed form: with a = γw²Δt and b = σwζ√Δt (ζ the pair's
// Philox number at that step, drawn here through the rng API) an explicit half step followed by an implicit
// half step maps the relative velocity along the pair to u = [(1 − a)u₀ + 2b]/(1 + a); the total momentum and
// the velocity across the pair do not change, and a pair beyond r_c is left alone.
TEST(Shardlow, OnePairFollowsTheS1ClosedForm) {
  WaterConfig cfg;
  cfg.gamma = 4.5;
  cfg.dt = 0.05;
  cfg.generator = rng::validated({"philox4x32", 10});
  cfg.seeding = rng::Seeding::pair_step;
  ShardlowSweep sweep(cfg);
  System s;
  s.box = Box{{6, 6, 6}};
  s.resize(2);
  s.x = {1.0, 1.6}, s.y = {2.0, 2.0}, s.z = {3.0, 3.0};  // r = 0.6 along x
  s.vx = {0.3, -0.2}, s.vy = {0.5, 0.1}, s.vz = {-0.4, 0.7};
  const double u0 = s.vx[1] - s.vx[0];
  sweep.sweep(s, 7);
  const double zeta = rng::with_pair_noise(cfg.generator, cfg.seeding, cfg.distribution, cfg.seed, [](auto noise) {
    return noise(rng::PairInput{0, 1, 0.6, 0.0, 0.0, 7});
  });
  const double w = 1 - 0.6, a = cfg.gamma * w * w * cfg.dt, b = 3.0 * w * std::sqrt(cfg.dt) * zeta;
  EXPECT_NEAR(s.vx[1] - s.vx[0], ((1 - a) * u0 + 2 * b) / (1 + a), 1e-14);
  EXPECT_NEAR(s.vx[0] + s.vx[1], 0.1, 1e-15);
  EXPECT_EQ(s.vy, (std::vector<double>{0.5, 0.1}));
  EXPECT_EQ(s.vz, (std::vector<double>{-0.4, 0.7}));
  s.x = {1.0, 2.1};
  const auto before = velocities(s);
  sweep.sweep(s, 8);
  EXPECT_EQ(velocities(s), before);
}

}  // namespace dpdrng_test::dpd_test_shardlow
