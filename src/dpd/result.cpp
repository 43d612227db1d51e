#include "dpdrng/dpd/result.hpp"

#include <cmath>

namespace dpdrng::dpd {

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
  s.std = x.size() > 1 ? std::sqrt(v2 / double(x.size() - 1)) : 0.0;
  // 20 blocks: long enough (hundreds of steps in a paper-sized run) to outlast the correlation time.
  constexpr std::size_t kBlocks = 20;
  if (x.size() < 2 * kBlocks) {
    s.sem = s.std / std::sqrt(double(x.size()));
    return s;
  }
  const std::size_t len = x.size() / kBlocks;
  double bm2 = 0;
  for (std::size_t b = 0; b < kBlocks; ++b) {
    double bm = 0;
    for (std::size_t k = b * len; k < (b + 1) * len; ++k) bm += x[k];
    bm /= double(len);
    bm2 += (bm - m) * (bm - m);
  }
  s.sem = std::sqrt(bm2 / double(kBlocks - 1) / double(kBlocks));
  return s;
}

nlohmann::json to_json(const Stat& s) { return {{"mean", s.mean}, {"std", s.std}, {"sem", s.sem}, {"n", s.n}}; }

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
          {"threads", t.threads}};
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
  static constexpr const char* kLabels[] = {"status", "steps_done", "generator", "seeding", "distribution", "pairs",
                                            "particles", "timings", "momentum_drift_per_bead", "momentum_final",
                                            "series"};
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

nlohmann::json to_json(const RunResult& r, bool arrays) {
  nlohmann::json j;
  put_run_labels(j, r);
  j["integrator"] = r.integrator;
  j["box_length"] = r.box_length;
  put_mean_sem(j, "temperature", r.temperature);
  j["temperature_std"] = r.temperature.std;
  put_mean_sem(j, "pressure", r.pressure);
  put_mean_sem(j, "pressure_conservative", r.pressure_conservative);
  j["diffusion_coefficient"] = r.msd.diffusion;
  j["diffusion_coefficient_sem"] = r.msd.diffusion_sem;
  j["velocity_pdf_error_rate"] = r.velocity_pdf.error_rate_kT_mean;
  j["velocity_pdf_error_rate_measured_T"] = r.velocity_pdf.error_rate_measured_mean;
  j["momentum_drift_per_bead"] = r.momentum_drift;
  j["temperature"] = to_json(r.temperature);
  j["pressure"] = to_json(r.pressure);
  j["pressure_conservative"] = to_json(r.pressure_conservative);
  for (int a = 0; a < 3; ++a) {
    j["pressure_diag"].push_back(to_json(r.pressure_diag[a]));
    j["pressure_conservative_diag"].push_back(to_json(r.pressure_conservative_diag[a]));
  }
  j["momentum_final"] = r.momentum_final;
  j["velocity_pdf_error_rate_xyz"] = r.velocity_pdf.error_rate_kT;
  j["msd_fit"] = {{"from", r.msd.fit_from}, {"to", r.msd.fit_to}};
  j["timings"] = timings_json(r.timings);
  j["timings"]["production_s"] = r.timings.production_s;
  j["timings"]["production_particle_steps_per_s"] = r.timings.production_particle_steps_per_s;
  if (arrays) put_arrays(j, r);
  if (blew_up(r.status)) null_observables(j, {"integrator", "box_length"});
  return j;
}
}  // namespace dpdrng::dpd
