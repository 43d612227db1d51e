// The stability report's charts (stability.hpp): accuracy against cost per method, the integrators' panel of cost
// against signed temperature error, the crossing of noise and integrator error against Δt, and the stability map.
#include <algorithm>
#include <cmath>

#include "dpdrng/study/stability.hpp"
#include "report_chart.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {
using detail::Chart;
using detail::Line;

// y in % of k_BT = 1 on a linear axis, drawn only within ±10 %: the band of interest is ±1 %, a few % decide the
// ranking, and a run far off (Shardlow at k_BT 45 before it blows up) would flatten everything else.
constexpr double kShownPercent = 10;
constexpr const char* kPercentAxis = "set grid\n";

bool shown(double percent) { return std::isfinite(percent) && std::abs(percent) <= kShownPercent; }

// Per integrator, the reference generator under its first noise at the scene's γ: wall seconds per unit of
// simulated time against the signed error of the ranking temperature (configurational for PNHLN), with 95 % CIs.
Chart integrator_panel(const StabilityAnalysis& a, double tolerance) {
  Chart c{"accuracy_cost_integrators",
          "Integrators (reference generator): temperature error against cost, 95 % CIs (PNHLN: T_conf; within 10 %)",
          "wall seconds per unit of simulated time",
          "<T> - 1 (%)",
          true,
          false,
          std::string(kPercentAxis) + "set arrow from graph 0, first " + std::to_string(100 * tolerance) +
              " to graph 1, first " + std::to_string(100 * tolerance) + " nohead dt 2\nset arrow from graph 0, first " +
              std::to_string(-100 * tolerance) + " to graph 1, first " + std::to_string(-100 * tolerance) +
              " nohead dt 2\nset key outside right\n",
          {},
          false};
  const auto ranks = rank_integrators(a, tolerance);
  for (std::size_t k = 0; k < ranks.size(); ++k) {
    const auto& r = ranks[k];
    Line l{r.integrator + (r.ranked_by == Thermometer::configurational ? " (T_conf)" : ""),
           "using 1:2:3 with yerrorlines pt 7 lw 2 lc " + std::to_string(k + 1), {}, {}};
    for (const auto& p : a.points) {
      if (p.method() != r.method || !std::isfinite(p.seconds_per_time)) continue;
      const bool conf = r.ranked_by == Thermometer::configurational;
      const double m = conf ? p.temperature_conf : p.temperature, h = conf ? p.temperature_conf_ci : p.temperature_ci;
      if (shown(100 * (m - 1)))
        l.rows.push_back({p.seconds_per_time, 100 * (m - 1), std::isfinite(h) ? 100 * h : 0.0});
    }
    if (!l.rows.empty()) c.lines.push_back(std::move(l));
  }
  return c;
}

// One chart per integrator that draws pair noise and per thermometer: k_BT (T_conf) against Δt for every
// generator × noise, 95 % CIs, linear axes.
std::vector<Chart> crossing_charts(const StabilityAnalysis& a) {
  const auto rows = crossing_rows(a);
  std::vector<std::string> integrators;
  for (const auto& r : rows)
    if (std::find(integrators.begin(), integrators.end(), r.integrator) == integrators.end())
      integrators.push_back(r.integrator);
  std::vector<Chart> out;
  for (const bool conf : {false, true})
    for (const auto& integ : integrators) {
      std::string tag = integ;
      std::replace(tag.begin(), tag.end(), ':', '_');
      Chart c{std::string("crossing_") + (conf ? "conf_" : "kinetic_") + tag,
              integ + ": " + (conf ? "configurational" : "kinetic") + " temperature against dt, 95 % CIs (within 10 %)",
              "dt (DPD time units)",
              conf ? "<T_conf> - 1 (%)" : "<k_BT> - 1 (%)",
              false,
              false,
              std::string(kPercentAxis) + "set key outside right\n",
              {},
              false};
      std::vector<std::string> series;
      for (const auto& r : rows)
        if (r.integrator == integ && std::find(series.begin(), series.end(), r.generator + " " + r.noise) == series.end())
          series.push_back(r.generator + " " + r.noise);
      for (std::size_t k = 0; k < series.size(); ++k) {
        Line l{series[k], "using 1:2:3 with yerrorlines pt 7 lw 2 lc " + std::to_string(k + 1), {}, {}};
        for (const auto& r : rows) {
          if (r.integrator != integ || r.generator + " " + r.noise != series[k]) continue;
          const double m = conf ? r.temperature_conf : r.temperature, h = conf ? r.temperature_conf_ci : r.temperature_ci;
          if (shown(100 * (m - 1))) l.rows.push_back({r.dt, 100 * (m - 1), std::isfinite(h) ? 100 * h : 0.0});
        }
        if (!l.rows.empty()) c.lines.push_back(std::move(l));
      }
      if (!c.lines.empty()) out.push_back(std::move(c));
    }
  return out;
}

}  // namespace

