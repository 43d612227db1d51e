// The scenes' shared run loop: its schedule of observer calls, its guards, and a water run that blows up.
#include <gtest/gtest.h>

#include <string>

#include "dpdrng/dpd/scene.hpp"
#include "dpdrng/dpd/water.hpp"

namespace dpdrng::dpd::test_scene {
namespace {

struct Counting : SceneObserver {
  int every = 0, checks = 0, samples = 0, production = 0;
  std::int64_t stop_at = -1;  // the scene's own guard fires at this step
  void every_step(const StepSums&, const System&) override { ++every; }
  RunStatus check(const StepSums& x) override {
    ++checks;
    return x.step == stop_at ? RunStatus::unstable(x.step, "scene says stop") : RunStatus{};
  }
  void sample(const StepSums& x, const System&) override {
    ++samples;
    production += x.production ? 1 : 0;
  }
};

// A still fluid with a force callback that returns no forces: the loop's schedule without physics.
struct StillFluid {
  System s = make_fluid(27, Box{{3.0, 3.0, 3.0}}, 1.0, 7);
  double min_r2 = 1.0;
  std::int64_t close_at = -1;  // the beads come closer than min_distance at this step
  ForceSums forces(std::int64_t step) const {
    ForceSums f;
    f.min_r2 = step == close_at ? 0.0 : min_r2;
    return f;
  }
  SceneRun run(const SceneLimits& lim, SceneObserver& obs, const RunHooks& hooks = {}) {
    return run_scene(
        s, lim, [&] { return forces(0); }, [&](std::int64_t k) { return forces(k); }, obs, hooks);
  }
};

TEST(SceneRun, CallsObserversOncePerStep) {
  StillFluid fluid;
  Counting obs;
  int observed = 0;
  RunHooks hooks;
  hooks.observe = [&](std::int64_t, const System&) { ++observed; };
  const SceneRun r = fluid.run({.steps = 30, .equilibrate = 12}, obs, hooks);
  EXPECT_TRUE(r.status.ok());
  EXPECT_EQ(r.steps_done, 30);
  EXPECT_EQ(obs.every, 30);
  EXPECT_EQ(obs.checks, 30);
  EXPECT_EQ(obs.samples, 30);
  EXPECT_EQ(obs.production, 18);
  EXPECT_EQ(observed, 30);
}

// Make_fluid's Maxwell velocities, unmoved: the shared sums are those of the state itself.
TEST(SceneRun, SumsAreTheStatesKineticEnergyAndPressure) {
  StillFluid fluid;
  struct Last : SceneObserver {
    StepSums x;
    void sample(const StepSums& s, const System&) override { x = s; }
  } obs;
  fluid.run({.steps = 2}, obs);
  const System& s = fluid.s;
  double kx = 0, ky = 0, kz = 0;
  for (std::size_t i = 0; i < s.size(); ++i) kx += s.vx[i] * s.vx[i], ky += s.vy[i] * s.vy[i], kz += s.vz[i] * s.vz[i];
  EXPECT_EQ(obs.x.step, 2);
  EXPECT_DOUBLE_EQ(obs.x.T, (kx + ky + kz) / (3.0 * 27 - 3.0));
  EXPECT_DOUBLE_EQ(obs.x.P[0], kx / 27.0);
  EXPECT_DOUBLE_EQ(obs.x.Pc[2], kz / 27.0);
}

TEST(SceneRun, SceneGuardStopsTheRun) {
  StillFluid fluid;
  Counting obs;
  obs.stop_at = 7;
  const SceneRun r = fluid.run({.steps = 30, .equilibrate = 3}, obs);
  EXPECT_EQ(r.status.text(), "unstable at step 7: scene says stop");
  EXPECT_EQ(r.steps_done, 7);
  EXPECT_EQ(obs.every, 7);  // the step that failed is traced, not sampled
  EXPECT_EQ(obs.samples, 6);
  EXPECT_EQ(obs.production, 3);
}

TEST(SceneRun, SharedGuardsComeFirst) {
  StillFluid fluid;
  fluid.close_at = 4;
  Counting obs;
  obs.stop_at = 4;
  const SceneRun r = fluid.run({.steps = 10, .min_distance = 1e-3}, obs);
  EXPECT_EQ(r.status.text().rfind("unstable at step 4: beads closer than 0.001", 0), 0u) << r.status;
  EXPECT_EQ(obs.checks, 3);  // the scene's guard is not asked once a shared one has fired
  EXPECT_EQ(obs.samples, 3);
}

TEST(SceneRun, TemperatureRunawayNamesTheStep) {
  StillFluid fluid;
  Counting obs;
  const SceneRun r = fluid.run({.steps = 5, .kT = 1e-6, .max_temperature = 100.0}, obs);
  EXPECT_EQ(r.status.text().rfind("unstable at step 1: temperature runaway (k_BT = ", 0), 0u) << r.status;
  EXPECT_EQ(obs.samples, 0);
}

// A water run at Δt = 5 blows up at its first step; its record keeps the labels and nulls the observables.
TEST(SceneRun, WaterBlowUpIsReportedWithNullObservables) {
  WaterConfig c;
  c.particles = 64;
  c.steps = 20;
  c.equilibrate = 10;
  c.dt = 5;
  c.threads = 1;
  c.series = true;
  const RunResult r = run_water(c);
  EXPECT_EQ(r.status.text().rfind("unstable at step 1: temperature runaway", 0), 0u) << r.status;
  EXPECT_EQ(r.steps_done, 1);
  EXPECT_EQ(r.series.step.size(), 1u);  // the series ends at the step that blew up
  EXPECT_EQ(r.temperature.n, 0u);
  const nlohmann::json j = to_json(r, false);
  EXPECT_EQ(j["status"], r.status.text());
  EXPECT_TRUE(j["temperature_mean"].is_null());
  EXPECT_TRUE(j["diffusion_coefficient"].is_null());
  EXPECT_TRUE(j["pressure"].is_null());
  EXPECT_FALSE(j["generator"].is_null());
}

}  // namespace
}  // namespace dpdrng::dpd::test_scene
