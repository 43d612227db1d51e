#include "dpdrng/dpd/scene.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "run_check.hpp"

namespace dpdrng::dpd {

namespace {

StepSums step_sums(const System& s, std::int64_t step, const ForceSums& f, double V) {
  const std::size_t n = s.size();
  StepSums x;
  x.step = step;
  x.forces = &f;
  double kin[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    kin[0] += s.vx[i] * s.vx[i], kin[1] += s.vy[i] * s.vy[i], kin[2] += s.vz[i] * s.vz[i];
  x.T = (kin[0] + kin[1] + kin[2]) / (3.0 * n - 3.0);
  for (int a = 0; a < 3; ++a) {
    x.kin[a] = kin[a];
    x.P[a] = (kin[a] + f.virial[a]) / V;
    x.Pc[a] = (kin[a] + f.virial_cons[a]) / V;
  }
  x.momentum = s.momentum();
  return x;
}

}  // namespace

SceneRun run_scene(System& s, const SceneLimits& limits, const std::function<ForceSums()>& start,
                   const std::function<ForceSums(std::int64_t step)>& advance, SceneObserver& observer,
                   const RunHooks& hooks) {
  SceneRun r;
  const double n = double(s.size()), V = s.box.volume();
  const auto t_start = SceneClock::now();
  ForceSums f = start();
  const auto p0 = r.momentum_initial = s.momentum();
  auto t_production = t_start;
  const std::int64_t progress_every = std::max<std::int64_t>(1, limits.steps / 50);
  TeamGovernor governor(limits.threads);
  for (std::int64_t step = 1; step <= limits.steps; ++step) {
    if (step == limits.equilibrate + 1) t_production = SceneClock::now();
    const TeamCap cap(governor.team());
    const auto t_step = SceneClock::now();
    f = advance(step);
    governor.record(seconds_between(t_step, SceneClock::now()));
    r.steps_done = step;
    StepSums x = step_sums(s, step, f, V);
    x.production = step > limits.equilibrate;
    const auto& p = x.momentum;
    r.momentum_drift = std::max(r.momentum_drift, std::hypot(p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]) / n);
    observer.every_step(x, s);
    RunStatus why = detail::check_state(limits, x.step, x.T, *x.forces);
    if (why.ok()) why = observer.check(x);
    if (!why.ok()) {
      r.status = std::move(why);
      break;
    }
    observer.sample(x, s);
    if (hooks.observe) hooks.observe(step, s);
    if (hooks.progress && step % progress_every == 0) hooks.progress(step, limits.steps);
  }
  const auto t_end = SceneClock::now();
  r.total_s = seconds_between(t_start, t_end);
  r.production_s = r.steps_done > limits.equilibrate ? seconds_between(t_production, t_end) : 0.0;
  r.momentum_final = s.momentum();
  r.steps_by_team = governor.steps_by_team(), r.team_moves = governor.moves();
  return r;
}

Timings scene_timings(const SceneRun& run, const ForceCounters& counters, const SceneLimits& limits, PairForces& pair,
                      const WaterConfig& pair_config, const DpdKernel& kernel, const System& s, bool estimate_share,
                      int threads) {
  const double n = double(s.size()), total = run.total_s;
  Timings t;
  t.total_s = total;
  t.force_s = counters.seconds;
  t.per_step_s = run.steps_done ? total / run.steps_done : 0;
  t.particle_steps_per_s = total > 0 ? n * run.steps_done / total : 0;
  t.production_s = run.production_s;
  t.production_particle_steps_per_s =
      run.production_s > 0 ? n * double(run.steps_done - limits.equilibrate) / run.production_s : 0;
  t.random_numbers = counters.numbers;
  t.zetas = counters.zetas;
  t.pairs_in_range = counters.pairs;
  t.pair_candidates = counters.candidates;
  t.ns_per_number = pair.ns_per_number();
  t.ns_per_zeta = pair.ns_per_zeta();
  // By difference against ζ = 0 on the final state (3 % of the run's time at most, beyond 5 pairs of force
  // evaluations), scaled by the force evaluations' share of the run: the RNG's share of a step.
  if (estimate_share && run.steps_done > 0 && total > 0)
    t.rng_share_estimate =
        rng_share_by_difference(pair, pair_config, kernel, s, std::uint64_t(limits.steps) + 1, 0.03 * total) *
        std::min(1.0, counters.seconds / total);
  t.list_builds = pair.list_builds();
  t.threads = threads;
  t.steps_by_team = run.steps_by_team, t.team_moves = run.team_moves;
  return t;
}

}  // namespace dpdrng::dpd
