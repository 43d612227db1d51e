// The stability study's points (stability.hpp): cells grouped by method and Δt, unstable replicas counted with
// their step and reason, the stable ones' accuracy and cost.
#include "dpdrng/study/stability.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "dpdrng/common/numbers.hpp"
#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/summary.hpp"
#include "dpdrng/study/observables.hpp"
#include "report_chart.hpp"

namespace dpdrng::study {
namespace {

bool is_reference_rdf_cell(const CellResult& c, double dt) {
  return c.cell.reference && c.cell.gamma == 0 && c.cell.feed == rng::Feed::halves && c.cell.dt == dt &&
         c.status == CellStatus::ok;
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// "unstable at step 412: temperature runaway (…)" → "temperature runaway (…)".
std::string bare_reason(const std::string& reason) {
  const std::size_t colon = reason.find(": ");
  return reason.rfind("unstable at step", 0) == 0 && colon != std::string::npos ? reason.substr(colon + 2) : reason;
}

void reference_of(const std::vector<CellResult>& cells, StabilityAnalysis& a) {
  for (const auto& c : cells)
    if (c.cell.reference && c.cell.gamma == 0 && (!std::isfinite(a.reference_dt) || c.cell.dt < a.reference_dt))
      a.reference_dt = c.cell.dt;
  std::vector<const CellResult*> ref;
  for (const auto& c : cells)
    if (is_reference_rdf_cell(c, a.reference_dt)) ref.push_back(&c);
  a.reference_cells = ref.size();
  a.reference_pressure = replica_mean(ref, "pressure_conservative_mean", "pressure_sem").mean;
  a.reference_diffusion = replica_mean(ref, "diffusion_coefficient", "diffusion_sem").mean;
  a.reference_rdf = detail::mean_series(ref, "rdf/g");
}

void accuracy_of(const std::vector<const CellResult*>& ok, const StabilityAnalysis& a, StabilityPoint& p) {
  const Observable& kinetic = kinetic_temperature();
  const ReplicaMean t = replica_mean(ok, kinetic.key, kinetic.sem);
  p.temperature = t.mean, p.temperature_ci = t.ci95;
  p.temperature_error = std::abs(t.mean - 1.0);
  const ReplicaMean tc = replica_mean(ok, "temperature_conf_mean", "temperature_conf_sem");
  p.temperature_conf = tc.mean, p.temperature_conf_ci = tc.ci95;
  p.pressure_conservative = replica_mean(ok, "pressure_conservative_mean", "pressure_sem").mean;
  p.pressure_error = std::abs(p.pressure_conservative - kWaterPressureConservative) / kWaterPressureConservative;
  p.pressure_ref_error = std::abs(p.pressure_conservative - a.reference_pressure) / a.reference_pressure;
  p.diffusion = replica_mean(ok, "diffusion_coefficient", "diffusion_sem").mean;
  p.diffusion_error = std::abs(p.diffusion - a.reference_diffusion) / a.reference_diffusion;
  if (!a.reference_rdf.empty()) p.rdf_error = curve_error(detail::mean_series(ok, "rdf/g"), a.reference_rdf, 0.1);
  std::vector<double> cost;
  for (const auto* c : ok)
    if (c->has("cost.step_seconds")) cost.push_back(c->scalar("cost.step_seconds", NAN));
  p.step_seconds = median(cost);
  p.seconds_per_time = p.step_seconds / p.dt;
}

// The values of `name` over a point's stable replicas.
std::vector<double> values(const std::vector<const CellResult*>& ok, const std::string& name) {
  std::vector<double> v;
  for (const auto* c : ok)
    if (c->has(name) && std::isfinite(c->scalar(name, NAN))) v.push_back(c->scalar(name, NAN));
  return v;
}

// The 95 % half-width of a point's replica mean with one replica's variance pooled from its own replicas and
// those of every other method at the same integrator, Δt and γ (other generators and noises: the replicas' spread
// is the run length's and the scene's, not the noise's), weighted by their degrees of freedom, unless its own
// replicas vary more than the pool (stats::paired_t's consistency test); NaN without any spread.
double pooled_half_width(const std::vector<double>& own, const std::vector<std::vector<double>>& others) {
  std::vector<stats::VarianceEstimate> extra;
  for (const auto& g : others)
    if (g.size() >= 2) extra.push_back({std::pow(stats::sample_sd(g), 2), double(g.size() - 1)});
  if (own.empty()) return NAN;
  const stats::TTest t = stats::paired_t(own, extra);
  return t.ci_half_width(0.95);
}

// Each point's k_BT and T_conf CIs under the pooled model (`oks`: each point's stable cells, in point order).
void pool_cis(StabilityAnalysis& a, const std::vector<std::vector<const CellResult*>>& oks) {
  for (const Observable* o : {&kinetic_temperature(), &observable_row("temperature_conf_mean")}) {
    const char* name = o->key;
    const bool conf = o != &kinetic_temperature();
    for (std::size_t k = 0; k < a.points.size(); ++k) {
      StabilityPoint& p = a.points[k];
      if (oks[k].empty()) continue;
      std::vector<std::vector<double>> others;
      for (std::size_t j = 0; j < a.points.size(); ++j) {
        const StabilityPoint& q = a.points[j];
        if (j != k && q.integrator == p.integrator && q.dt == p.dt && q.gamma == p.gamma)
          others.push_back(values(oks[j], name));
      }
      const double h = pooled_half_width(values(oks[k], name), others);
      (conf ? p.temperature_conf_ci : p.temperature_ci) = h;
    }
  }
}

}  // namespace

std::string StabilityPoint::method() const {
  const std::string m = (integrator.empty() ? std::string("mvv") : integrator) + " " + generator + " " + noise;
  return gamma > 0 ? m + " γ" + exact_decimal(gamma) : m;
}

std::vector<std::string> stability_methods(const StabilityAnalysis& a) {
  std::vector<std::string> out;
  for (const auto& p : a.points)
    if (std::find(out.begin(), out.end(), p.method()) == out.end()) out.push_back(p.method());
  return out;
}

StabilityAnalysis analyse_stability(const StudyConfig& config, const std::vector<CellResult>& cells) {
  StabilityAnalysis a;
  reference_of(cells, a);
  // Methods in the order of the sweep (its first cell of each), Δt ascending.
  std::vector<std::string> order;
  std::map<std::string, std::map<double, std::vector<const CellResult*>>> groups;
  std::vector<const CellResult*> sorted;
  for (const auto& c : cells) sorted.push_back(&c);
  std::map<std::string, std::size_t> position;
  for (const auto& cell : enumerate_cells(config)) position.emplace(cell.id(), position.size());
  const auto rank = [&](const CellResult* c) {
    const auto it = position.find(c->cell.id());
    return it == position.end() ? position.size() : it->second;
  };
  std::stable_sort(sorted.begin(), sorted.end(),
                   [&](const CellResult* x, const CellResult* y) { return rank(x) < rank(y); });
  for (const auto* c : sorted) {
    if (const auto it = c->notes.find("cost.cpu");
        it != c->notes.end() && std::find(a.cpus.begin(), a.cpus.end(), it->second) == a.cpus.end())
      a.cpus.push_back(it->second);
    StabilityPoint key;
    key.integrator = c->cell.integrator, key.generator = c->cell.label(), key.noise = c->cell.noise();
    key.gamma = c->cell.gamma;
    const std::string m = key.method();
    if (!groups.count(m)) order.push_back(m);
    groups[m][c->cell.dt].push_back(c);
  }
  std::vector<std::vector<const CellResult*>> oks;  // each point's stable cells
  for (const auto& m : order)
    for (const auto& [dt, group] : groups[m]) {
      StabilityPoint p;
      const Cell& first = group.front()->cell;
      p.integrator = first.integrator, p.generator = first.label(), p.noise = first.noise(), p.dt = dt;
      p.gamma = first.gamma, p.reference = first.reference;
      p.replicas = group.size();
      std::vector<const CellResult*> ok;
      for (const auto* c : group) {
        if (c->status == CellStatus::ok) {
          ok.push_back(c);
          continue;
        }
        const long step = c->status == CellStatus::unstable ? c->unstable_step : -1;
        if (p.reason.empty() || (step >= 0 && (p.first_blowup_step < 0 || step < p.first_blowup_step))) {
          p.first_blowup_step = step;
          p.reason = c->status == CellStatus::unstable ? bare_reason(c->reason)
                                                       : std::string(to_string(c->status)) + ": " + c->reason;
        }
      }
      p.stable = ok.size();
      if (!ok.empty()) accuracy_of(ok, a, p);
      a.points.push_back(std::move(p));
      oks.push_back(std::move(ok));
    }
  pool_cis(a, oks);
  return a;
}

double first_unstable_dt(const StabilityAnalysis& a, const std::string& method) {
  for (const auto& p : a.points)
    if (p.method() == method && p.stable < p.replicas) return p.dt;
  return NAN;
}

}  // namespace dpdrng::study
