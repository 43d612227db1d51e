#include "dpdrng/dpd/water.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "dpdrng/dpd/observables.hpp"
#include "dpdrng/dpd/scene.hpp"
#include "dpdrng/dpd/water_integrator.hpp"
#include "dpdrng/dpd/shardlow.hpp"
#include "dpdrng/dpd/zeta_track.hpp"

namespace dpdrng::dpd {

namespace {

// The water scene's measurements: T and the pressures every production step, the velocity PDF, g(r) and the
// MSD on their own schedules, the series every step.
class WaterObserver : public SceneObserver {
 public:
  WaterObserver(const WaterConfig& cfg, RunResult& r, double L, const RunHooks& hooks)
      : cfg_(cfg), r_(r), hooks_(hooks),
        tap_zeta_(cfg.observables && cfg.noise_override == NoiseOverride::off && cfg.integrator != Integrator::pnhln),
        production_(cfg.steps - cfg.equilibrate),
        rdf_every_(cfg.rdf_every > 0 ? cfg.rdf_every : (n() <= 2000 ? cfg.sample_every : 20 * cfg.sample_every)),
        msd_every_(msd_interval(cfg, production_, max_frames())),
        vpdf_(cfg.vpdf_bins, cfg.vpdf_range * std::sqrt(cfg.kT), int(kStatBlocks)),
        vpdf_samples_(std::max<std::int64_t>(1, (production_ + cfg.sample_every - 1) / cfg.sample_every)),
        msd_(n(), msd_every_ * cfg.dt, max_frames()),
        rdf_(cfg.rdf_bins, std::min(cfg.rdf_rmax, L / 2), cfg.threads, int(kStatBlocks)),
        rdf_samples_(std::max<std::int64_t>(1, (production_ + rdf_every_ - 1) / rdf_every_)) {}

  bool tap_zeta() const { return tap_zeta_; }

  void every_step(const StepSums& x, const System&) override {
    P_ = 0, Pc_ = 0;
    for (int a = 0; a < 3; ++a) P_ += x.P[a] / 3, Pc_ += x.Pc[a] / 3;
    if (!cfg_.series) return;
    auto& sr = r_.series;
    sr.step.push_back(x.step);
    sr.temperature.push_back(x.T), sr.pressure.push_back(P_), sr.pressure_conservative.push_back(Pc_);
    sr.px.push_back(x.momentum[0]), sr.py.push_back(x.momentum[1]), sr.pz.push_back(x.momentum[2]);
  }

  void sample(const StepSums& x, const System& s) override {
    if (!x.production) return;
    if (tap_zeta_) r_.zeta.merge(x.forces->zeta);  // mvv: the pair loop's ζ; shardlow: the sweep's
    hand_over_in_range(x.step);
    T_.push_back(x.T), P_s_.push_back(P_), Pc_s_.push_back(Pc_);
    const double per_component = double(s.size()) - 1.0;  // 3N − 3 degrees of freedom, N − 1 per component
    for (int a = 0; a < 3; ++a) {
      Pd_[a].push_back(x.P[a]), Pcd_[a].push_back(x.Pc[a]);
      Td_[a].push_back(x.kin[a] / per_component);
    }
    if (x.forces->configurational)
      conf_force2_.push_back(x.forces->conf_force2), conf_laplacian_.push_back(x.forces->conf_laplacian);
    if (tap_zeta_) w2z2_.push_back(x.forces->zeta.w2z2), w2_.push_back(x.forces->zeta.w2);
    if (!cfg_.observables) return;
    // The velocity and g(r) samples fall into kStatBlocks consecutive blocks, for their jackknife errors.
    const auto blocks = static_cast<std::int64_t>(kStatBlocks);
    const std::int64_t k = x.step - cfg_.equilibrate - 1;  // 0 at the first production step
    if (k % cfg_.sample_every == 0)
      vpdf_.sample(s, int(std::min(blocks - 1, k / cfg_.sample_every * blocks / vpdf_samples_)));
    if (k % rdf_every_ == 0) rdf_.sample(s, int(std::min(blocks - 1, k / rdf_every_ * blocks / rdf_samples_)));
    if (k % msd_every_ == 0) msd_.sample(s);
  }

