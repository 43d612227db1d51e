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

std::string dt_list(const std::vector<double>& v, const char* sep) {
  std::string out;
  for (double d : v) out += (out.empty() ? "" : sep) + num(d);
  return out;
}

// "1.0123 ± 0.0045"; "–" when there is no value.
std::string pm(double m, double h) {
  if (!std::isfinite(m)) return "–";
  return fmt("%.4f", m) + " ± " + (std::isfinite(h) ? fmt("%.4f", h) : std::string("n/a"));
}
std::string pm_percent(double m, double h) {
  if (!std::isfinite(m)) return "–";
  return fmt("%+.2f", 100 * m) + " ± " + (std::isfinite(h) ? fmt("%.2f", 100 * h) : std::string("n/a")) + " %";
}

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
       "seconds_per_unit_time,gamma,temperature_conf,temperature_conf_ci95,pressure_ref_error,step_seconds\n";
  for (const auto& p : a.points) {
    std::string reason = p.reason;
    std::replace(reason.begin(), reason.end(), ',', ';');
    std::replace(reason.begin(), reason.end(), '"', '\'');
    o << p.method() << ',' << p.integrator << ',' << p.generator << ',' << p.noise << ',' << num(p.dt) << ','
      << p.replicas << ',' << p.stable << ',' << (p.first_blowup_step >= 0 ? std::to_string(p.first_blowup_step) : "")
      << ",\"" << reason << "\"," << num(p.temperature) << ',' << num(p.temperature_ci) << ','
      << num(p.temperature_error) << ',' << num(p.pressure_conservative) << ',' << num(p.pressure_error) << ','
      << num(p.diffusion) << ',' << num(p.diffusion_error) << ',' << num(p.rdf_error) << ','
      << num(p.seconds_per_time) << ',' << (p.gamma > 0 ? num(p.gamma) : "") << ',' << num(p.temperature_conf) << ','
      << num(p.temperature_conf_ci) << ',' << num(p.pressure_ref_error) << ',' << num(p.step_seconds) << '\n';
  }
  return o.str();
}

std::string frontier_csv(const StabilityAnalysis& a, double tolerance) {
  std::ostringstream o;
  o << "method,thermometer,tolerance,inside,outside,outside_below,first_blowup_dt\n";
  for (const auto& m : stability_methods(a))
    for (const Thermometer t : {Thermometer::kinetic, Thermometer::configurational}) {
      const Frontier f = accuracy_frontier(a, m, t, tolerance);
      o << m << ',' << to_string(t) << ',' << num(tolerance) << ',' << num(f.inside) << ',' << num(f.outside) << ','
        << dt_list(f.outside_below, ";") << ',' << num(first_unstable_dt(a, m)) << '\n';
    }
  return o.str();
}

std::string ranking_csv(const std::vector<IntegratorRank>& r) {
  std::ostringstream o;
  o << "rank,integrator,method,ranked_by,kinetic_inside,kinetic_outside,configurational_inside,"
       "configurational_outside,step_seconds,relative_step_cost,seconds_per_unit_time_at_frontier,jdpd_factor\n";
  for (std::size_t k = 0; k < r.size(); ++k)
    o << k + 1 << ',' << r[k].integrator << ',' << r[k].method << ',' << to_string(r[k].ranked_by) << ','
      << num(r[k].kinetic.inside) << ',' << num(r[k].kinetic.outside) << ',' << num(r[k].configurational.inside)
      << ',' << num(r[k].configurational.outside) << ',' << num(r[k].step_seconds) << ','
      << num(r[k].relative_step_cost) << ',' << num(r[k].seconds_per_time) << ',' << num(r[k].jdpd_factor) << '\n';
  return o.str();
}

