// run_bilayer: the engine's pair loop (any noise) plus bonds and bending through the integrator's force
// callback, with the membrane's observables.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/bilayer_observables.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/pair_forces.hpp"
#include "run_check.hpp"

namespace dpdrng::dpd {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

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
  return w;
}

// detail::check_state, then the bonds.
RunStatus check(const BilayerConfig& cfg, std::int64_t step, double T, const ForceSums& f, double max_bond) {
  if (RunStatus s = detail::check_state(cfg, step, T, f); !s.ok()) return s;
  if (!(max_bond <= cfg.max_bond)) {
    std::ostringstream why;
    why << "bond stretched to " << max_bond << " > " << cfg.max_bond;
    return RunStatus::unstable(step, why.str());
  }
  return {};
}

double tension_of(const std::array<double, 3>& P, double Lz) { return Lz * (P[2] - 0.5 * (P[0] + P[1])); }

}  // namespace

BilayerResult run_bilayer(const BilayerConfig& in, const RunHooks& hooks) {
  BilayerConfig cfg = in;
  cfg.generator = rng::validated(in.generator);
  if (cfg.threads == 0) cfg.threads = omp_get_max_threads();
  BilayerState st = build_bilayer(cfg);  // validates
  System& s = st.system;
  const std::size_t n = s.size();
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
  double force_s = 0, bonded_s = 0;
  std::uint64_t numbers = 0, zetas = 0;
  BondedSums last_bonded;
  Taps no_taps;
  auto make_force = [&](PairForces& pair) {
    return ForceFn([&, p = &pair](System& sys, VelocityView v) {
      const auto t0 = Clock::now();
      ForceSums f = p->compute(sys, v, static_cast<std::uint64_t>(current), false, false, false, no_taps);
      const auto t1 = Clock::now();
      last_bonded = bonded.add(sys, st.topology);
      for (int a = 0; a < 3; ++a) {
        const double w = last_bonded.virial_bond[a] + last_bonded.virial_bend[a];
        f.virial[a] += w, f.virial_cons[a] += w;
      }
      const auto t2 = Clock::now();
      force_s += seconds(t0, t2), bonded_s += seconds(t1, t2);
      numbers += f.numbers;
      zetas += f.in_range;
      return f;
    });
  };
  const ForceFn force_warm = make_force(*pair_warm), force_main = make_force(*pair_main);

  const double V = s.box.volume(), Lz = s.box.L[2];
  const std::int64_t production = cfg.steps - cfg.equilibrate;
  const std::int64_t samples_total = std::max<std::int64_t>(1, (production + cfg.sample_every - 1) / cfg.sample_every);
  ProfileAccumulator prof(s.box, cfg.profile_bin, cfg.blocks);
  std::vector<double> T_s, Pd_s[3], P_s, ten_s, tenc_s, ten_nobond_s, ten_nobend_s, sep_s, order_s;
  std::array<double, kTailLength - 1> order_sum{};
  std::size_t order_n = 0;
  RunStatus disrupted;

  const auto t_start = Clock::now();
  ForceSums f = (cfg.warmup > 0 ? vv_warm : vv_main).start(s, cfg.warmup > 0 ? force_warm : force_main);
  const auto p0 = s.momentum();
  const std::int64_t progress_every = std::max<std::int64_t>(1, cfg.steps / 50);
  for (std::int64_t step = 1; step <= cfg.steps; ++step) {
    current = step;
    // Step k moves with the Δt of its phase; the first step at dt reuses forces from dt_warmup's loop,
    // which differ only in the random force's amplitude of one evaluation.
    f = step <= cfg.warmup ? vv_warm.step(s, force_warm) : vv_main.step(s, force_main);
    r.steps_done = step;
    double kin[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i)
      kin[0] += s.vx[i] * s.vx[i], kin[1] += s.vy[i] * s.vy[i], kin[2] += s.vz[i] * s.vz[i];
    const double T = (kin[0] + kin[1] + kin[2]) / (3.0 * n - 3.0);
    const auto p = s.momentum();
    r.momentum_drift = std::max(r.momentum_drift, std::hypot(p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]) / n);
    if (RunStatus why = check(cfg, step, T, f, last_bonded.max_bond); !why.ok()) {
      r.status = std::move(why);
      break;
    }

    const bool sampled = step % cfg.sample_every == 0 || step == cfg.steps;
    const bool prod = step > cfg.equilibrate;
    std::array<double, 3> P{}, Pc{}, Pnb{}, Pne{};
    for (int a = 0; a < 3; ++a) {
      P[a] = (kin[a] + f.virial[a]) / V;
      Pc[a] = (kin[a] + f.virial_cons[a]) / V;
      Pnb[a] = P[a] - last_bonded.virial_bond[a] / V;
      Pne[a] = P[a] - last_bonded.virial_bend[a] / V;
    }
    if (prod) {
      T_s.push_back(T);
      for (int a = 0; a < 3; ++a) Pd_s[a].push_back(P[a]);
      P_s.push_back((P[0] + P[1] + P[2]) / 3.0);
      ten_s.push_back(tension_of(P, Lz));
      tenc_s.push_back(tension_of(Pc, Lz));
      ten_nobond_s.push_back(tension_of(Pnb, Lz));
      ten_nobend_s.push_back(tension_of(Pne, Lz));
    }
    if (sampled) {
      const double zmid = bilayer_midplane(s, st.lipids);
      const int out = lipids_out(s, st.lipids, zmid, cfg.escape_distance);
      r.lipids_out_max = std::max(r.lipids_out_max, out);
      if (out > 0 && disrupted.ok())
        disrupted = RunStatus::disrupted(step, std::to_string(out) + " lipid(s) left the bilayer");
      const TailOrder order = tail_order(s, st.lipids);
      if (prod) {
        const std::int64_t k = (step - cfg.equilibrate - 1) / cfg.sample_every;
        prof.sample(s, zmid, static_cast<int>(std::min<std::int64_t>(cfg.blocks - 1, k * cfg.blocks / samples_total)));
        sep_s.push_back(head_separation(s, st.lipids, zmid));
        order_s.push_back(order.mean);
        for (std::size_t b = 0; b < order_sum.size(); ++b) order_sum[b] += order.by_bond[b];
        ++order_n;
      }
      if (cfg.series) {
        r.series.step.push_back(step);
        r.series.temperature.push_back(T);
        r.series.pxx.push_back(P[0]), r.series.pyy.push_back(P[1]), r.series.pzz.push_back(P[2]);
        r.series.tension.push_back(tension_of(P, Lz));
        r.series.tail_order.push_back(order.mean);
        r.series.lipids_out.push_back(out);
      }
    }
    if (hooks.progress && step % progress_every == 0) hooks.progress(step, cfg.steps);
  }
  if (r.ok()) r.status = disrupted;
  const double total = seconds(t_start, Clock::now());

  r.momentum_final = s.momentum();
  r.temperature = make_stat(T_s);
  for (int a = 0; a < 3; ++a) r.pressure_diag[a] = make_stat(Pd_s[a]);
  r.pressure = make_stat(P_s);
  r.tension = make_stat(ten_s);
  r.tension_conservative = make_stat(tenc_s);
  r.tension_without_bond_virial = make_stat(ten_nobond_s);
  r.tension_without_bend_virial = make_stat(ten_nobend_s);
  r.thickness = prof.thickness();
  r.head_separation = make_stat(sep_s);
  r.tail_order = make_stat(order_s);
  r.order_by_bond.assign(order_sum.begin(), order_sum.end());
  if (order_n > 0)
    for (auto& v : r.order_by_bond) v /= double(order_n);
  r.profile = prof.finish();

  Timings& t = r.timings;
  t.total_s = total;
  t.force_s = force_s;
  t.per_step_s = r.steps_done ? total / r.steps_done : 0;
  t.particle_steps_per_s = total > 0 ? double(n) * r.steps_done / total : 0;
  t.random_numbers = numbers;
  t.zetas = zetas;
  t.ns_per_number = pair_main->ns_per_number();
  t.ns_per_zeta = pair_main->ns_per_zeta();
  // As the water scene does: by difference against ζ = 0 on the final state (3 % of the run's time at most),
  // scaled by the pair forces' share of the run (the bonded forces and observables are the rest).
  if (r.steps_done > 0 && total > 0)
    t.rng_share_estimate = rng_share_by_difference(*pair_main, main_config, main_kernel, s,
                                                   std::uint64_t(cfg.steps) + 1, 0.03 * total) *
                           std::min(1.0, force_s / total);
  t.list_builds = pair_warm->list_builds() + pair_main->list_builds();
  t.threads = cfg.threads;
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
  put_value_sem(j, "membrane_tension", r.tension);
  j["membrane_tension_convention"] = "L_z [P_zz - (P_xx + P_yy)/2], positive = stretched";
  put_value_sem(j, "membrane_tension_conservative", r.tension_conservative);
  j["membrane_tension_without_bond_virial"] = r.tension_without_bond_virial.mean;
  j["membrane_tension_without_bend_virial"] = r.tension_without_bend_virial.mean;
  put_value_sem(j, "bilayer_thickness", r.thickness);
  put_value_sem(j, "head_separation", r.head_separation);
  put_value_sem(j, "tail_order", r.tail_order);
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
