#include "dpdrng/study/decomposition_run.hpp"

#include <algorithm>
#include <cmath>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/observables.hpp"
#include "dpdrng/dpd/scene.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/seeding_repair.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/ttest.hpp"

namespace dpdrng::study {

using namespace dpdrng::dpd;

namespace {


// The randomness taps of one run: every pair's word 0 at sampled steps, and the tapped pairs' series.
struct Tapper {
  const DecompConfig& cfg;
  const DecomposedForces& forces;
  std::vector<double> step_words;                // sampled steps × N(N−1)/2, step-major
  std::size_t sampled_steps = 0;
  std::vector<std::vector<double>> series;       // per tapped pair
  std::vector<std::uint64_t> scratch;
  double duplicates = 0;

  void sample_step(const System& s, std::uint64_t step) {
    const std::uint32_t n = static_cast<std::uint32_t>(s.size());
    scratch.clear();
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const std::uint64_t w = forces.raw(s, i, j, step)[0];
        scratch.push_back(w);
        step_words.push_back(rng::to_unit(w));
      }
    ++sampled_steps;
    std::sort(scratch.begin(), scratch.end());
    std::size_t dup = 0;
    for (std::size_t k = 0; k < scratch.size(); ++k)
      if ((k > 0 && scratch[k] == scratch[k - 1]) || (k + 1 < scratch.size() && scratch[k] == scratch[k + 1])) ++dup;
    duplicates += double(dup);
  }
  void sample_series(const System& s, std::uint64_t step) {
    series.resize(cfg.ttest_pairs);
    for (int p = 0; p < cfg.ttest_pairs; ++p)
      series[p].push_back(rng::to_unit(forces.raw(s, std::uint32_t(p), std::uint32_t(p + 1), step)[0]));
  }

  RandomnessCost finish() const {
    RandomnessCost c;
    const std::size_t pairs = sampled_steps ? step_words.size() / sampled_steps : 0;
    for (std::size_t t = 0; t < sampled_steps; ++t) {
      const auto r = stats::chi2_uniform(std::span(step_words).subspan(t * pairs, pairs), {0, cfg.alpha});
      if (r.verdict == stats::Verdict::not_applicable) continue;
      ++c.chi2_tests;
      c.chi2_pass += r.verdict == stats::Verdict::pass;
      c.chi2_min_p = c.chi2_tests == 1 ? r.p_value : std::min(c.chi2_min_p, r.p_value);
    }
    for (const auto& x : series) {
      const auto r = stats::lag1_ttest(x, cfg.alpha);
      if (r.verdict == stats::Verdict::not_applicable) continue;
      ++c.lag1_tests;
      c.lag1_pass += r.verdict == stats::Verdict::pass;
      c.lag1_max_abs_r = c.lag1_tests == 1 ? std::fabs(r.r) : std::max(c.lag1_max_abs_r, std::fabs(r.r));
    }
    if (sampled_steps) {
      const auto m = stats::NoiseMatrix::step_major(step_words, pairs, sampled_steps);
      const auto r = stats::cross_pair_correlation(m, 1, cfg.alpha);
      c.cross_pair_r = r.r, c.cross_pair_p = r.p_value;
      c.cross_pair_verdict = std::string(stats::to_string(r.verdict));
      c.duplicates_per_step = duplicates / double(sampled_steps);
    }
    return c;
  }
};

// T and P from the total kinetic energy on every production step, the MSD, and the reference run's noise taps.
class DecompObserver : public SceneObserver {
 public:
  DecompObserver(const DecompConfig& cfg, const System& s, Tapper* tap)
      : cfg_(cfg), tap_(tap), n_(s.size()), V_(s.box.volume()), msd_every_(msd_interval(cfg.water, n_)),
        msd_(n_, msd_every_ * cfg.water.dt, max_frames(n_)) {}

