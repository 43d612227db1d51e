#include "dpdrng/dpd/result.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <string_view>

#include "dpdrng/common/error.hpp"

namespace dpdrng::dpd {

namespace {

// Integrated autocorrelation time by Sokal's automatic window (Madras & Sokal, J. Stat. Phys. 50 (1988) 109):
// τ(W) = 1/2 + Σ_{l=1}^{W} ρ(l), W the first lag with W ≥ 6 τ(W), at most n/4. Fixed blocks would not do: at
// the CI scale a block of 65 steps is only seven times the temperature's τ ≈ 9 steps, and the block means'
// correlation made the standard error 8 % too small.
struct Autocorrelation {
  double tau = 0.5;
  std::size_t window = 0;
};
Autocorrelation integrated_tau(const std::vector<double>& x, double m) {
  const std::size_t n = x.size();
  double c0 = 0;
  for (const double v : x) c0 += (v - m) * (v - m);
  c0 /= double(n);
  Autocorrelation a;
  if (!(c0 > 0)) return a;
  for (std::size_t l = 1; l <= n / 4; ++l) {
    double c = 0;
    for (std::size_t i = 0; i + l < n; ++i) c += (x[i] - m) * (x[i + l] - m);
    a.tau += c / double(n - l) / c0;
    a.window = l;
    if (double(l) >= 6.0 * a.tau) break;
  }
  a.tau = std::max(a.tau, 0.5 / double(n));  // a strongly alternating series; never a negative variance
  return a;
}

}  // namespace

Stat make_stat(const std::vector<double>& x) {
  Stat s;
  s.n = x.size();
  if (x.empty()) return s;
  double m = 0;
  for (double v : x) m += v;
  m /= double(x.size());
  double v2 = 0;
  for (double v : x) v2 += (v - m) * (v - m);
  s.mean = m;
  if (x.size() < 2) {
    s.std = s.sem = s.std_sem = NAN;
    return s;
  }
  s.std = std::sqrt(v2 / double(x.size() - 1));
  constexpr std::size_t kTooShort = 40;
  if (x.size() < kTooShort) {
    // Too short to estimate a correlation time: the errors of independent normal samples.
    s.sem = s.std / std::sqrt(double(x.size()));
    s.sem_dof = double(x.size()) - 1.0;
    s.std_sem = s.std / std::sqrt(2.0 * double(x.size() - 1));
    s.std_sem_dof = s.sem_dof;
    return s;
  }
  const double n = double(x.size());
  const Autocorrelation a = integrated_tau(x, m);
  s.sem = std::sqrt(v2 / n * 2.0 * a.tau / n);
  // var(τ̂)/τ² ≈ 2(2W + 1)/n (Madras & Sokal), so s.sem² carries about n/(2W + 1) degrees of freedom.
  s.sem_dof = n / double(2 * a.window + 1);
  // The variance is the mean of y = (x − m)²: its error likewise, and std's by the delta method, σ_s = σ_{s²}/2s.
  std::vector<double> y(x.size());
  double my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = (x[k] - m) * (x[k] - m), my += y[k] / n;
  double vy = 0;
  for (const double v : y) vy += (v - my) * (v - my);
  const Autocorrelation ay = integrated_tau(y, my);
  s.std_sem = s.std > 0 ? std::sqrt(vy / n * 2.0 * ay.tau / n) / (2.0 * s.std) : 0.0;
  s.std_sem_dof = n / double(2 * ay.window + 1);
  return s;
}

Stat make_ratio_stat(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  double ma = 0, mb = 0;
  for (std::size_t k = 0; k < n; ++k) ma += a[k], mb += b[k];
  if (n < 2 || !(mb > 0)) return Stat{};  // one sample has no error to give
  const double r = ma / mb;
  mb /= double(n);
  std::vector<double> d(n);
  for (std::size_t k = 0; k < n; ++k) d[k] = (a[k] - r * b[k]) / mb;
  Stat s = make_stat(d);
  s.mean = r;
  return s;
}

std::string_view to_string(RunState s) {
  switch (s) {
    case RunState::ok: return "ok";
    case RunState::unstable: return "unstable";
    case RunState::disrupted: return "disrupted";
  }
  return "?";
}

RunState parse_run_state(std::string_view name) {
  for (RunState s : {RunState::ok, RunState::unstable, RunState::disrupted})
    if (to_string(s) == name) return s;
  throw InputError("unknown run state \"" + std::string(name) + "\" (known: ok, unstable, disrupted)");
}

std::string RunStatus::text() const {
  if (state == RunState::ok) return "ok";
  return std::string(to_string(state)) + " at step " + std::to_string(step) + ": " + detail;
}

std::ostream& operator<<(std::ostream& o, const RunStatus& s) { return o << s.text(); }

nlohmann::json to_json(const Stat& s) {
  return {{"mean", s.mean},       {"std", s.std},         {"sem", s.sem},
          {"sem_dof", s.sem_dof}, {"std_sem", s.std_sem}, {"std_sem_dof", s.std_sem_dof},
          {"n", s.n}};
}

namespace {
// {"moves": k, "steps": {"2": n2, "1": n1}}: the steps each team size ran (JSON keys are strings).
nlohmann::json team_json(const Timings& t) {
  nlohmann::json steps = nlohmann::json::object();
  for (const auto& [team, n] : t.steps_by_team) steps[std::to_string(team)] = n;
  return {{"moves", t.team_moves}, {"steps", steps}};
}
}  // namespace

nlohmann::json timings_json(const Timings& t) {
  return {{"total_s", t.total_s},
          {"force_s", t.force_s},
          {"per_step_s", t.per_step_s},
          {"particle_steps_per_s", t.particle_steps_per_s},
          {"random_numbers", t.random_numbers},
          {"zetas", t.zetas},
          {"ns_per_number", t.ns_per_number},
          {"ns_per_zeta", t.ns_per_zeta},
          {"rng_share_estimate", t.rng_share_estimate},
          {"list_builds", t.list_builds},
          {"threads", t.threads},
          {"team", team_json(t)}};
}

void put_mean_sem(nlohmann::json& j, const std::string& key, const Stat& s) {
  j[key + "_mean"] = s.mean;
  j[key + "_sem"] = s.sem;
}

void put_value_sem(nlohmann::json& j, const std::string& key, const Stat& s) {
  j[key] = s.mean;
  j[key + "_sem"] = s.sem;
}

namespace {

void put_arrays(nlohmann::json& j, const RunResult& r) {
  const VelocityPdf& p = r.velocity_pdf;
  j["velocity_pdf"] = {{"v", p.v}, {"x", p.pdf[0]}, {"y", p.pdf[1]}, {"z", p.pdf[2]},
                       {"maxwell_boltzmann_kT", p.mb_kT}, {"maxwell_boltzmann_measured", p.mb_measured},
                       {"samples", p.samples}};
  j["msd"] = {{"tau", r.msd.tau}, {"msd", r.msd.msd}};
  j["rdf"] = {{"r", r.rdf.r}, {"g", r.rdf.g}, {"samples", r.rdf.samples}};
  if (!r.series.step.empty())
    j["series"] = {{"step", r.series.step}, {"temperature", r.series.temperature},
                   {"pressure", r.series.pressure}, {"pressure_conservative", r.series.pressure_conservative},
                   {"px", r.series.px}, {"py", r.series.py}, {"pz", r.series.pz}};
}


}  // namespace

void null_observables(nlohmann::json& j, std::initializer_list<const char*> kept) {
  static constexpr const char* kLabels[] = {"status", "steps_done", "generator", "seeding", "distribution", "feed", "pairs",
                                            "particles", "timings", "momentum_drift_per_bead", "momentum_final",
                                            "series", "not_applicable"};
  auto keep = [&](const std::string& k) {
    for (const char* l : kLabels)
      if (k == l) return true;
    for (const char* l : kept)
      if (k == l) return true;
    return false;
  };
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!keep(it.key())) it.value() = nullptr;
}

