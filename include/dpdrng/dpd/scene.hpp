#pragma once
// One run loop for every scene (water, bilayer, …): it steps the integrator through equilibration and
// production, forms the per-step sums every scene needs (kinetic energy, k_BT, the pressure tensor's diagonal,
// the momentum drift), stops a run that blows up ("unstable at step k: reason") and times it. What a scene
// measures lives in its SceneObserver, which the loop calls at fixed points of each step.
//
//   struct Counter : dpd::SceneObserver {
//     int n = 0;
//     void sample(const dpd::StepSums&, const dpd::System&) override { ++n; }
//   };
//   Counter c;
//   dpd::SceneRun r = dpd::run_scene(s, {.steps = 100, .kT = 1.0}, start, advance, c);
#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/system.hpp"
#include "dpdrng/dpd/water.hpp"

namespace dpdrng::dpd {

using SceneClock = std::chrono::steady_clock;
inline double seconds_between(SceneClock::time_point a, SceneClock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The schedule and the guards of a run: steps 1..equilibrate are equilibration, the rest production; a state
// hotter than max_temperature × kT or with beads closer than min_distance stops the run.
struct SceneLimits {
  std::int64_t steps = 0, equilibrate = 0;
  double kT = 1.0, max_temperature = 100.0, min_distance = 1e-5;
  double rc = 1.0;  // the pair loop's cut-off: pairs beyond it are not seen by the min_distance guard
  int threads = 1;  // the run's team; a TeamGovernor picks each step's from it and the times of the steps before
};

// What the loop computes at the end of every step, for the guards and the observers.
struct StepSums {
  std::int64_t step = 0;
  bool production = false;     // step > equilibrate
  const ForceSums* forces = nullptr;
  std::array<double, 3> kin{};  // Σ v_α²
  double T = 0;                 // Σv²/(3N − 3)
  std::array<double, 3> P{}, Pc{};  // (Σ v_α² + W_αα) / V, all pair forces / the conservative force's virial
  std::array<double, 3> momentum{};
};

class SceneObserver {
 public:
  virtual ~SceneObserver() = default;
  // Every completed step, before the guards: a trace that ends at the step that blew up.
  virtual void every_step(const StepSums&, const System&) {}
  // The scene's own reason to stop (checked after the shared guards), or ok.
  virtual RunStatus check(const StepSums&) { return {}; }
  // Every step that passed the guards, equilibration included (the observer keeps its own schedule).
  virtual void sample(const StepSums&, const System&) {}
};

// Force evaluations' cost and the numbers they drew, summed by the scene's force callback.
struct ForceCounters {
  double seconds = 0;
  std::uint64_t numbers = 0, zetas = 0;
  std::uint64_t pairs = 0, candidates = 0;  // pairs inside r_c (ζ = 0 runs too); candidates the search visited
};

struct SceneRun {
  RunStatus status;  // ok, or unstable at step k with its reason
  std::int64_t steps_done = 0;
  double momentum_drift = 0;  // max over steps of |P(t) − P(0)|, per bead
  std::array<double, 3> momentum_initial{}, momentum_final{};  // after the first force evaluation; at the end
  double total_s = 0, production_s = 0;
  std::map<int, std::int64_t> steps_by_team;  // steps run with each team size (TeamGovernor)
  std::int64_t team_moves = 0;
};

// `start` makes the first force evaluation; `advance(k)` moves the state through step k and returns its forces.
SceneRun run_scene(System& s, const SceneLimits& limits, const std::function<ForceSums()>& start,
                   const std::function<ForceSums(std::int64_t step)>& advance, SceneObserver& observer,
                   const RunHooks& hooks = {});

// A scene result's share of the loop's outcome: status, steps done, momentum drift and final momentum.
template <class Result>
void put_scene_run(Result& r, const SceneRun& run) {
  r.status = run.status;
  r.steps_done = run.steps_done;
  r.momentum_drift = run.momentum_drift;
  r.momentum_final = run.momentum_final;
}


// The timings every scene reports: wall clock per step and per particle-step, the force evaluations' share and
// the generator's cost (pair: the production pair loop), and the RNG's share of a step by difference against
// ζ = 0 on the final state if `estimate_share`.
Timings scene_timings(const SceneRun& run, const ForceCounters& counters, const SceneLimits& limits, PairForces& pair,
                      const WaterConfig& pair_config, const DpdKernel& kernel, const System& s, bool estimate_share,
                      int threads);

}  // namespace dpdrng::dpd
