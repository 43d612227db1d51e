// run_bilayer: the engine's pair loop (any noise) plus bonds and bending through the integrator's force
// callback, with the membrane's observables.

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/bilayer_observables.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/scene.hpp"
#include "dpdrng/dpd/zeta_track.hpp"

namespace dpdrng::dpd {

namespace {

// The engine's pair-forces factory takes a WaterConfig; only its noise and pair-search fields matter here.
WaterConfig pair_config(const BilayerConfig& c, std::uint64_t seed) {
  WaterConfig w;
  w.rc = c.rc;
  w.kT = c.kT;
  w.gamma = c.gamma;
  w.pairs = c.pairs;
  w.generator = c.generator;
  w.seeding = c.seeding;
  w.distribution = c.distribution;
  w.feed = c.feed;
  w.seed = seed;
  w.threads = c.threads;
  w.team_beads = c.team_beads;
  return w;
}

double tension_of(const std::array<double, 3>& P, double Lz) { return Lz * (P[2] - 0.5 * (P[0] + P[1])); }

// The membrane's measurements: T, the pressure diagonal and the tensions every production step; the integrity
// check, the profiles, the head separation and the tail order every sample_every steps (and at the last).
class BilayerObserver : public SceneObserver {
 public:
  BilayerObserver(const BilayerConfig& cfg, const BilayerState& st, const BondedSums& bonded, BilayerResult& r)
      : cfg_(cfg), st_(st), bonded_(bonded), r_(r), V_(st.system.box.volume()), Lz_(st.system.box.L[2]),
        samples_total_(std::max<std::int64_t>(1, (cfg.steps - cfg.equilibrate + cfg.sample_every - 1) / cfg.sample_every)),
        prof_(st.system.box, cfg.profile_bin, cfg.blocks) {}

  RunStatus check(const StepSums& x) override {
    if (bonded_.max_bond <= cfg_.max_bond) return {};
    std::ostringstream why;
    why << "bond stretched to " << bonded_.max_bond << " > " << cfg_.max_bond;
    return RunStatus::unstable(x.step, why.str());
  }

  void sample(const StepSums& x, const System& s) override {
    const bool sampled = x.step % cfg_.sample_every == 0 || x.step == cfg_.steps;
    const std::array<double, 3>& P = x.P;
    if (x.production) {
      std::array<double, 3> Pnb{}, Pne{};
      for (int a = 0; a < 3; ++a) {
        Pnb[a] = P[a] - bonded_.virial_bond[a] / V_;
        Pne[a] = P[a] - bonded_.virial_bend[a] / V_;
      }
      T_s_.push_back(x.T);
      const double per_component = double(s.size()) - 1.0;  // N − 1 of the 3N − 3 degrees of freedom
      for (int a = 0; a < 3; ++a) Pd_s_[a].push_back(P[a]), Td_s_[a].push_back(x.kin[a] / per_component);
      aniso_s_.push_back(P[0] - P[1]);
      w2z2_s_.push_back(x.forces->zeta.w2z2), w2_s_.push_back(x.forces->zeta.w2);
      P_s_.push_back((P[0] + P[1] + P[2]) / 3.0);
      ten_s_.push_back(tension_of(P, Lz_));
      tenc_s_.push_back(tension_of(x.Pc, Lz_));
      ten_nobond_s_.push_back(tension_of(Pnb, Lz_));
      ten_nobend_s_.push_back(tension_of(Pne, Lz_));
    }
    if (sampled) structure(x, s);
  }

  void finish(const SceneRun& run) {
    if (run.status.ok()) r_.status = disrupted_;
    r_.temperature = make_stat(T_s_);
    for (int a = 0; a < 3; ++a) r_.pressure_diag[a] = make_stat(Pd_s_[a]), r_.temperature_diag[a] = make_stat(Td_s_[a]);
    r_.pressure_anisotropy = make_stat(aniso_s_);
    r_.zeta_weighted_second_moment = make_ratio_stat(w2z2_s_, w2_s_);
    r_.pressure = make_stat(P_s_);
    r_.tension = make_stat(ten_s_);
    r_.tension_conservative = make_stat(tenc_s_);
    r_.tension_without_bond_virial = make_stat(ten_nobond_s_);
    r_.tension_without_bend_virial = make_stat(ten_nobend_s_);
    r_.thickness = prof_.thickness();
    r_.head_separation = make_stat(sep_s_);
    r_.tail_order = make_stat(order_s_);
    r_.nematic_order = make_stat(nematic_s_);
    r_.order_by_bond.assign(order_sum_.begin(), order_sum_.end());
    if (order_n_ > 0)
      for (auto& v : r_.order_by_bond) v /= double(order_n_);
    r_.profile = prof_.finish();
  }

