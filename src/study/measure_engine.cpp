// The engine side of a cell: which steps and pairs to tap, the WaterConfig, and the RunResult's observables.
#include <algorithm>
#include <cstdio>
#include <set>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/machine.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/stats/moments.hpp"
#include "dpdrng/study/measure.hpp"
#include "dpdrng/study/observables.hpp"
#include "measure_common.hpp"

namespace dpdrng::study {

TapPlan plan_taps(const Cell& cell, const StudyConfig& config, int words_per_pair) {
  const auto& s = config.scene;
  const auto& t = config.tests;
  const std::int64_t steps = s.steps_at(cell.dt), equilibrate = s.equilibrate_at(cell.dt);
  const std::int64_t production = steps - equilibrate;
  TapPlan plan;
  // Shardlow's sweep is not tapped and pnhln draws no pair noise: their cells measure physics only.
  if (!integrator_of(cell.integrator, s).tapped()) return plan;
  const std::int64_t m = std::min<std::int64_t>(t.chi2_steps, production);
  for (std::int64_t k = 0; k < m; ++k) plan.chi2_steps.push_back(equilibrate + 1 + k * production / m);

  if (cell.nist) {
    // Every pair draws every step only in `all` mode; in `cells` mode the count varies, so tap generously.
    const std::int64_t pairs = std::int64_t(s.particles) * (s.particles - 1) / 2;
    const std::int64_t per_step = (s.pairs == dpd::PairMode::all ? pairs : pairs / 8) * words_per_pair;
    const std::int64_t words = (t.nist_sequences * t.nist_bits + 63) / 64;
    const std::int64_t need = std::min<std::int64_t>((words + per_step - 1) / per_step, production);
    for (std::int64_t k = steps - need + 1; k <= steps; ++k) plan.nist_steps.push_back(k);
  }

  // Couples (i, j), (i, j+1): neighbouring pair ids, the inputs a weak hash is most likely to correlate.
  const auto n = static_cast<std::uint32_t>(s.particles);
  const std::int64_t couples = (t.ttest_pairs + 1) / 2;
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (std::int64_t c = 0; c < couples && n >= 3; ++c) {
    const auto i = static_cast<std::uint32_t>(c * (n - 2) / couples);
    const auto j = i + 1 + static_cast<std::uint32_t>((c * 37) % (n - i - 2 > 0 ? n - i - 2 : 1));
    for (auto p : {std::pair{i, j}, std::pair{i, j + 1}})
      if (std::int64_t(plan.pairs.size()) < t.ttest_pairs && p.second < n && seen.insert(p).second)
        plan.pairs.push_back(p);
  }
  return plan;
}

dpd::WaterConfig engine_config(const Cell& cell, const StudyConfig& config, int threads, const TapPlan& plan) {
  const auto& s = config.scene;
  dpd::WaterConfig w;
  detail::set_run(w, cell, s, threads);
  const IntegratorSpec integrator = integrator_of(cell.integrator, s);
  w.integrator = integrator.kind;
  w.lambda = integrator.lambda;
  w.scmvv_iterations = integrator.iterations;
  w.pnhln_mu = integrator.mu;
  w.density = s.density;
  w.a = s.a;
  std::set<std::int64_t> raw(plan.chi2_steps.begin(), plan.chi2_steps.end());
  raw.insert(plan.nist_steps.begin(), plan.nist_steps.end());
  w.taps.raw_steps.assign(raw.begin(), raw.end());
  w.taps.pairs = plan.pairs;
  w.zeta_lags = kStudyZetaLags;
  return w;
}

void validate_scene(const StudyConfig& config) {
  const auto cells = enumerate_cells(config);
  std::set<std::pair<double, std::string>> seen;
  for (const auto& c : cells) {
    if (!seen.insert({c.dt, c.integrator}).second) continue;
    try {
      if (config.scene.is_bilayer())
        bilayer_engine_config(c, config, 1).validate();
      else
        engine_config(c, config, 1, TapPlan{}).validate();
    } catch (const InputError& e) {
      // %g: std::to_string would print a dt of 1e-300 as 0.000000.
      char dt[32];
      std::snprintf(dt, sizeof dt, "%g", c.dt);
      const std::string integ = c.integrator.empty() ? "" : ", integrator " + c.integrator;
      throw InputError("study config " + config.name + ": scene (dt = " + dt + integ + "): " + e.what());
    }
  }
}

namespace detail {

std::vector<double> thin(const std::vector<double>& v, std::size_t points) {
  if (v.size() <= points) return v;
  std::vector<double> out;
  const std::size_t stride = (v.size() + points - 1) / points;
  for (std::size_t k = 0; k < v.size(); k += stride) out.push_back(v[k]);
  return out;
}

void record_costs(const dpd::Timings& t, std::int64_t steps_done, CellResult& out) {
  auto& sc = out.scalars;
  sc["cost.run_seconds"] = t.total_s;
  sc["cost.step_seconds"] = t.per_step_s;
  // The costs are this CPU's: a report that ranks by them names it.
  out.notes["cost.cpu"] = cpu_model();
  sc["cost.ns_per_number"] = t.ns_per_number;
  sc["cost.rng_share"] = t.rng_share_estimate;
  sc["cost.particle_steps_per_second"] = t.particle_steps_per_s;
  if (steps_done > 0) sc["cost.numbers_per_step"] = double(t.random_numbers) / double(steps_done);
}

}  // namespace detail

namespace {

// Leave-one-block-out curves as a blocks × bins matrix (none when there are fewer than two).
void put_jackknife(const std::vector<std::vector<double>>& curves, const std::string& name, CellResult& out) {
  if (curves.size() < 2) return;
  h5::Matrix m{curves.size(), curves.front().size(), {}};
  for (const auto& c : curves) {
    if (c.size() != m.cols) return;
    m.data.insert(m.data.end(), c.begin(), c.end());
  }
  out.matrices[name] = std::move(m);
}

}  // namespace

namespace {

// key_mean (unless stored already under `key`), key_sem and key_sem_dof (absent when the Stat has no samples).
void put_stat(const std::string& key, const dpd::Stat& s, CellResult& out, bool mean = true) {
  if (s.n == 0) return;
  if (mean) out.scalars[key + "_mean"] = s.mean;
  out.scalars[key + "_sem"] = s.sem;
  out.scalars[key + "_sem_dof"] = s.sem_dof;
}

void put_estimate(const std::string& key, const dpd::Estimate& e, CellResult& out) {
  if (!e.not_applicable.empty()) return;
  out.scalars[key] = e.mean;
  out.scalars[key + "_se"] = e.se;
  out.scalars[key + "_n"] = double(e.n);
}

}  // namespace

// The error budget's observables: the configurational temperature, the per-component temperatures and
// pressures, the noise's w_R²-weighted power and the correlations of its ζ (each with its standard error; absent
// where it cannot be computed).
void record_physics(const dpd::RunResult& r, CellResult& out) {
  put_stat("temperature_conf", r.configurational_temperature, out);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    put_stat(std::string("temperature_") + axes[a], r.temperature_diag[a], out);
    put_stat(std::string("pressure_") + axes[a] + axes[a], r.pressure_diag[a], out, false);
  }
  put_stat("zeta_weighted_second_moment", r.zeta_weighted_second_moment, out);
  detail::record_zeta_correlation(r.zeta_correlation, out);
}