std::string crossing_csv(const std::vector<CrossingRow>& rows) {
  std::ostringstream o;
  o << "integrator,generator,noise,dt,temperature,temperature_ci95,temperature_conf,temperature_conf_ci95,"
       "noise_shift,noise_shift_ci95,integrator_error,integrator_error_ci95,cancellation\n";
  for (const auto& r : rows)
    o << r.integrator << ',' << r.generator << ',' << r.noise << ',' << num(r.dt) << ',' << num(r.temperature) << ','
      << num(r.temperature_ci) << ',' << num(r.temperature_conf) << ',' << num(r.temperature_conf_ci) << ','
      << num(r.noise_shift) << ',' << num(r.noise_shift_ci) << ',' << num(r.integrator_error) << ','
      << num(r.integrator_error_ci) << ",\"" << r.cancellation << "\"\n";
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
  for (const auto& m : stability_methods(a)) {
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

std::string frontier_markdown(const StabilityAnalysis& a, double tolerance) {
  std::ostringstream o;
  o << "| method | k_BT frontier | k_BT outside below it | T_conf frontier | T_conf outside below it | first Δt with a "
       "blow-up |\n|---|---|---|---|---|---|\n";
  for (const auto& m : stability_methods(a)) {
    const Frontier k = accuracy_frontier(a, m, Thermometer::kinetic, tolerance);
    const Frontier c = accuracy_frontier(a, m, Thermometer::configurational, tolerance);
    const double bad = first_unstable_dt(a, m);
    o << "| " << m << " | " << bracket_text(k) << " | " << (k.outside_below.empty() ? "–" : dt_list(k.outside_below, ", "))
      << " | " << bracket_text(c) << " | " << (c.outside_below.empty() ? "–" : dt_list(c.outside_below, ", ")) << " | "
      << (std::isfinite(bad) ? num(bad) : "none in the sweep") << " |\n";
  }
  return o.str();
}

std::string ranking_markdown(const std::vector<IntegratorRank>& r, double tolerance) {
  std::ostringstream o;
  o << "| rank | integrator | ranked by | frontier (±" << num(100 * tolerance)
    << " %) of the ranking temperature | k_BT frontier | T_conf frontier | s per step | step cost / GW-MVV's | "
       "s per unit time at the frontier | Jdpd's factor |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < r.size(); ++k) {
    const Frontier& f = r[k].ranked_by == Thermometer::kinetic ? r[k].kinetic : r[k].configurational;
    o << "| " << k + 1 << " | " << r[k].integrator << " | " << to_string(r[k].ranked_by) << " | " << bracket_text(f)
      << " | " << bracket_text(r[k].kinetic) << " | " << bracket_text(r[k].configurational) << " | "
      << fmt("%.3g", r[k].step_seconds) << " | " << fmt("%.2f", r[k].relative_step_cost) << " | "
      << fmt("%.3g", r[k].seconds_per_time) << " | "
      << (std::isfinite(r[k].jdpd_factor) ? fmt("%.1f", r[k].jdpd_factor) : std::string("not sourced")) << " |\n";
  }
  return o.str();
}

std::string crossing_markdown(const std::vector<CrossingRow>& rows) {
  std::ostringstream o;
  o << "| integrator | generator | noise | Δt | ⟨k_BT⟩ ± 95 % | ⟨T_conf⟩ ± 95 % | noise error (variant − reference) | "
       "integrator error (reference − 1) | cancel |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    if (!std::isfinite(r.temperature)) continue;
    o << "| " << r.integrator << " | " << r.generator << " | " << r.noise << " | " << num(r.dt) << " | "
      << pm(r.temperature, r.temperature_ci) << " | " << pm(r.temperature_conf, r.temperature_conf_ci) << " | "
      << pm_percent(r.noise_shift, r.noise_shift_ci) << " | " << pm_percent(r.integrator_error, r.integrator_error_ci)
      << " | " << r.cancellation << " |\n";
  }
  o << "\nWhere the two errors cancel (resolved, of opposite signs, and the variant's CI of k_BT holds 1):\n\n";
  bool any = false;
  for (const auto& r : rows)
    if (r.cancellation == "full") {
      any = true;
      o << "- " << r.integrator << " " << r.generator << " " << r.noise << " at Δt " << num(r.dt) << ": noise error "
        << pm_percent(r.noise_shift, r.noise_shift_ci) << " against integrator error "
        << pm_percent(r.integrator_error, r.integrator_error_ci) << ", k_BT " << pm(r.temperature, r.temperature_ci)
        << "\n";
    }
  if (!any) o << "- nowhere in the sweep\n";
  return o.str();
}

