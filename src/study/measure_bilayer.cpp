// The membrane scene's cell: one dpd::run_bilayer and its observables. No taps: the generators' statistics are
// the water scene's job, so a bilayer cell costs only its run.
#include <algorithm>
#include <cstdio>

#include "dpdrng/study/measure.hpp"
#include "measure_common.hpp"

namespace dpdrng::study {
namespace {

void put(CellResult& out, const std::string& name, const dpd::Stat& s) {
  out.scalars[name + "_mean"] = s.mean;
  out.scalars[name + "_std"] = s.std;
  out.scalars[name + "_sem"] = s.sem;
  out.scalars[name + "_sem_dof"] = s.sem_dof;
}

}  // namespace

dpd::BilayerConfig bilayer_engine_config(const Cell& cell, const StudyConfig& config, int threads) {
  const auto& s = config.scene;
  dpd::BilayerConfig b;
  detail::set_run(b, cell, s, threads);
  b.warmup = std::min<std::int64_t>(b.warmup, s.equilibrate);
  b.zeta_lags = kStudyZetaLags;
  return b;
}

void record_bilayer(const dpd::BilayerResult& r, CellResult& out) {
  if (!r.ok()) {
    const bool disrupted = r.status.state == dpd::RunState::disrupted;
    out.status = disrupted ? CellStatus::disrupted : CellStatus::unstable;
    out.unstable_step = static_cast<long>(disrupted ? r.status.step : r.steps_done);
    out.reason = r.status.text();
  }
  auto& sc = out.scalars;
  sc["steps_done"] = double(r.steps_done);
  sc["momentum_drift"] = r.momentum_drift;
  sc["box_z"] = r.box[2];
  if (!r.series.step.empty()) {
    std::vector<double> steps(r.series.step.begin(), r.series.step.end());
    out.series["series/step"] = detail::thin(steps, 1000);
    out.series["series/temperature"] = detail::thin(r.series.temperature, 1000);
    out.series["series/tension"] = detail::thin(r.series.tension, 1000);
  }
  sc["cost.bonded_seconds"] = r.bonded_s;
  detail::record_costs(r.timings, r.steps_done, out);
  // A run that blew up has no observables: they stay absent (null to h5py), never 0. A disrupted one (a lipid
  // left the bilayer) ran to the end: its observables are data.
  if (out.status == CellStatus::unstable) return;
  put(out, "temperature", r.temperature);
  put(out, "pressure", r.pressure);
  put(out, "pressure_xx", r.pressure_diag[0]);
  put(out, "pressure_yy", r.pressure_diag[1]);
  put(out, "pressure_zz", r.pressure_diag[2]);
  put(out, "temperature_x", r.temperature_diag[0]);
  put(out, "temperature_y", r.temperature_diag[1]);
  put(out, "temperature_z", r.temperature_diag[2]);
  put(out, "pressure_xx_minus_yy", r.pressure_anisotropy);
  if (r.zeta_weighted_second_moment.n > 0) put(out, "zeta_weighted_second_moment", r.zeta_weighted_second_moment);
  detail::record_zeta_correlation(r.zeta_correlation, out);
  put(out, "tension", r.tension);
  put(out, "tension_conservative", r.tension_conservative);
  put(out, "thickness", r.thickness);
  put(out, "head_separation", r.head_separation);
  put(out, "tail_order", r.tail_order);
  sc["lipids_out_max"] = r.lipids_out_max;
  if (!r.profile.z.empty()) {
    out.series["profile/z"] = r.profile.z;
    out.series["profile/head"] = r.profile.head;
    out.series["profile/tail"] = r.profile.tail;
    out.series["profile/water"] = r.profile.water;
  }
  if (!r.order_by_bond.empty()) out.series["order_by_bond"] = r.order_by_bond;
}

}  // namespace dpdrng::study
