// The stability study's report: the stability map, the largest accurate Δt per method, accuracy against cost
// per unit of simulated time, and their charts. Every method × Δt has a row, whether or not it blew up.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "dpdrng/study/stability.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {
using detail::fmt;
using detail::num;

std::vector<std::string> methods_of(const StabilityAnalysis& a) {
  std::vector<std::string> out;
  for (const auto& p : a.points)
    if (std::find(out.begin(), out.end(), p.method()) == out.end()) out.push_back(p.method());
  return out;
}

std::vector<double> dts_of(const StabilityAnalysis& a) {
  std::set<double> s;
  for (const auto& p : a.points) s.insert(p.dt);
  return {s.begin(), s.end()};
}

const StabilityPoint* find(const StabilityAnalysis& a, const std::string& method, double dt) {
  for (const auto& p : a.points)
    if (p.method() == method && p.dt == dt) return &p;
  return nullptr;
}

std::string percent(double x) { return fmt("%.2f %%", 100 * x); }

std::string blowup_text(const StabilityPoint& p) {
  if (p.stable == p.replicas) return "";
  std::string s = p.first_blowup_step >= 0 ? "step " + std::to_string(p.first_blowup_step) + ": " : "";
  return s + p.reason;
}

double cell_seconds(const std::vector<CellResult>& cells) {
  double s = 0;
  for (const auto& c : cells) s += c.seconds;
  return s;
}

}  // namespace

std::string stability_csv(const StabilityAnalysis& a) {
  std::ostringstream o;
  o << "method,integrator,generator,noise,dt,replicas,stable,first_blowup_step,reason,temperature,temperature_ci95,"
       "temperature_error,pressure_conservative,pressure_error,diffusion,diffusion_error,rdf_error,"
       "seconds_per_unit_time\n";
  for (const auto& p : a.points) {
    std::string reason = p.reason;
    std::replace(reason.begin(), reason.end(), ',', ';');
    std::replace(reason.begin(), reason.end(), '"', '\'');
    o << p.method() << ',' << p.integrator << ',' << p.generator << ',' << p.noise << ',' << num(p.dt) << ','
      << p.replicas << ',' << p.stable << ',' << (p.first_blowup_step >= 0 ? std::to_string(p.first_blowup_step) : "")
      << ",\"" << reason << "\"," << num(p.temperature) << ',' << num(p.temperature_ci) << ','
      << num(p.temperature_error) << ',' << num(p.pressure_conservative) << ',' << num(p.pressure_error) << ','
      << num(p.diffusion) << ',' << num(p.diffusion_error) << ',' << num(p.rdf_error) << ','
      << num(p.seconds_per_time) << '\n';
  }
  return o.str();
}

std::string stability_map_markdown(const StabilityAnalysis& a) {
  const auto dts = dts_of(a);
  std::ostringstream o;
  o << "| method |";
  for (double dt : dts) o << " Δt " << num(dt) << " |";
  o << "\n|---|";
  for (std::size_t k = 0; k < dts.size(); ++k) o << "---|";
  o << "\n";
  for (const auto& m : methods_of(a)) {
    o << "| " << m << " |";
    for (double dt : dts) {
      const StabilityPoint* p = find(a, m, dt);
      if (!p) {
        o << " (no cell) |";
        continue;
      }
      const bool all = p->stable == p->replicas;
      o << ' ' << (all ? "" : "**") << p->stable << "/" << p->replicas << (all ? "" : "**");
      if (!all && p->first_blowup_step >= 0) o << " @" << p->first_blowup_step;
      o << " |";
    }
    o << "\n";
  }
  o << "\nBlow-ups (the earliest replica of each method × Δt, its step and reason):\n\n";
  bool any = false;
  for (const auto& p : a.points)
    if (p.stable < p.replicas) {
      any = true;
      o << "- " << p.method() << ", Δt " << num(p.dt) << ": " << p.replicas - p.stable << " of " << p.replicas
        << " blew up; " << blowup_text(p) << "\n";
    }
  if (!any) o << "- none\n";
  return o.str();
}

std::string frontier_markdown(const StabilityAnalysis& a) {
  std::ostringstream o;
  o << "| method | largest Δt with \\|⟨k_BT⟩ − 1\\| < 1 % | < 3 % | first Δt with a blow-up | s per unit time at "
       "the 1 % Δt |\n|---|---|---|---|---|\n";
  for (const auto& m : methods_of(a)) {
    const double d1 = largest_accurate_dt(a, m, 0.01), d3 = largest_accurate_dt(a, m, 0.03);
    const double bad = first_unstable_dt(a, m);
    const StabilityPoint* p1 = std::isfinite(d1) ? find(a, m, d1) : nullptr;
    o << "| " << m << " | " << (std::isfinite(d1) ? num(d1) : "none") << " | "
      << (std::isfinite(d3) ? num(d3) : "none") << " | " << (std::isfinite(bad) ? num(bad) : "none in the sweep")
      << " | " << (p1 ? fmt("%.3g", p1->seconds_per_time) : "–") << " |\n";
  }
  return o.str();
}