std::string gamma_series_markdown(const StabilityAnalysis& a, double tolerance) {
  std::ostringstream o;
  bool any = false;
  for (const auto& m : stability_methods(a)) {
    const StabilityPoint* p = nullptr;
    for (const auto& q : a.points)
      if (q.method() == m) p = &q;
    if (!p || p->gamma == 0) continue;
    if (!any)
      o << "| integrator | γ | k_BT frontier | T_conf frontier | at the scene's γ: k_BT | T_conf |\n"
           "|---|---|---|---|---|---|\n";
    any = true;
    StabilityPoint same = *p;
    same.gamma = 0;
    const std::string base = same.method();
    o << "| " << (p->integrator.empty() ? "mvv" : p->integrator) << " | " << num(p->gamma) << " | "
      << bracket_text(accuracy_frontier(a, m, Thermometer::kinetic, tolerance)) << " | "
      << bracket_text(accuracy_frontier(a, m, Thermometer::configurational, tolerance)) << " | "
      << bracket_text(accuracy_frontier(a, base, Thermometer::kinetic, tolerance)) << " | "
      << bracket_text(accuracy_frontier(a, base, Thermometer::configurational, tolerance)) << " |\n";
  }
  return o.str();
}

std::string accuracy_markdown(const StabilityAnalysis& a) {
  std::ostringstream o;
  o << "| method | Δt | stable | ⟨k_BT⟩ ± 95 % | \\|⟨k_BT⟩ − 1\\| | ⟨T_conf⟩ ± 95 % | P_c (err vs 23.64) | P_c err "
       "vs reference | D (err) | g(r) err | s per unit time |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : a.points) {
    o << "| " << p.method() << " | " << num(p.dt) << " | " << p.stable << "/" << p.replicas << " | ";
    if (p.stable == 0) {
      o << "blown up: " << blowup_text(p) << " | – | – | – | – | – | – | – |\n";
      continue;
    }
    o << pm(p.temperature, p.temperature_ci) << " | " << percent(p.temperature_error) << " | "
      << pm(p.temperature_conf, p.temperature_conf_ci) << " | " << fmt("%.3f", p.pressure_conservative) << " ("
      << percent(p.pressure_error) << ") | " << percent(p.pressure_ref_error) << " | "
      << fmt("%.4f", p.diffusion) << " (" << percent(p.diffusion_error) << ") | " << percent(p.rdf_error) << " | "
      << fmt("%.3g", p.seconds_per_time) << " |\n";
  }
  return o.str();
}

namespace {

// The sentence that sets Shardlow's frontier against GW-MVV λ = 0.65's, both with the reference generator.
std::string shardlow_against_mvv065(const std::vector<IntegratorRank>& ranks) {
  const IntegratorRank *sh = nullptr, *mv = nullptr;
  for (const auto& r : ranks) {
    if (r.integrator == "shardlow") sh = &r;
    if (r.integrator == "mvv:0.65") mv = &r;
  }
  if (!sh || !mv) return "";
  const Frontier &f = sh->kinetic, &g = mv->kinetic;
  std::string verdict;
  if (std::isfinite(f.outside) && std::isfinite(g.inside) && f.outside <= g.inside)
    verdict = "Shardlow's lies below: its splitting leaves ±1 % at a smaller Δt than GW-MVV with λ = 0.65";
  else if (std::isfinite(g.outside) && std::isfinite(f.inside) && g.outside <= f.inside)
    verdict = "Shardlow's lies above";
  else
    verdict = "the two overlap: the CIs do not order them";
  return "Shardlow's k_BT frontier (" + bracket_text(f) + ") against GW-MVV λ = 0.65's (" + bracket_text(g) +
         ") with the reference generator: " + verdict + ". λ = 0.65 is Groot & Warren's choice because its velocity prediction cancels part of the integrator's "
         "heating at their γ = 4.5; the friction series below shows whether that cancellation holds "
         "there, and the scene's γ rows whether it survives the larger friction.\n\n";
}

std::string cpu_text(const StabilityAnalysis& a) {
  if (a.cpus.empty()) return "not recorded by the cells";
  std::string out;
  for (const auto& c : a.cpus) out += (out.empty() ? "" : "; ") + c;
  return out;
}

}  // namespace