  void sample(const StepSums& x, const System& s) override {
    if (!x.production) return;
    const ForceSums& f = *x.forces;
    const std::int64_t k = x.step - cfg_.water.equilibrate - 1;
    const double kin = s.kinetic_twice();
    T_.push_back(kin / (3.0 * n_ - 3.0));
    P_.push_back((kin + f.virial[0] + f.virial[1] + f.virial[2]) / (3.0 * V_));
    if (k % msd_every_ == 0) msd_.sample(s);
    if (!tap_) return;
    const auto step = static_cast<std::uint64_t>(x.step);
    if (cfg_.chi2_every > 0 && k % cfg_.chi2_every == 0) tap_->sample_step(s, step);
    if (cfg_.ttest_pairs > 0) tap_->sample_series(s, step);
  }

  void finish(DecompRun& r) const {
    r.temperature = make_stat(T_);
    r.pressure = make_stat(P_);
    const Msd m = msd_.finish();
    r.diffusion = m.diffusion, r.diffusion_sem = m.diffusion_sem;
  }

 private:
  static std::size_t max_frames(std::size_t n) { return std::max<std::size_t>(1, (std::size_t{1} << 24) / (3 * n)); }
  static int msd_interval(const WaterConfig& w, std::size_t n) {
    const std::int64_t production = w.steps - w.equilibrate;
    return static_cast<int>(std::max<std::int64_t>(w.msd_every > 0 ? w.msd_every : w.sample_every,
                                                   (production + max_frames(n) - 1) / max_frames(n)));
  }

  const DecompConfig& cfg_;
  Tapper* tap_;
  const std::size_t n_;
  const double V_;
  const int msd_every_;
  MsdRecorder msd_;
  std::vector<double> T_, P_;
};

DecompRun run_one(const DecompConfig& cfg, const DomainGrid& grid, BoundaryStats* first, Tapper* tap) {
  const WaterConfig& w = cfg.water;
  const std::size_t n = static_cast<std::size_t>(w.particles);
  const double L = w.box_length();
  System s = make_fluid(n, Box{{L, L, L}}, w.kT, w.init_seed);
  const DpdKernel kernel = make_kernel(w.a, w.rc, w.gamma, w.kT, w.dt);
  auto forces = make_decomposed_forces(cfg.noise, kernel, grid);
  ModifiedVelocityVerlet vv(w.dt, w.lambda, 1);

  DecompRun r;
  std::uint64_t current = 0;
  const ForceFn force = [&](System& sys, VelocityView v) {
    if (current == 0 && first) {
      BoundaryStats snap;
      ForceSums f = forces->compute(sys, v, current, &snap, nullptr);
      r.boundary.merge(snap);
      *first = snap;
      return f;
    }
    return forces->compute(sys, v, current, &r.boundary, nullptr);
  };
  Tapper* t = tap;
  if (t) t->step_words.reserve(std::size_t(w.steps / std::max(1, cfg.chi2_every) + 1) * n * (n - 1) / 2);

  DecompObserver obs(cfg, s, t);
  const SceneLimits limits{w.steps, w.equilibrate, w.kT, w.max_temperature, w.min_distance};
  const SceneRun run = run_scene(
      s, limits, [&] { return vv.start(s, force); },
      [&](std::int64_t step) {
        current = static_cast<std::uint64_t>(step);
        return vv.step(s, force);
      },
      obs);
  r.status = run.status;
  r.steps_done = run.steps_done;
  r.momentum_drift = run.momentum_drift;
  r.seconds = run.total_s;
  obs.finish(r);
  const auto p0 = run.momentum_initial;
  const auto pe = s.momentum();
  r.momentum_final = std::hypot(pe[0] - p0[0], pe[1] - p0[1], pe[2] - p0[2]) / n;
  const double kin = s.kinetic_twice();
  r.com_kinetic_share = kin > 0 ? (pe[0] * pe[0] + pe[1] * pe[1] + pe[2] * pe[2]) / double(n) / kin : 0;
  return r;
}

}  // namespace