std::string accuracy_markdown(const StabilityAnalysis& a) {
  std::ostringstream o;
  o << "| method | Δt | stable | ⟨k_BT⟩ ± 95 % | \\|⟨k_BT⟩ − 1\\| | P_c (err vs 23.64) | D (err) | g(r) err | "
       "s per unit time |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : a.points) {
    o << "| " << p.method() << " | " << num(p.dt) << " | " << p.stable << "/" << p.replicas << " | ";
    if (p.stable == 0) {
      o << "blown up: " << blowup_text(p) << " | – | – | – | – | – |\n";
      continue;
    }
    o << fmt("%.4f", p.temperature) << " ± " << fmt("%.4f", p.temperature_ci) << " | " << percent(p.temperature_error)
      << " | " << fmt("%.3f", p.pressure_conservative) << " (" << percent(p.pressure_error) << ") | "
      << fmt("%.4f", p.diffusion) << " (" << percent(p.diffusion_error) << ") | " << percent(p.rdf_error) << " | "
      << fmt("%.3g", p.seconds_per_time) << " |\n";
  }
  return o.str();
}

std::vector<std::string> write_stability_charts(const StabilityAnalysis& a, const fs::path& dir, std::ostream* log) {
  using detail::Chart;
  using detail::Line;
  const auto methods = methods_of(a);
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

fs::path write_stability_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                                const fs::path& study_dir, const ReportOptions& options) {
  const fs::path dir = study_dir / "report";
  fs::create_directories(dir / "charts");
  const StabilityAnalysis a = analyse_stability(config, cells);
  detail::write_text(dir / "stability.csv", stability_csv(a));
  detail::write_text(dir / "cells.csv", detail::cells_csv(cells));
  std::vector<std::string> made;
  if (options.charts) made = write_stability_charts(a, dir / "charts", options.log);
  const auto have = [&](const std::string& n) { return std::find(made.begin(), made.end(), n) != made.end(); };
  const Analysis none = analyse(config, {});
  const auto& s = config.scene;

  std::ostringstream md;
  md << detail::report_header(config, none, cells, "the stability report makes no generator verdicts")
     << detail::unreadable_cells_markdown(options.unreadable);
  md << "A *method* is an integrator (`mvv:λ`: Groot–Warren's modified velocity-Verlet; `shardlow`: Shardlow's S1 "
        "splitting; `scmvv:K`: the self-consistent velocity-Verlet with K dissipative-force iterations, K = 1 being "
        "DPD-VV; `pnhln:μ`: the pairwise Nosé–Hoover–Langevin thermostat, which draws no pair noise and runs with "
        "the MT19937 reference only) with a generator and its noise. Every Δt runs "
     << (s.time > 0 ? "the same simulated time, " + num(s.time) + " (of which " + num(s.equilibrate_time) +
                          " equilibrates), so steps = time / Δt"
                    : std::to_string(s.steps) + " steps")
     << ". The cells' own wall times add up to " << fmt("%.0f", cell_seconds(cells))
     << " s (cells run side by side, so the study took about that over the threads it had). A replica that blows up (non-finite forces, k_BT above 100, or beads closer than 1e-5) stops there: "
        "it has no observables, is counted in every table below, and never contributes a value.\n\n";

  md << "## Stability map\n\n"
     << "Stable replicas / replicas per method and Δt (**bold**: at least one blew up, @ the earliest step).\n\n"
     << stability_map_markdown(a) << "\n";
  if (have("stability_map")) md << detail::chart_link("stability_map", "fraction stable against dt");

  md << "## How large a Δt each method allows\n\n"
     << "The largest Δt at which every replica is stable, at every smaller Δt too, and the replica mean of "
        "k_BT lies within 1 % (3 %) of the thermostat's k_BT = 1; and the smallest Δt at which any replica blew up.\n\n"
     << frontier_markdown(a) << "\n";

  md << "## Accuracy against cost per unit of simulated time\n\n"
     << "Replica means over the stable replicas. References: k_BT = 1 (the thermostat's); the conservative-virial "
        "pressure P_c = 23.64 at ρ = 3, a = 25, k_BT = 1 (Allen & Tildesley's DPD example, 23.636(2) with "
        "Shardlow's scheme and 23.635(3) with the Lowe thermostat; Groot & Warren's 1997 fit p = ρk_BT + αaρ², "
        "α = 0.101, is for the total pressure, 25.7 here); D and g(r) against the MT19937 cells at the smallest "
        "Δt ("
     << num(a.reference_dt) << ", " << a.reference_cells
     << " stable cells pooled over the integrators; g(r) error: mean relative deviation where g_ref ≥ 0.1). Cost: "
        "median wall seconds of a step / Δt over the stable replicas (cells ran side by side, so absolute times "
        "carry the machine's load). A method × Δt whose replicas all blew up has a row and a red mark on the "
        "charts' top edge, never a value.\n\n"
     << accuracy_markdown(a) << "\n";
  for (const char* n : {"temperature", "pressure", "diffusion", "rdf"})
    if (have(std::string("accuracy_cost_") + n))
      md << detail::chart_link(std::string("accuracy_cost_") + n, std::string("accuracy against cost: ") + n);

  md << detail::broken_cells_markdown(cells);
  md << "\n## Files\n\n`stability.csv` (one row per method × Δt), `cells.csv` (every scalar of every cell); charts "
        "in `charts/` (SVG, PNG and the gnuplot script of each); all data in `../study.h5`.\n";
  detail::write_text(dir / "report.md", md.str());
  return dir / "report.md";
}

}  // namespace dpdrng::study