std::vector<std::string> write_stability_charts(const StabilityAnalysis& a, double tolerance, const fs::path& dir,
                                                std::ostream* log) {
  const auto methods = stability_methods(a);
  struct Axis {
    const char* name;
    const char* label;
    double StabilityPoint::*error;
  };
  const Axis axes[] = {{"temperature", "|<k_BT> - 1|", &StabilityPoint::temperature_error},
                       {"pressure", "|P_c - 23.64| / 23.64", &StabilityPoint::pressure_error},
                       {"diffusion", "|D - D_ref| / D_ref", &StabilityPoint::diffusion_error},
                       {"rdf", "mean |g(r) - g_ref(r)| / g_ref(r)", &StabilityPoint::rdf_error}};
  std::vector<Chart> charts;
  for (const auto& ax : axes) {
    Chart c{std::string("accuracy_cost_") + ax.name,
            std::string("Accuracy against cost per unit simulated time: ") + ax.label +
                " (blown-up points on the top edge)",
            "wall seconds per unit of simulated time", ax.label, false, true, "set logscale x\n", {}, false};
    // A method × Δt whose replicas all blew up has no accuracy: it is marked on the top edge at the cost its
    // method's last stable Δt predicts (cost per step / Δt), never left out.
    double top = 0;
    for (const auto& p : a.points)
      if (std::isfinite(p.*ax.error)) top = std::max(top, p.*ax.error);
    top = top > 0 ? top * 3 : 1;
    Line blown{"all replicas blew up", "using 1:2 with points pt 2 ps 2 lw 2 lc rgb 'red'", {}, {}};
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Line l{methods[k], "using 1:2 with linespoints pt 7 lw 2 lc " + std::to_string(k + 1), {}, {}};
      double step_seconds = NAN;
      for (const auto& p : a.points) {
        if (p.method() != methods[k]) continue;
        if (std::isfinite(p.seconds_per_time)) step_seconds = p.seconds_per_time * p.dt;
        if (p.all_blew_up()) {
          if (std::isfinite(step_seconds)) blown.rows.push_back({step_seconds / p.dt, top});
          continue;
        }
        const double y = p.*ax.error;
        if (std::isfinite(y) && y > 0 && std::isfinite(p.seconds_per_time)) l.rows.push_back({p.seconds_per_time, y});
      }
      if (!l.rows.empty()) c.lines.push_back(std::move(l));
    }
    if (!blown.rows.empty()) c.lines.push_back(std::move(blown));
    charts.push_back(std::move(c));
  }
  charts.push_back(integrator_panel(a, tolerance));
  for (auto& c : crossing_charts(a)) charts.push_back(std::move(c));
  Chart map{"stability_map", "Fraction of replicas stable against dt", "dt", "fraction stable", false, false,
            "set yrange [-0.05:1.05]\nset key outside right\n", {}, false};
  for (std::size_t k = 0; k < methods.size(); ++k) {
    Line l{methods[k], "using 1:2 with linespoints pt " + std::to_string(k % 12 + 1) + " lw 2", {}, {}};
    for (const auto& p : a.points)
      if (p.method() == methods[k]) l.rows.push_back({p.dt, double(p.stable) / double(p.replicas)});
    map.lines.push_back(std::move(l));
  }
  charts.push_back(std::move(map));
  std::vector<std::string> made;
  const bool run = detail::has_gnuplot();
  for (const auto& c : charts)
    if (detail::render(c, dir, run, log)) made.push_back(c.name);
  return made;
}


}  // namespace dpdrng::study