  void finish(const System& s) {
    r_.temperature = make_stat(T_);
    r_.pressure = make_stat(P_s_);
    r_.pressure_conservative = make_stat(Pc_s_);
    for (int a = 0; a < 3; ++a) {
      r_.pressure_diag[a] = make_stat(Pd_[a]), r_.pressure_conservative_diag[a] = make_stat(Pcd_[a]);
      r_.temperature_diag[a] = make_stat(Td_[a]);
    }
    r_.configurational_temperature = make_ratio_stat(conf_force2_, conf_laplacian_);
    r_.zeta_weighted_second_moment = make_ratio_stat(w2z2_, w2_);
    if (!cfg_.observables) return;
    r_.velocity_pdf = vpdf_.finish(cfg_.kT, r_.temperature.n ? r_.temperature.mean : cfg_.kT);
    r_.msd = msd_.finish();
    r_.rdf = rdf_.finish(s);
  }

 private:
  // The step's pairs inside r_c, recorded by its force evaluation, go out once the step has passed the guards,
  // like its ζ into the zeta sums.
  void hand_over_in_range(std::int64_t step) {
    InRangeTap& tap = r_.taps.in_range;
    if (tap.step != step) return;
    if (hooks_.in_range) hooks_.in_range(tap);
    tap.clear(), tap.step = -1;
  }

  std::size_t n() const { return static_cast<std::size_t>(cfg_.particles); }
  std::size_t max_frames() const { return std::max<std::size_t>(1, (std::size_t{1} << 24) / (3 * n())); }
  static int msd_interval(const WaterConfig& cfg, std::int64_t production, std::size_t max_frames) {
    const int every = cfg.msd_every > 0 ? cfg.msd_every : cfg.sample_every;
    return static_cast<int>(std::max<std::int64_t>(every, (production + max_frames - 1) / max_frames));
  }