nlohmann::json to_json(const ZetaSums& z) {
  return {{"n", z.n}, {"s1", z.s1}, {"s2", z.s2}, {"s3", z.s3}, {"s4", z.s4}};
}

nlohmann::json mean_se_json(const Stat& s) {
  if (s.n == 0) return nullptr;
  return {{"mean", s.mean}, {"se", s.sem}};
}

nlohmann::json to_json(const Estimate& e) {
  if (!e.not_applicable.empty()) return nullptr;
  return {{"mean", e.mean}, {"se", e.se}, {"n", e.n}};
}

nlohmann::json to_json(const ZetaCorrelation& z) {
  nlohmann::json j;
  if (!z.not_applicable.empty()) {
    j["autocorrelation"] = nullptr;
    j["shared_bead_correlation"] = nullptr;
    j["not_applicable"] = "not applicable: " + z.not_applicable;
    return j;
  }
  j["autocorrelation"] = nlohmann::json::array();
  for (std::size_t l = 0; l < z.autocorrelation.size(); ++l) {
    nlohmann::json e = to_json(z.autocorrelation[l]);
    if (e.is_object()) e["lag"] = l + 1;
    j["autocorrelation"].push_back(e);
  }
  j["shared_bead_correlation"] = to_json(z.shared_bead);
  j["segments"] = z.segments;
  return j;
}

