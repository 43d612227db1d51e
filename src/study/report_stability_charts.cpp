// The stability report's charts (stability.hpp): accuracy against cost per method, the integrators' panel of cost
// against signed temperature error, the crossing of noise and integrator error against Δt, and the stability map.
#include <algorithm>
#include <cmath>
#include <string>

#include "dpdrng/study/stability.hpp"
#include "report_chart.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {
using detail::Axis;
using detail::Chart;
using detail::Line;
using detail::Scale;

// y in % of k_BT = 1 on a linear axis, drawn only within ±10 %: the band of interest is ±1 %, a few % decide the
// ranking, and a run far off (Shardlow at k_BT 45 before it blows up) would flatten everything else.
constexpr double kShownPercent = 10;
bool shown(double percent) { return std::isfinite(percent) && std::abs(percent) <= kShownPercent; }

// Series of one family after the first are dashed: the noises of one generator apart at a glance.
std::size_t dash_of(const std::vector<std::string>& series, std::size_t k) {
  std::size_t n = 0;
  for (std::size_t j = 0; j < k; ++j) n += detail::family_colour(series[j]) == detail::family_colour(series[k]);
  return n;
}

struct MapQuantity {
  const char* name;
  const char* what;
  const char* unit;
  double (*value)(const StabilityPoint&);  // in the unit, NaN when the point has none
  bool signed_error;
};

const std::vector<MapQuantity>& map_quantities() {
  static const std::vector<MapQuantity> q = {
      {"temperature", "k_BT − 1", "% of k_BT", [](const StabilityPoint& p) { return 100 * (p.temperature - 1); }, true},
      {"pressure", "|P_c − 23.64| / 23.64", "%", [](const StabilityPoint& p) { return 100 * p.pressure_error; }, false},
      {"diffusion", "|D − D_ref| / D_ref", "%", [](const StabilityPoint& p) { return 100 * p.diffusion_error; }, false},
      {"rdf", "mean |g − g_ref| / g_ref", "%", [](const StabilityPoint& p) { return 100 * p.rdf_error; }, false},
  };
  return q;
}

// The stability map as small multiples: one panel per generator × noise (× γ), Δt along x, the integrators along
// y, each cell coloured by the quantity's error and a cross where every replica blew up. The temperature's colours
// span ±5 %, where the noise's −3.5 % and the integrators' few % lie; the other errors 0–10 %.
Chart stability_map(const StabilityAnalysis& a, const MapQuantity& q) {
  Chart c{std::string("stability_map") + (std::string(q.name) == "temperature" ? "" : std::string("_") + q.name),
          std::string("Stability map: ") + q.what + " by Δt and integrator (cross: every replica blew up)",
          Axis{"time step Δt", "τ", Scale::log10}, Axis{"integrator", "", Scale::categories},
          {"dt", "integrator_index", "value", "stable_fraction"}};
  std::vector<std::string> integrators, panels;
  for (const auto& p : a.points) {
    const std::string integ = p.integrator.empty() ? "mvv" : p.integrator;
    if (std::find(integrators.begin(), integrators.end(), integ) == integrators.end()) integrators.push_back(integ);
    const std::string panel = p.generator + " " + p.noise + (p.gamma > 0 ? " γ=" + detail::num(p.gamma) : "");
    if (std::find(panels.begin(), panels.end(), panel) == panels.end()) panels.push_back(panel);
  }
  c.panels = panels;
  c.key = "off";  // the title says what a cross means; the colour box what a colour does
  c.extra = std::string("set cblabel ") + detail::q(std::string(q.what) + " [" + q.unit + "]") + " noenhanced\n" +
            (q.signed_error ? "set cbrange [-5:5]\nset palette defined (-5 '#2166AC', 0 '#F7F7F7', 5 '#B2182B')\n"
                            : "set cbrange [0:10]\nset palette defined (0 '#F7F7F7', 10 '#B2182B')\n") +
            "set yrange [-0.5:" + detail::num(double(integrators.size()) - 0.5) + "]\n";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    Line cells{"error (colour)",
               std::string("using 2:3:(max(") + (q.signed_error ? "-5" : "0") + ", min(" + (q.signed_error ? "5" : "10") +
                   ", $4))):ytic(6) with points pt 5 ps 1.4 palette",
               {}, {}, k};
    Line blown{"every replica blew up", "using 2:3:ytic(6) with points pt 2 ps 1.4 lw 2 lc rgb 'black'", {}, {}, k};
    for (const auto& p : a.points) {
      const std::string panel = p.generator + " " + p.noise + (p.gamma > 0 ? " γ=" + detail::num(p.gamma) : "");
      if (panel != panels[k]) continue;
      const std::string integ = p.integrator.empty() ? "mvv" : p.integrator;
      const double y = double(std::find(integrators.begin(), integrators.end(), integ) - integrators.begin());
      const double stable = p.replicas ? double(p.stable) / double(p.replicas) : NAN;
      Line& l = p.all_blew_up() ? blown : cells;
      l.rows.push_back({p.dt, y, p.all_blew_up() ? NAN : q.value(p), stable});
      l.labels.push_back(integ);
    }
    if (!cells.rows.empty()) c.lines.push_back(std::move(cells));
    if (!blown.rows.empty()) c.lines.push_back(std::move(blown));
  }
  c.extra += "max(a, b) = a > b ? a : b\nmin(a, b) = a < b ? a : b\n";
  return c;
}