 private:
  void structure(const StepSums& x, const System& s) {
    const std::size_t lipids = st_.lipids;
    const double zmid = bilayer_midplane(s, lipids);
    const int out = lipids_out(s, lipids, zmid, cfg_.escape_distance);
    r_.lipids_out_max = std::max(r_.lipids_out_max, out);
    if (out > 0 && disrupted_.ok())
      disrupted_ = RunStatus::disrupted(x.step, std::to_string(out) + " lipid(s) left the bilayer");
    const TailOrder order = tail_order(s, lipids);
    if (x.production) {
      const std::int64_t k = (x.step - cfg_.equilibrate - 1) / cfg_.sample_every;
      prof_.sample(s, zmid, static_cast<int>(std::min<std::int64_t>(cfg_.blocks - 1, k * cfg_.blocks / samples_total_)));
      sep_s_.push_back(head_separation(s, lipids, zmid));
      order_s_.push_back(order.mean);
      nematic_s_.push_back(nematic_order(lipid_axes(s, lipids)));
      for (std::size_t b = 0; b < order_sum_.size(); ++b) order_sum_[b] += order.by_bond[b];
      ++order_n_;
    }
    if (cfg_.series) {
      auto& sr = r_.series;
      sr.step.push_back(x.step);
      sr.temperature.push_back(x.T);
      sr.pxx.push_back(x.P[0]), sr.pyy.push_back(x.P[1]), sr.pzz.push_back(x.P[2]);
      sr.tension.push_back(tension_of(x.P, Lz_));
      sr.tail_order.push_back(order.mean);
      sr.lipids_out.push_back(out);
    }
  }

