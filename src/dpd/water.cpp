#include "dpdrng/dpd/water.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "dpdrng/dpd/observables.hpp"
#include "dpdrng/dpd/shardlow.hpp"
#include "run_check.hpp"

namespace dpdrng::dpd {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// Per-step scalar samples of the production phase.
struct Samples {
  std::vector<double> T, P, Pc, Pd[3], Pcd[3];
};

}  // namespace

RunResult run_water(const WaterConfig& in, const RunHooks& hooks) {
  WaterConfig cfg = in;
  cfg.generator = rng::validated(in.generator);
  if (cfg.threads == 0) cfg.threads = omp_get_max_threads();
  cfg.validate();

  const std::size_t n = static_cast<std::size_t>(cfg.particles);
  const double L = cfg.box_length();
  System s = make_fluid(n, Box{{L, L, L}}, cfg.kT, cfg.init_seed);
  const DpdKernel kernel = pair_force_kernel(cfg);
  auto pair = make_pair_forces(pair_force_config(cfg), kernel, n);
  WaterIntegrator vv(cfg);

  RunResult r;
  r.generator = cfg.generator.name == "mt19937" ? "mt19937" : rng::describe(cfg.generator);
  if (cfg.noise_override == NoiseOverride::none) r.generator = "none";
  if (cfg.noise_override == NoiseOverride::unhashed) r.generator = "unhashed";
  r.seeding = cfg.generator.name == "mt19937" ? "stream" : std::string(rng::to_string(cfg.seeding));
  r.distribution = rng::to_string(cfg.distribution);
  r.feed = rng::to_string(cfg.feed);
  r.pairs = to_string(cfg.pairs);
  r.integrator = to_string(cfg.integrator);
  r.particles = n;
  r.box_length = L;

  std::vector<std::int64_t> raw_steps = cfg.taps.raw_steps;
  std::sort(raw_steps.begin(), raw_steps.end());
  raw_steps.erase(std::unique(raw_steps.begin(), raw_steps.end()), raw_steps.end());

  std::int64_t current = 0;
  // The ζ moments ride with the observables (a benchmark turns both off and pays for neither).
  const bool tap_zeta = cfg.observables && cfg.noise_override == NoiseOverride::off;
  double force_s = 0;
  std::uint64_t numbers = 0, zetas = 0;
  const ForceFn force = [&](System& sys, VelocityView v) {
    const auto t0 = Clock::now();
    const bool tap_raw = std::binary_search(raw_steps.begin(), raw_steps.end(), current);
    const bool production = current > cfg.equilibrate;
    const bool tap_series = !cfg.taps.pairs.empty() && production;
    const ForceSums f =
        pair->compute(sys, v, static_cast<std::uint64_t>(current), tap_raw, tap_series, tap_zeta && production, r.taps);
    force_s += seconds(t0, Clock::now());
    numbers += f.numbers;
    zetas += cfg.noise_override == NoiseOverride::none ? 0 : f.in_range;
    return f;
  };

  const std::int64_t production = cfg.steps - cfg.equilibrate;
  const int rdf_every = cfg.rdf_every > 0 ? cfg.rdf_every : (n <= 2000 ? cfg.sample_every : 20 * cfg.sample_every);
  int msd_every = cfg.msd_every > 0 ? cfg.msd_every : cfg.sample_every;
  const std::size_t max_frames = std::max<std::size_t>(1, (std::size_t{1} << 24) / (3 * n));
  msd_every = static_cast<int>(std::max<std::int64_t>(msd_every, (production + max_frames - 1) / max_frames));
  VelocityHistogram vpdf(cfg.vpdf_bins, cfg.vpdf_range * std::sqrt(cfg.kT), int(kStatBlocks));
  // The velocity and g(r) samples fall into kStatBlocks consecutive blocks, for their jackknife errors.
  const auto blocks = static_cast<std::int64_t>(kStatBlocks);
  const std::int64_t vpdf_samples = std::max<std::int64_t>(1, (production + cfg.sample_every - 1) / cfg.sample_every);
  MsdRecorder msd(n, msd_every * cfg.dt, max_frames);
  RdfHistogram rdf(cfg.rdf_bins, std::min(cfg.rdf_rmax, L / 2), cfg.threads, int(kStatBlocks));
  const std::int64_t rdf_samples = std::max<std::int64_t>(1, (production + rdf_every - 1) / rdf_every);
  Samples smp;

  const double V = s.box.volume();
  const auto t_start = Clock::now();
  ForceSums f = vv.start(s, force);
  const auto p0 = s.momentum();
  auto t_production = t_start;
  const std::int64_t progress_every = std::max<std::int64_t>(1, cfg.steps / 50);
  for (std::int64_t step = 1; step <= cfg.steps; ++step) {
    current = step;
    if (step == cfg.equilibrate + 1) t_production = Clock::now();
    f = vv.step(s, force);
    r.steps_done = step;
    double kin[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) kin[0] += s.vx[i] * s.vx[i], kin[1] += s.vy[i] * s.vy[i], kin[2] += s.vz[i] * s.vz[i];
    const double T = (kin[0] + kin[1] + kin[2]) / (3.0 * n - 3.0);
    const auto p = s.momentum();
    r.momentum_drift = std::max(r.momentum_drift, std::hypot(p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]) / n);
    double P = 0, Pc = 0, Pd[3], Pcd[3];
    for (int a = 0; a < 3; ++a) {
      Pd[a] = (kin[a] + f.virial[a]) / V;
      Pcd[a] = (kin[a] + f.virial_cons[a]) / V;
      P += Pd[a] / 3, Pc += Pcd[a] / 3;
    }
    if (cfg.series) {
      r.series.step.push_back(step);
      r.series.temperature.push_back(T), r.series.pressure.push_back(P), r.series.pressure_conservative.push_back(Pc);
      r.series.px.push_back(p[0]), r.series.py.push_back(p[1]), r.series.pz.push_back(p[2]);
    }
    if (RunStatus why = detail::check_state(cfg, step, T, f); !why.ok()) {
      r.status = std::move(why);
      break;
    }
    if (step > cfg.equilibrate) {
      if (tap_zeta) r.zeta.merge(f.zeta);  // mvv: the pair loop's ζ; shardlow: the sweep's
      smp.T.push_back(T), smp.P.push_back(P), smp.Pc.push_back(Pc);
      for (int a = 0; a < 3; ++a) smp.Pd[a].push_back(Pd[a]), smp.Pcd[a].push_back(Pcd[a]);
      const std::int64_t k = step - cfg.equilibrate - 1;  // 0 at the first production step
      if (cfg.observables) {
        if (k % cfg.sample_every == 0)
          vpdf.sample(s, int(std::min(blocks - 1, k / cfg.sample_every * blocks / vpdf_samples)));
        if (k % rdf_every == 0) rdf.sample(s, int(std::min(blocks - 1, k / rdf_every * blocks / rdf_samples)));
        if (k % msd_every == 0) msd.sample(s);
      }
    }
    if (hooks.observe) hooks.observe(step, s);
    if (hooks.progress && step % progress_every == 0) hooks.progress(step, cfg.steps);
  }
  const auto t_end = Clock::now();
  const double total = seconds(t_start, t_end);
  const double production_s = r.steps_done > cfg.equilibrate ? seconds(t_production, t_end) : 0.0;

  r.momentum_final = s.momentum();
  r.temperature = make_stat(smp.T);
  r.pressure = make_stat(smp.P);
  r.pressure_conservative = make_stat(smp.Pc);
  for (int a = 0; a < 3; ++a) r.pressure_diag[a] = make_stat(smp.Pd[a]), r.pressure_conservative_diag[a] = make_stat(smp.Pcd[a]);
  if (cfg.observables) {
    r.velocity_pdf = vpdf.finish(cfg.kT, r.temperature.n ? r.temperature.mean : cfg.kT);
    r.msd = msd.finish();
    r.rdf = rdf.finish(s);
  }
  Timings& t = r.timings;
  t.total_s = total;
  t.force_s = force_s;
  t.per_step_s = r.steps_done ? total / r.steps_done : 0;
  t.particle_steps_per_s = total > 0 ? double(n) * r.steps_done / total : 0;
  t.production_s = production_s;
  t.production_particle_steps_per_s =
      production_s > 0 ? double(n) * double(r.steps_done - cfg.equilibrate) / production_s : 0;
  t.random_numbers = numbers;
  t.zetas = zetas;
  t.ns_per_number = pair->ns_per_number();
  t.ns_per_zeta = pair->ns_per_zeta();
  // By difference against ζ = 0 on the final state (3 % of the run's time at most, beyond 5 pairs of force
  // evaluations), scaled by the force evaluations' share of the run: the RNG's share of a step.
  if (cfg.noise_override == NoiseOverride::off && r.steps_done > 0 && total > 0)
    t.rng_share_estimate = rng_share_by_difference(*pair, pair_force_config(cfg), kernel, s, std::uint64_t(cfg.steps) + 1, 0.03 * total) *
                           std::min(1.0, force_s / total);
  t.list_builds = pair->list_builds();
  t.threads = cfg.threads;
  return r;
}

}  // namespace dpdrng::dpd
