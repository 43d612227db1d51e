// The team a run's regions use: the per-thread cap, the governor's choice from step times (fed fake times, so
// that the policy is tested apart from any clock), and the engine's bits when the team changes every step.
#include <gtest/gtest.h>

#include <bit>
#include <functional>
#include <thread>

#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/team.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/dpd/water_integrator.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "scale.hpp"

namespace dpdrng_test::dpd_test_team {

using namespace dpdrng;
using namespace dpdrng::dpd;

TEST(TeamCap, LowersTheTeamOfItsOwnThreadWhileItLives) {
  EXPECT_EQ(team_size(3), 3);
  {
    const TeamCap one(1);
    EXPECT_EQ(team_size(3), 1);
    {
      const TeamCap two(2);  // inside a lower cap: the lower holds
      EXPECT_EQ(team_size(3), 1);
    }
    int other = 0;
    std::thread([&] { other = team_size(3); }).join();
    EXPECT_EQ(other, 3);  // another thread's runs keep their team
    EXPECT_EQ(team_size(3), 1);
  }
  EXPECT_EQ(team_size(3), 3);
  const TeamCap two(2);
  EXPECT_EQ(team_size(3), 2);
  EXPECT_EQ(team_size(1), 1);
}

// A run of `steps` steps under the governor, each step taking time(team, step); returns the total time.
struct Governed {
  double seconds = 0;
  TeamGovernor g;
};
Governed govern(int threads, std::int64_t steps, const std::function<double(int, std::int64_t)>& time) {
  Governed run{0.0, TeamGovernor(threads)};
  for (std::int64_t k = 0; k < steps; ++k) {
    const double t = time(run.g.team(), k);
    run.seconds += t;
    run.g.record(t);
  }
  return run;
}

// A quiet two-core machine: two threads take 1/1.87 of one thread's time (bench dpd's cells scene on an AMD
// EPYC). The governor stays with two and its probes of one thread cost about kBudget of the run.
TEST(TeamGovernor, KeepsTheWholeTeamWhereItIsFastest) {
  const std::int64_t steps = 5000;
  const Governed r = govern(2, steps, [](int team, std::int64_t) { return team == 2 ? 1.0 : 1.87; });
  EXPECT_EQ(r.g.moves(), 0);
  EXPECT_EQ(r.g.team(), 2);
  EXPECT_GT(r.g.steps_by_team().at(1), 0);  // it did look
  EXPECT_LT(r.seconds / double(steps) - 1.0, 2 * TeamGovernor::kBudget);
}

// Beside a busy core two threads take 1.3 times one thread's time (bench dpd --oversubscribe's cells scene): the
// first probe moves to one thread, and the run costs one thread's time within the probing budget.
TEST(TeamGovernor, MovesToOneThreadBesideABusyCore) {
  const std::int64_t steps = 5000;
  const Governed r = govern(2, steps, [](int team, std::int64_t) { return team == 2 ? 1.3 : 1.0; });
  EXPECT_EQ(r.g.moves(), 1);
  EXPECT_EQ(r.g.team(), 1);
  EXPECT_LT(r.seconds / double(steps) - 1.0, 2 * TeamGovernor::kBudget);
}

// The other process comes and goes: the governor follows, and is back on two threads soon after it leaves.
TEST(TeamGovernor, FollowsLoadThatComesAndGoes) {
  const auto busy = [](std::int64_t k) { return k >= 1000 && k < 3000; };
  const Governed r = govern(2, 5000, [&](int team, std::int64_t k) {
    if (busy(k)) return team == 2 ? 1.3 : 1.0;
    return team == 2 ? 1.0 : 1.87;
  });
  EXPECT_GE(r.g.moves(), 2);
  EXPECT_EQ(r.g.team(), 2);
  // Ideal: 1.0 a step throughout. Each change of load is noticed within one probe interval (≤ 3·0.87/0.01 steps
  // on the quiet side, ≤ 3·0.3/0.01 on the busy side).
  EXPECT_LT(r.seconds / 5000.0 - 1.0, 0.03);
}

// More cores, one of them busy: of 8, 4, 2 and 1 threads the 4 are fastest; the ladder gets there and stays.
TEST(TeamGovernor, ClimbsTheLadderToTheFastestTeam) {
  const Governed r = govern(8, 5000, [](int team, std::int64_t) { return team == 8 ? 0.6 : 1.0 / team; });
  EXPECT_EQ(r.g.team(), 4);
  EXPECT_EQ(r.g.moves(), 1);
  EXPECT_GT(r.g.steps_by_team().at(2), 0);  // it looked below
  EXPECT_GT(r.g.steps_by_team().at(8), 8);  // and above, after moving
  EXPECT_EQ(r.g.steps_by_team().count(1), 0u);
}

// One thread asked: nothing to choose, no probe.
TEST(TeamGovernor, OneThreadNeverProbes) {
  const Governed r = govern(1, 1000, [](int, std::int64_t) { return 1.0; });
  EXPECT_EQ(r.g.steps_by_team().size(), 1u);
  EXPECT_EQ(r.g.steps_by_team().at(1), 1000);
}

// The governor's premise: results do not depend on the team, even when it changes from one step to the next.
// A cells-mode fluid above the one-thread size runs its steps alternately on two threads and one, and its state
// equals bit for bit that of a run on one thread, under each integrator.
TEST(TeamGovernor, ATeamChangingEveryStepGivesTheSameBits) {
  for (const char* integrator : {"mvv", "scmvv:3", "pnhln", "shardlow"}) {
    WaterConfig cfg;
    set_integrator(cfg, integrator, "integrator");
    cfg.particles = 1500;
    cfg.pairs = PairMode::cells;
    cfg.generator = rng::validated({"tea32", 1});
    cfg.observables = false;
    cfg.team_beads = 0;
    cfg.threads = 2;
    const auto run = [&](bool alternate) {
      const std::size_t n = std::size_t(cfg.particles);
      const double L = cfg.box_length();
      System s = make_fluid(n, Box{{L, L, L}}, cfg.kT, cfg.init_seed);
      auto pair = make_pair_forces(pair_force_config(cfg), pair_force_kernel(cfg), n);
      WaterIntegrator vv(cfg);
      std::uint64_t step = 0;
      Taps taps;
      const ForceFn force = [&](System& sys, VelocityView v) {
        return pair->compute(sys, v, step, false, false, false, taps);
      };
      vv.start(s, force);
      for (step = 1; step <= std::uint64_t(test_scale::scaled(20, 8)); ++step) {
        const TeamCap cap(alternate ? int(1 + step % 2) : 1);
        vv.step(s, force);
      }
      return s;
    };
    const System a = run(false), b = run(true);
    for (std::size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a.x[k]), std::bit_cast<std::uint64_t>(b.x[k])) << integrator << " " << k;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a.vz[k]), std::bit_cast<std::uint64_t>(b.vz[k])) << integrator << " " << k;
    }
  }
}

}  // namespace dpdrng_test::dpd_test_team