  const BilayerConfig& cfg_;
  const BilayerState& st_;
  const BondedSums& bonded_;  // the last force evaluation's bonded sums
  BilayerResult& r_;
  const double V_, Lz_;
  const std::int64_t samples_total_;
  ProfileAccumulator prof_;
  std::vector<double> Td_s_[3], w2z2_s_, w2_s_, aniso_s_;
  std::vector<double> T_s_, Pd_s_[3], P_s_, ten_s_, tenc_s_, ten_nobond_s_, ten_nobend_s_, sep_s_, order_s_, nematic_s_;
  std::array<double, kTailLength - 1> order_sum_{};
  std::size_t order_n_ = 0;
  RunStatus disrupted_;
};

}  // namespace

BilayerResult run_bilayer(const BilayerConfig& in, const RunHooks& hooks) {
  BilayerConfig cfg = in;
  cfg.generator = rng::validated(in.generator);
  BilayerState st = build_bilayer(cfg);  // validates
  System& s = st.system;
  const std::size_t n = s.size();
  cfg.threads = team_threads(cfg.threads, n, cfg.team_beads);
  const BondedForces bonded{cfg.bond, cfg.bend};

  // The random force's amplitude σ/√Δt is part of the pair kernel, so each Δt gets its own pair loop. Keyed
  // hashes are functions of the pair (and step), so two loops see one noise field; the mt19937 stream of the
  // second phase is seeded differently so that it does not replay the warm-up's numbers.
  const bool is_mt = cfg.generator.name == "mt19937";
  auto pair_warm = make_pair_forces(pair_config(cfg, cfg.seed), bilayer_kernel(cfg, cfg.dt_warmup), n);
  const WaterConfig main_config = pair_config(cfg, is_mt ? cfg.seed ^ 0xD1B54A32D192ED03ull : cfg.seed);
  const DpdKernel main_kernel = bilayer_kernel(cfg, cfg.dt);
  auto pair_main = make_pair_forces(main_config, main_kernel, n);
  ModifiedVelocityVerlet vv_warm(cfg.dt_warmup, cfg.lambda, cfg.threads), vv_main(cfg.dt, cfg.lambda, cfg.threads);

  BilayerResult r;
  r.generator = is_mt ? "mt19937" : rng::describe(cfg.generator);
  r.seeding = is_mt ? "stream" : std::string(rng::to_string(cfg.seeding));
  r.distribution = rng::to_string(cfg.distribution);
  r.feed = rng::to_string(cfg.feed);
  r.pairs = to_string(cfg.pairs);
  r.particles = n;
  r.lipids = st.lipids;
  r.box = cfg.box;

  std::int64_t current = 0;
  double bonded_s = 0;
  ForceCounters counted;
  BondedSums last_bonded;
  Taps no_taps;
  std::optional<ZetaTracker> tracker;
  if (cfg.zeta_lags > 0) tracker.emplace(cfg.zeta_lags, n, cfg.rc);
  std::int64_t tracked = 0;
  auto make_force = [&](PairForces& pair) {
    return ForceFn([&, p = &pair](System& sys, VelocityView v) {
      const auto t0 = SceneClock::now();
      // The production steps' ζ sums, for the noise's w_R²-weighted power.
      ForceSums f = p->compute(sys, v, static_cast<std::uint64_t>(current), false, false, current > cfg.equilibrate,
                               no_taps);
      const auto t1 = SceneClock::now();
      last_bonded = bonded.add(sys, st.topology);
      for (int a = 0; a < 3; ++a) {
        const double w = last_bonded.virial_bond[a] + last_bonded.virial_bend[a];
        f.virial[a] += w, f.virial_cons[a] += w;
      }
      const auto t2 = SceneClock::now();
      counted.seconds += seconds_between(t0, t2), bonded_s += seconds_between(t1, t2);
      counted.numbers += f.numbers;
      counted.zetas += f.in_range;
      counted.pairs += f.in_range, counted.candidates += f.candidates;
      // Once per production step, on the positions the pair forces just used.
      if (tracker && current > cfg.equilibrate && current > tracked)
        tracker->record(sys, *p, static_cast<std::uint64_t>(current)), tracked = current;
      return f;
    });
  };
  const ForceFn force_warm = make_force(*pair_warm), force_main = make_force(*pair_main);

  BilayerObserver obs(cfg, st, last_bonded, r);
  const SceneLimits limits{cfg.steps, cfg.equilibrate, cfg.kT, cfg.max_temperature, cfg.min_distance,
                           cfg.rc, cfg.threads};
  // Step k moves with the Δt of its phase; the first step at dt reuses forces from dt_warmup's loop, which
  // differ only in the random force's amplitude of one evaluation.
  const SceneRun run = run_scene(
      s, limits,
      [&] { return (cfg.warmup > 0 ? vv_warm : vv_main).start(s, cfg.warmup > 0 ? force_warm : force_main); },
      [&](std::int64_t step) {
        current = step;
        return step <= cfg.warmup ? vv_warm.step(s, force_warm) : vv_main.step(s, force_main);
      },
      obs, hooks);
  put_scene_run(r, run);
  obs.finish(run);
  if (tracker) r.zeta_correlation = tracker->finish();
  r.zeta_correlation.requested = cfg.zeta_lags > 0;

  // As the water scene does, scaled by the pair forces' share of the run (the bonded forces and observables are
  // the rest).
  r.timings = scene_timings(run, counted, limits, *pair_main, main_config, main_kernel, s, true, cfg.threads);
  r.timings.list_builds = pair_warm->list_builds() + pair_main->list_builds();
  r.bonded_s = bonded_s;
  return r;
}

nlohmann::json to_json(const BilayerResult& r, bool arrays) {
  nlohmann::json j;
  j["scene"] = "bilayer";
  put_run_labels(j, r);
  j["lipids"] = r.lipids;
  j["box"] = r.box;
  put_mean_sem(j, "temperature", r.temperature);
  put_mean_sem(j, "pressure", r.pressure);
  put_mean_sem(j, "pressure_xx", r.pressure_diag[0]);
  put_mean_sem(j, "pressure_yy", r.pressure_diag[1]);
  put_mean_sem(j, "pressure_zz", r.pressure_diag[2]);
  put_mean_sem(j, "pressure_xx_minus_yy", r.pressure_anisotropy);
  put_value_sem(j, "membrane_tension", r.tension);
  j["membrane_tension_convention"] = "L_z [P_zz - (P_xx + P_yy)/2], positive = stretched";
  put_value_sem(j, "membrane_tension_conservative", r.tension_conservative);
  j["membrane_tension_without_bond_virial"] = r.tension_without_bond_virial.mean;
  j["membrane_tension_without_bend_virial"] = r.tension_without_bend_virial.mean;
  put_value_sem(j, "bilayer_thickness", r.thickness);
  put_value_sem(j, "head_separation", r.head_separation);
  put_value_sem(j, "tail_order", r.tail_order);
  put_value_sem(j, "nematic_order", r.nematic_order);
  j["lipids_out_max"] = r.lipids_out_max;
  j["momentum_drift_per_bead"] = r.momentum_drift;
  j["momentum_final"] = r.momentum_final;
  j["temperature"] = to_json(r.temperature);
  j["tension"] = to_json(r.tension);
  j["thickness"] = to_json(r.thickness);
  j["tail_order_stat"] = to_json(r.tail_order);
  for (int a = 0; a < 3; ++a) j["pressure_diag"].push_back(to_json(r.pressure_diag[a]));
  j["timings"] = timings_json(r.timings);
  j["timings"]["bonded_s"] = r.bonded_s;
  if (arrays) {
    j["order_by_bond"] = r.order_by_bond;
    j["profile"] = {{"z", r.profile.z}, {"head", r.profile.head}, {"tail", r.profile.tail},
                    {"water", r.profile.water}, {"samples", r.profile.samples}};
  }
  if (blew_up(r.status)) null_observables(j, {"scene", "lipids", "box", "membrane_tension_convention"});
  return j;
}

}  // namespace dpdrng::dpd