// Per integrator, the reference generator under its first noise at the scene's γ: wall seconds per unit of
// simulated time against the signed error of the ranking temperature (configurational for PNHLN), with 95 % CIs.
Chart integrator_panel(const StabilityAnalysis& a, double tolerance) {
  Chart c{"accuracy_cost_integrators",
          "Integrators (reference generator): temperature error against cost, 95 % CIs (PNHLN: T_conf; within 10 %)",
          Axis{"wall time per unit of simulated time (two cells at a time)", "s/τ", Scale::log2},
          Axis{"temperature − 1", "% of k_BT"}, {"seconds_per_time", "error_pct", "ci_pct"}};
  c.extra = detail::margin_band(100 * tolerance, "tolerance");
  const auto ranks = rank_integrators(a, tolerance);
  for (std::size_t k = 0; k < ranks.size(); ++k) {
    const auto& r = ranks[k];
    Line l{r.integrator + (r.ranked_by == Thermometer::configurational ? " (T_conf)" : ""),
           "using 2:3:4 with yerrorlines pt 7 lw 2 lc " + std::to_string(k + 1), {}, {}};
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
              integ + ": " + (conf ? "configurational" : "kinetic") + " temperature against Δt, 95 % CIs (within 10 %)",
              Axis{"time step Δt", "τ"}, Axis{conf ? "T_conf − 1" : "k_BT − 1", "% of k_BT"},
              {"dt", "error_pct", "ci_pct"}};
      c.key = "inside top left";
      c.extra = "set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'\n";
      std::vector<std::string> series;
      for (const auto& r : rows)
        if (r.integrator == integ && std::find(series.begin(), series.end(), r.generator + " " + r.noise) == series.end())
          series.push_back(r.generator + " " + r.noise);
      for (std::size_t k = 0; k < series.size(); ++k) {
        Line l{series[k], "using 2:3:4 with yerrorlines pt 7 lw 2 " + detail::colour_style(series[k]) + " dt " +
                              std::to_string(1 + dash_of(series, k)), {}, {}};
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
  detail::fresh_chart_directory(dir);
  std::vector<Chart> charts;
  for (const auto& q : map_quantities()) charts.push_back(stability_map(a, q));
  charts.push_back(integrator_panel(a, tolerance));
  for (auto& c : crossing_charts(a)) charts.push_back(std::move(c));
  std::vector<std::string> made;
  const bool run = detail::has_gnuplot();
  for (const auto& c : charts)
    if (detail::render(c, dir, run, log)) made.push_back(c.name);
  return made;
}

}  // namespace dpdrng::study