void detail::record_zeta_correlation(const dpd::ZetaCorrelation& z, CellResult& out) {
  if (!z.requested || !z.not_applicable.empty()) return;
  for (std::size_t l = 0; l < z.autocorrelation.size(); ++l)
    put_estimate("zeta_autocorrelation_" + std::to_string(l + 1), z.autocorrelation[l], out);
  put_estimate("zeta_shared_bead_correlation", z.shared_bead, out);
}

void record_run(const dpd::RunResult& r, CellResult& out) {
  if (!r.ok()) {
    out.status = CellStatus::unstable;
    out.unstable_step = static_cast<long>(r.steps_done);
    out.reason = r.status.text();
  }
  auto& sc = out.scalars;
  sc["steps_done"] = double(r.steps_done);
  sc["momentum_drift"] = r.momentum_drift;
  if (!r.series.temperature.empty()) {
    std::vector<double> steps(r.series.step.begin(), r.series.step.end());
    out.series["series/step"] = detail::thin(steps, 1000);
    out.series["series/temperature"] = detail::thin(r.series.temperature, 1000);
  }
  detail::record_costs(r.timings, r.steps_done, out);
  // A run that blew up has no observables: they stay absent (null to h5py), never 0.
  if (!r.ok()) return;
  if (r.zeta.n >= 4) {
    // The power sums (replicas pool by adding them) and the cell's own moments, for h5py readers.
    const stats::MomentsResult m =
        stats::moments_of(stats::MomentSums::from_powers(r.zeta.n, r.zeta.s1, r.zeta.s2, r.zeta.s3, r.zeta.s4));
    sc["zeta_n"] = double(r.zeta.n);
    sc["zeta_s1"] = r.zeta.s1, sc["zeta_s2"] = r.zeta.s2, sc["zeta_s3"] = r.zeta.s3, sc["zeta_s4"] = r.zeta.s4;
    sc["zeta_mean"] = m.mean;
    sc["zeta_variance"] = m.variance;
    sc["zeta_variance_ci_lo"] = m.variance_ci.low, sc["zeta_variance_ci_hi"] = m.variance_ci.high;
    sc["zeta_second_moment"] = m.second_moment;
    sc["zeta_skewness"] = m.skewness;
    sc["zeta_excess_kurtosis"] = m.kurtosis;
  }
  // The kinetic temperature and its fluctuation under the observable table's names; each standard error's
  // degrees of freedom beside it.
  const Observable& kinetic = kinetic_temperature();
  const Observable& fluctuation = observable_row("temperature_std");
  sc[kinetic.key] = r.temperature.mean;
  sc[kinetic.sem] = r.temperature.sem;
  sc[std::string(kinetic.sem) + "_dof"] = r.temperature.sem_dof;
  sc[fluctuation.key] = r.temperature.std;
  sc[fluctuation.sem] = r.temperature.std_sem;
  sc[std::string(fluctuation.sem) + "_dof"] = r.temperature.std_sem_dof;
  sc["pressure_mean"] = r.pressure.mean;
  sc["pressure_sem"] = r.pressure.sem;
  sc["pressure_sem_dof"] = r.pressure.sem_dof;
  sc["pressure_conservative_mean"] = r.pressure_conservative.mean;
  sc["pressure_xx"] = r.pressure_diag[0].mean;
  sc["pressure_yy"] = r.pressure_diag[1].mean;
  sc["pressure_zz"] = r.pressure_diag[2].mean;
  record_physics(r, out);
  if (!r.msd.msd.empty()) {
    sc["diffusion_coefficient"] = r.msd.diffusion;
    sc["diffusion_sem"] = r.msd.diffusion_sem;
    sc["diffusion_sem_dof"] = r.msd.diffusion_sem_dof;
    out.series["msd/tau"] = r.msd.tau;
    out.series["msd/msd"] = r.msd.msd;
    put_jackknife(r.msd.jackknife, "msd/jackknife", out);
  }
  const auto& v = r.velocity_pdf;
  if (!v.v.empty()) {
    sc["vpdf_error_mb"] = v.error_rate_kT_mean;
    sc["vpdf_error_mb_sem"] = v.error_rate_kT_mean_sem;
    sc["vpdf_error_mb_sem_dof"] = v.error_rate_kT_mean_sem_dof;
    sc["vpdf_error_mb_measured_T"] = v.error_rate_measured_mean;
    std::vector<double> pooled(v.v.size(), 0.0);
    for (std::size_t k = 0; k < pooled.size(); ++k) pooled[k] = (v.pdf[0][k] + v.pdf[1][k] + v.pdf[2][k]) / 3.0;
    out.series["vpdf/v"] = v.v;
    out.series["vpdf/p"] = pooled;
    out.series["vpdf/mb"] = v.mb_kT;
    put_jackknife(v.jackknife, "vpdf/jackknife", out);
  }
  if (!r.rdf.g.empty()) {
    out.series["rdf/r"] = r.rdf.r;
    out.series["rdf/g"] = r.rdf.g;
    put_jackknife(r.rdf.jackknife, "rdf/jackknife", out);
  }
}

}  // namespace dpdrng::study