  const WaterConfig& cfg_;
  RunResult& r_;
  const RunHooks& hooks_;
  const bool tap_zeta_;  // the ζ moments ride with the observables (a benchmark turns both off and pays for neither)
  const std::int64_t production_;
  const int rdf_every_, msd_every_;
  VelocityHistogram vpdf_;
  const std::int64_t vpdf_samples_;
  MsdRecorder msd_;
  RdfHistogram rdf_;
  const std::int64_t rdf_samples_;
  double P_ = 0, Pc_ = 0;  // this step's scalar pressures
  std::vector<double> T_, P_s_, Pc_s_, Pd_[3], Pcd_[3], Td_[3];
  std::vector<double> conf_force2_, conf_laplacian_, w2z2_, w2_;  // per production step
};

ZetaCorrelation zeta_correlation(const WaterConfig& cfg, bool tapped, const std::optional<ZetaTracker>& tracker) {
  ZetaCorrelation z;
  z.requested = cfg.zeta_lags > 0;
  if (!z.requested) return z;
  if (cfg.integrator == Integrator::pnhln) {
    z.not_applicable = "pnhln draws no pair noise (its thermostat's noise is one number a step)";
  } else if (!tapped) {
    z.not_applicable = "the run draws no ζ of its own (a benchmark baseline or observables off)";
  } else if (cfg.integrator == Integrator::shardlow) {
    z.not_applicable = "Shardlow's sweep draws the ζ outside the pair loop";
  } else {
    z = tracker->finish();
    z.requested = true;
  }
  return z;
}

void label(const WaterConfig& cfg, std::size_t n, double L, RunResult& r) {
  r.generator = cfg.generator.name == "mt19937" ? "mt19937" : rng::describe(cfg.generator);
  if (cfg.noise_override == NoiseOverride::none) r.generator = "none";
  // pnhln draws only its thermostat's noise, from the mt19937 stream, whatever the pair generator.
  const bool reference_only = cfg.integrator == Integrator::pnhln;
  if (reference_only) r.generator = "mt19937";
  if (cfg.noise_override == NoiseOverride::unhashed) r.generator = "unhashed";
  r.seeding = cfg.generator.name == "mt19937" || reference_only ? "stream" : std::string(rng::to_string(cfg.seeding));
  r.distribution = reference_only ? "gauss" : rng::to_string(cfg.distribution);
  r.feed = reference_only ? "halves" : rng::to_string(cfg.feed);
  r.pairs = to_string(cfg.pairs);
  r.integrator = cfg.integrator_name();
  r.particles = n;
  r.box_length = L;
}

}  // namespace

RunResult run_water(const WaterConfig& in, const RunHooks& hooks) {
  WaterConfig cfg = in;
  cfg.generator = rng::validated(in.generator);
  cfg.validate();

  const std::size_t n = static_cast<std::size_t>(cfg.particles);
  cfg.threads = team_threads(cfg.threads, n, cfg.team_beads);
  const double L = cfg.box_length();
  System s = make_fluid(n, Box{{L, L, L}}, cfg.kT, cfg.init_seed);
  const DpdKernel kernel = pair_force_kernel(cfg);
  auto pair = make_pair_forces(pair_force_config(cfg), kernel, n);
  WaterIntegrator vv(cfg);

  RunResult r;
  label(cfg, n, L, r);
  WaterObserver obs(cfg, r, L, hooks);

  std::vector<std::int64_t> raw_steps = cfg.taps.raw_steps;
  std::sort(raw_steps.begin(), raw_steps.end());
  raw_steps.erase(std::unique(raw_steps.begin(), raw_steps.end()), raw_steps.end());

  std::optional<ZetaTracker> tracker;
  if (cfg.zeta_lags > 0 && obs.tap_zeta()) tracker.emplace(cfg.zeta_lags, n, cfg.rc);
  std::int64_t current = 0, tracked = 0;
  ForceCounters counted;
  const ForceFn force = [&](System& sys, VelocityView v) {
    const auto t0 = SceneClock::now();
    const bool tap_raw = std::binary_search(raw_steps.begin(), raw_steps.end(), current);
    const bool production = current > cfg.equilibrate;
    const bool tap_series = !cfg.taps.pairs.empty() && production;
    // The configurational temperature on the sampled production steps (those of the velocity PDF).
    pair->sum_configurational(production && cfg.observables &&
                              (current - cfg.equilibrate - 1) % cfg.sample_every == 0);
    pair->tap_in_range(current >= cfg.taps.in_range_first && current <= cfg.taps.in_range_last);
    const ForceSums f = pair->compute(sys, v, static_cast<std::uint64_t>(current), tap_raw, tap_series,
                                      obs.tap_zeta() && production, r.taps);
    if (tap_raw && hooks.raw && !r.taps.raw.empty() && r.taps.raw.back().step == current &&
        hooks.raw(r.taps.raw.back()))
      r.taps.recycled.push_back(std::move(r.taps.raw.back())), r.taps.raw.pop_back();
    counted.seconds += seconds_between(t0, SceneClock::now());
    // Once per step, on the positions the forces just used (outside the force time).
    if (tracker && production && cfg.integrator != Integrator::shardlow && current > tracked)
      tracker->record(sys, *pair, static_cast<std::uint64_t>(current)), tracked = current;
    counted.numbers += f.numbers;
    counted.zetas += cfg.noise_override == NoiseOverride::none ? 0 : f.in_range;
    counted.pairs += f.in_range, counted.candidates += f.candidates;
    return f;
  };

  const SceneLimits limits{cfg.steps, cfg.equilibrate, cfg.kT, cfg.max_temperature, cfg.min_distance,
                           cfg.rc, cfg.threads};
  const SceneRun run = run_scene(
      s, limits, [&] { return vv.start(s, force); },
      [&](std::int64_t step) {
        current = step;
        return vv.step(s, force);
      },
      obs, hooks);
  pair->finish_taps(r.taps);
  r.taps.recycled.clear();
  put_scene_run(r, run);
  obs.finish(s);
  r.zeta_correlation = zeta_correlation(cfg, obs.tap_zeta(), tracker);
  r.timings = scene_timings(run, counted, limits, *pair, pair_force_config(cfg), kernel, s,
                            cfg.noise_override == NoiseOverride::off, cfg.threads);
  return r;
}

}  // namespace dpdrng::dpd