fs::path write_stability_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                                const fs::path& study_dir, const ReportOptions& options) {
  constexpr double kTolerance = 0.01;
  const fs::path dir = study_dir / "report";
  fs::create_directories(dir / "charts");
  const StabilityAnalysis a = analyse_stability(config, cells);
  const auto ranks = rank_integrators(a, kTolerance);
  const auto crossing = crossing_rows(a);
  detail::write_text(dir / "stability.csv", stability_csv(a));
  detail::write_text(dir / "frontier.csv", frontier_csv(a, kTolerance));
  detail::write_text(dir / "ranking.csv", ranking_csv(ranks));
  detail::write_text(dir / "crossing.csv", crossing_csv(crossing));
  detail::write_text(dir / "cells.csv", detail::cells_csv(cells));
  std::vector<std::string> made;
  if (options.charts) made = write_stability_charts(a, kTolerance, dir / "charts", options.log);
  const auto have = [&](const std::string& n) { return std::find(made.begin(), made.end(), n) != made.end(); };
  const Analysis none = analyse(config, {});
  const auto& s = config.scene;

  std::ostringstream md;
  md << detail::report_header(config, none, cells, "the stability report makes no generator verdicts")
     << detail::unreadable_cells_markdown(options.unreadable);
  md << "A *method* is an integrator (`mvv:λ`: Groot–Warren's modified velocity-Verlet; `shardlow`: Shardlow's S1 "
        "splitting; `scmvv:K`: the self-consistent velocity-Verlet with K dissipative-force iterations, K = 1 being "
        "DPD-VV; `pnhln:μ`: the pairwise Nosé–Hoover–Langevin thermostat, which draws no pair noise and runs with "
        "the MT19937 reference only) with a generator and its noise"
     << (config.reference_gammas.empty() ? std::string("")
                                         : "; a method marked γX runs the reference at friction γ = X instead of the "
                                           "scene's γ = " + num(s.gamma))
     << ". Every Δt runs "
     << (s.time > 0 ? "the same simulated time, " + num(s.time) + " (of which " + num(s.equilibrate_time) +
                          " equilibrates), so steps = time / Δt"
                    : std::to_string(s.steps) + " steps")
     << ". The cells' own wall times add up to " << fmt("%.0f", cell_seconds(cells))
     << " s (cells run side by side, so the study took about that over the threads it had). *Stable* means no "
        "blow-up within the run: a replica blows up on non-finite forces, k_BT above 100, or beads closer than "
        "1e-5, stops there, has no observables, is counted in every table below, and never contributes a value. "
        "Accuracy is judged separately, from the CIs.\n\n";

  md << "## Stability map\n\n"
     << "Stable replicas / replicas per method and Δt (**bold**: at least one blew up, @ the earliest step).\n\n"
     << stability_map_markdown(a) << "\n";
  if (have("stability_map"))
    md << detail::chart_link("stability_map", "k_BT − 1 by Δt and integrator, per generator and noise");

  md << "## Accuracy frontiers\n\n"
     << "Per method and thermometer, the bracket *inside – outside*: *inside* is the largest Δt whose 95 % CI of the "
        "replica mean lies within 1 ± "
     << num(100 * kTolerance)
     << " % with every replica stable; *outside* the smallest Δt above it whose CI lies wholly outside the band or "
        "at which a replica blew up. The frontier lies between them; Δt in between have CIs that straddle the "
        "band's edge (more replicas would resolve them). A Δt below *inside* whose CI lies wholly outside is listed: "
        "an accurate Δt above an inaccurate one is errors cancelling, not accuracy. k_BT is the kinetic temperature, "
        "T_conf the configurational one (Rugh's ⟨|∇U|²⟩/⟨∇²U⟩ over the conservative potential). A CI is Student's t "
        "on one replica's variance pooled over every method at the same integrator, Δt and γ (the generators and "
        "noises change the temperature, not how much a run of this length scatters), unless the point's own "
        "replicas vary more than that pool (one-sided F test at 5 %). From `frontier.csv`."
        "\n\n"
     << frontier_markdown(a, kTolerance) << "\n";

  md << "## The integrators ranked\n\n"
     << "Each integrator with the reference generator under its first noise at γ = " << num(s.gamma)
     << ", ranked by the *inside* Δt of its ±" << num(100 * kTolerance)
     << " % frontier (configurational for PNHLN, whose thermostat acts on the momenta and pins the kinetic "
        "temperature; kinetic for the others), then by the wall seconds per unit of simulated time at that Δt. "
        "Step seconds: the median over the method's stable points of each point's median step time; measured on "
     << cpu_text(a)
     << ", cells running side by side, so the absolute times carry the machine's load and the ratios are the "
        "comparable figures. Jdpd's factors: the relative computation times Jdpd (the Java DPD kernel of van den "
        "Broek, Kuhn & Zielesny, J. Cheminform. 10, 25 (2018)) names for its integration types, GW-MVV = 1, as "
        "quoted, not re-measured here; \"not sourced\" where it names none. From `ranking.csv`.\n\n"
     << ranking_markdown(ranks, kTolerance) << "\n"
     << shardlow_against_mvv065(ranks);
  if (have("accuracy_cost_integrators"))
    md << detail::chart_link("accuracy_cost_integrators", "integrators: temperature error against cost");

  if (const std::string g = gamma_series_markdown(a, kTolerance); !g.empty())
    md << "## The friction series\n\n"
       << "The reference generator alone at the friction of `[sweep] reference_gammas`, beside the same integrator "
          "at the scene's γ = "
       << num(s.gamma)
       << " (±" << num(100 * kTolerance)
       << " % brackets as above). Groot & Warren (1997) chose λ = 0.65 from runs at γ = 4.5 (σ = 3); their "
          "temperatures are not transcribed here, so the comparison with their figure is left to the reader. From "
          "`frontier.csv`.\n\n"
       << g << "\n";

  md << "## The crossing: noise error against integrator error\n\n"
     << "For every integrator that draws pair noise (not PNHLN) at γ = " << num(s.gamma)
     << ": each generator × noise against Δt. Noise error: the variant's ⟨k_BT⟩ − the reference's at the same "
        "integrator, noise and Δt; integrator error: the reference's ⟨k_BT⟩ − 1; each ± the 95 % half-width "
        "√(h₁² + h₂²) of its replica means. They *cancel* when both are resolved (CI clear of 0) and of opposite "
        "signs: fully when the variant's CI of k_BT then holds 1 (a defective generator reading the right "
        "temperature), partly otherwise. Only the comparison with the reference at the same settings separates "
        "the two errors. From `crossing.csv`.\n\n"
     << "Rows with no stable replica are left out here (they are in `crossing.csv` and the stability map).\n\n"
     << crossing_markdown(crossing) << "\n";
  for (const auto& n : made)
    if (n.rfind("crossing_", 0) == 0) md << detail::chart_link(n, n);

  md << "## Accuracy against cost per unit of simulated time\n\n"
     << "Replica means over the stable replicas. References: k_BT = 1 (the thermostat's); the conservative-virial "
        "pressure P_c = 23.64 at ρ = 3, a = 25, k_BT = 1 (Allen & Tildesley's DPD example, 23.636(2) with "
        "Shardlow's scheme and 23.635(3) with the Lowe thermostat; Groot & Warren's 1997 fit p = ρk_BT + αaρ², "
        "α = 0.101, is for the total pressure, 25.7 here). The integrator error of P_c, D and g(r) is measured "
        "against the MT19937 cells at the smallest Δt, "
     << num(a.reference_dt) << " (" << a.reference_cells << " stable cells at γ = " << num(s.gamma)
     << " pooled over the integrators: P_c = " << fmt("%.4f", a.reference_pressure)
     << ", D = " << fmt("%.5f", a.reference_diffusion)
     << "; g(r) error: mean relative deviation where g_ref ≥ 0.1). Cost: median wall seconds of a step / Δt over "
        "the stable replicas. A method × Δt whose replicas all blew up has a row and a cross on the maps, never a "
        "value. The maps show each error by Δt and integrator, a panel per generator and noise (colour clipped "
        "at 10 %). From `stability.csv`.\n\n"
     << accuracy_markdown(a) << "\n";
  for (const char* n : {"pressure", "diffusion", "rdf"})
    if (have(std::string("stability_map_") + n))
      md << detail::chart_link(std::string("stability_map_") + n, std::string("error map: ") + n);

  md << detail::broken_cells_markdown(cells);
  md << "\n## Files\n\n`stability.csv` (one row per method × Δt), `frontier.csv` (each method's brackets), "
        "`ranking.csv` (the integrators ranked), `crossing.csv` (noise error against integrator error), `cells.csv` "
        "(every scalar of every cell); charts in `charts/` (SVG and PNG, each drawn by its gnuplot script from the CSV beside it); all data in "
        "`../study.h5`.\n";
  detail::write_text(dir / "report.md", md.str());
  return dir / "report.md";
}

}  // namespace dpdrng::study