namespace {

// The noise as the force received it: the w_R²-weighted second moment and the ζ correlations (null with the
// reason under "not_applicable" where they cannot be computed or were not asked for).
nlohmann::json zeta_physics_json(const RunResult& r) {
  nlohmann::json z;
  z["weighted_second_moment"] = mean_se_json(r.zeta_weighted_second_moment);
  if (r.zeta_weighted_second_moment.n == 0)
    z["not_applicable"]["weighted_second_moment"] = "not applicable: no ζ drawn for a pair inside r_c";
  const ZetaCorrelation& c = r.zeta_correlation;
  if (!c.requested) {
    z["autocorrelation"] = nullptr;
    z["shared_bead_correlation"] = nullptr;
    z["not_applicable"]["autocorrelation"] = "not requested (zeta_lags = 0)";
    return z;
  }
  const nlohmann::json j = to_json(c);
  z["autocorrelation"] = j["autocorrelation"];
  z["shared_bead_correlation"] = j["shared_bead_correlation"];
  if (j.contains("segments")) z["tracked_segments"] = j["segments"];
  if (j.contains("not_applicable")) z["not_applicable"]["autocorrelation"] = j["not_applicable"];
  return z;
}

}  // namespace

nlohmann::json to_json(const RunResult& r, bool arrays) {
  nlohmann::json j;
  put_run_labels(j, r);
  j["integrator"] = r.integrator;
  j["box_length"] = r.box_length;
  put_mean_sem(j, "temperature", r.temperature);
  j["temperature_std"] = r.temperature.std;
  j["temperature_std_sem"] = r.temperature.std_sem;
  put_mean_sem(j, "pressure", r.pressure);
  put_mean_sem(j, "pressure_conservative", r.pressure_conservative);
  j["diffusion_coefficient"] = r.msd.diffusion;
  j["diffusion_coefficient_sem"] = r.msd.diffusion_sem;
  j["velocity_pdf_error_rate"] = r.velocity_pdf.error_rate_kT_mean;
  j["velocity_pdf_error_rate_sem"] = r.velocity_pdf.error_rate_kT_mean_sem;
  j["velocity_pdf_error_rate_measured_T"] = r.velocity_pdf.error_rate_measured_mean;
  if (!r.velocity_pdf.measured_not_applicable.empty())
    j["not_applicable"]["velocity_pdf_error_rate_measured_T"] = "not applicable: " + r.velocity_pdf.measured_not_applicable;
  j["momentum_drift_per_bead"] = r.momentum_drift;
  j["temperature"] = to_json(r.temperature);
  j["pressure"] = to_json(r.pressure);
  j["pressure_conservative"] = to_json(r.pressure_conservative);
  for (int a = 0; a < 3; ++a) {
    j["pressure_diag"].push_back(to_json(r.pressure_diag[a]));
    j["pressure_conservative_diag"].push_back(to_json(r.pressure_conservative_diag[a]));
  }
  j["configurational_temperature"] = mean_se_json(r.configurational_temperature);
  if (r.configurational_temperature.n == 0)
    j["not_applicable"]["configurational_temperature"] =
        "not applicable: fewer than 2 sampled production steps, or no positive mean Laplacian of the "
        "conservative potential";
  for (int a = 0; a < 3; ++a) {
    j["temperature_components"].push_back(mean_se_json(r.temperature_diag[a]));
    j["pressure_components"].push_back(mean_se_json(r.pressure_diag[a]));
  }
  j["zeta"] = zeta_physics_json(r);
  j["momentum_final"] = r.momentum_final;
  j["velocity_pdf_error_rate_xyz"] = r.velocity_pdf.error_rate_kT;
  j["msd_fit"] = {{"from", r.msd.fit_from}, {"to", r.msd.fit_to}};
  j["zeta_sums"] = to_json(r.zeta);
  j["timings"] = timings_json(r.timings);
  j["timings"]["production_s"] = r.timings.production_s;
  j["timings"]["production_particle_steps_per_s"] = r.timings.production_particle_steps_per_s;
  if (arrays) put_arrays(j, r);
  if (blew_up(r.status)) null_observables(j, {"integrator", "box_length"});
  return j;
}
}  // namespace dpdrng::dpd