DecompResult run_decomposition(const DecompConfig& in) {
  DecompConfig cfg = in;
  cfg.noise.generator = rng::validated(in.noise.generator);
  cfg.validate();
  DecompResult out;
  out.generator = rng::describe(cfg.noise.generator);
  out.seeding = to_string(cfg.noise.seeding);
  out.distribution = std::string(rng::to_string(cfg.noise.distribution));
  out.feed = std::string(rng::to_string(cfg.noise.feed));
  out.domains = to_string(cfg.domains);
  out.particles = static_cast<std::size_t>(cfg.water.particles);
  out.box_length = cfg.water.box_length();

  out.decomposed = run_one(cfg, cfg.domains, &out.snapshot, nullptr);
  if (cfg.reference) {
    const WaterConfig& w = cfg.water;
    const DpdKernel kernel = make_kernel(w.a, w.rc, w.gamma, w.kT, w.dt);
    const DomainGrid whole{};
    auto forces = make_decomposed_forces(cfg.noise, kernel, whole);
    Tapper tap{cfg, *forces, {}, 0, {}, {}, 0};
    out.reference = run_one(cfg, whole, nullptr, &tap);
    out.randomness = tap.finish();
    out.has_reference = true;
  }
  return out;
}

nlohmann::json to_json(const BoundaryStats& b) {
  return {{"evaluations", b.evaluations},
          {"pairs_in_range", b.in_range},
          {"boundary_pairs", b.boundary},
          {"shifted_pairs", b.shifted},
          {"separation_mismatches", b.separation_mismatch},
          {"range_mismatches", b.range_mismatch},
          {"zeta_mismatches", b.zeta_mismatch},
          {"mismatch_fraction", b.mismatch_fraction()},
          {"shifted_mismatch_fraction", b.shifted ? double(b.zeta_mismatch + b.range_mismatch) / b.shifted : 0.0},
          {"zeta_diff_mean", b.zeta_diff_mean()},
          {"zeta_diff_rms", b.zeta_diff_rms()},
          {"zeta_diff_max", b.zeta_diff_max},
          {"force_mismatch_max", b.force_mismatch_max},
          {"net_force_per_bead_max", b.net_force_max},
          {"net_force_per_bead_rms", b.net_force_rms()},
          {"grid_straddle_expected", b.grid_straddle_expected}};
}

namespace {
nlohmann::json stat_json(const Stat& s) { return {{"mean", s.mean}, {"std", s.std}, {"sem", s.sem}, {"n", s.n}}; }

nlohmann::json run_json(const DecompRun& r) {
  return {{"status", r.status.text()},
          {"steps_done", r.steps_done},
          {"temperature", stat_json(r.temperature)},
          {"pressure", stat_json(r.pressure)},
          {"diffusion", r.diffusion},
          {"diffusion_sem", r.diffusion_sem},
          {"momentum_drift_per_bead", r.momentum_drift},
          {"momentum_final_per_bead", r.momentum_final},
          {"com_kinetic_share", r.com_kinetic_share},
          {"boundary", to_json(r.boundary)},
          {"seconds", r.seconds}};
}
}  // namespace

nlohmann::json to_json(const DecompResult& r) {
  nlohmann::json j = {{"generator", r.generator},     {"seeding", r.seeding},
                      {"distribution", r.distribution}, {"feed", r.feed}, {"domains", r.domains},
                      {"particles", r.particles},       {"box_length", r.box_length},
                      {"snapshot", to_json(r.snapshot)}, {"decomposed", run_json(r.decomposed)}};
  if (r.has_reference) {
    j["reference"] = run_json(r.reference);
    const auto& c = r.randomness;
    j["randomness"] = {{"chi2_tests", c.chi2_tests},
                       {"chi2_pass_fraction", c.chi2_pass_fraction()},
                       {"chi2_min_p", c.chi2_min_p},
                       {"lag1_tests", c.lag1_tests},
                       {"lag1_pass_fraction", c.lag1_pass_fraction()},
                       {"lag1_max_abs_r", c.lag1_max_abs_r},
                       {"cross_pair_r", c.cross_pair_r},
                       {"cross_pair_p", c.cross_pair_p},
                       {"cross_pair_verdict", c.cross_pair_verdict},
                       {"duplicates_per_step", c.duplicates_per_step}};
  }
  return j;
}

}  // namespace dpdrng::study
