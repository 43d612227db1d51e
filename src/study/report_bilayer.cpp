// report.md for the membrane scene: the bilayer's observables per generator with CIs, their paired differences
// from MT19937 with their tests, and the profile and CI charts.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "dpdrng/study/report.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {

using detail::fmt;

std::string with_ci(const ReplicaMean& m) {
  if (m.n == 0) return "–";
  return fmt("%.4f", m.mean) + " ± " + fmt("%.4f", m.ci95) + (m.from_run_sem ? "†" : "");
}

const char* label_of(const std::string& observable) {
  for (const auto& o : bilayer_observables())
    if (observable == o.name) return o.label;
  if (observable == "head_profile_vs_mt") return "H profile";
  if (observable == "tail_profile_vs_mt") return "T profile";
  if (observable == "water_profile_vs_mt") return "W profile";
  return observable.c_str();
}

}  // namespace

std::string bilayer_table_markdown(const Analysis& a, const std::string& distribution) {
  std::ostringstream o;
  o << "| generator | replicas |";
  for (const auto& b : bilayer_observables()) o << ' ' << b.label << " |";
  o << "\n|---|---|";
  for (std::size_t k = 0; k < bilayer_observables().size(); ++k) o << "---|";
  o << '\n';
  for (const auto& v : a.variants) {
    if (v.key.noise() != distribution) continue;
    o << "| " << v.key.label_and_seeding() << " | " << v.cells.size() << (v.broken.empty() ? "" : " (+" + std::to_string(v.broken.size()) + " broken)")
      << " |";
    for (const auto& b : bilayer_observables())
      o << ' ' << with_ci(replica_mean(v.cells, b.key, b.sem)) << " |";
    o << '\n';
  }
  return o.str();
}

std::string bilayer_table_csv(const Analysis& a) {
  std::ostringstream o;
  o << "generator,rounds,distribution,seeding,dt,observable,replicas,mean,ci95,ci_from_run_sem\n";
  for (const auto& v : a.variants)
    for (const auto& b : bilayer_observables()) {
      const ReplicaMean m = replica_mean(v.cells, b.key, b.sem);
      o << v.key.generator << ',' << v.key.rounds << ',' << v.key.noise() << ','
        << v.key.seeding_name() << ',' << detail::num(v.key.dt) << ',' << b.name << ','
        << m.n << ',' << detail::num(m.mean) << ',' << detail::num(m.ci95) << ',' << int(m.from_run_sem) << '\n';
    }
  return o.str();
}

std::string bilayer_differences_markdown(const Analysis& a, const std::string& distribution) {
  std::ostringstream o;
  o << "| generator | observable | value | MT | difference [95 % CI] | 1σ | paired-t p | corrected p |\n"
       "|---|---|---|---|---|---|---|---|\n";
  std::ostringstream curves;
  curves << "| generator | profile | mean relative deviation from MT | F (d) | p | corrected p |\n"
            "|---|---|---|---|---|---|\n";
  bool any_curve = false;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.key.noise() != distribution) continue;
    for (const auto& c : v.observables) {
      const std::string b = c.decision.differs ? "**" : "";
      const std::string corrected = detail::p_text(c.decision.p_adjusted);
      if (!c.available) {
        o << "| " << v.key.label_and_seeding() << " | " << label_of(c.observable) << " | – | – | – | – | – | " << c.note << " |\n";
        continue;
      }
      if (!c.paired) {
        any_curve = true;
        curves << "| " << v.key.label_and_seeding() << " | " << label_of(c.observable) << " | " << b << fmt("%.2e", c.error_rate)
               << b << " | " << fmt("%.2f", c.statistic) << " (" << fmt("%.1f", c.dof) << ") | "
               << detail::p_text(c.decision.p) << " | " << corrected << " |\n";
        continue;
      }
      o << "| " << v.key.label_and_seeding() << " | " << label_of(c.observable) << " | " << fmt("%.4f", c.value) << " | "
        << fmt("%.4f", c.ref) << " | " << b << fmt("%+.4f", c.diff) << b << " [± " << fmt("%.4f", c.diff_ci) << "] | "
        << fmt("%.4f", c.sigma) << " | " << detail::p_text(c.decision.p) << " | " << corrected << " |\n";
    }
  }
  if (any_curve) o << '\n' << curves.str();
  return o.str();
}

std::string bilayer_differences_csv(const Analysis& a) {
  std::ostringstream o;
  o << "generator,rounds,distribution,seeding,dt,observable,replicas,value,value_sd,reference_replicas,reference,"
       "reference_sd,pairs,difference,difference_ci95,sigma,test,statistic,dof,p_value,p_adjusted,differs\n";
  for (const auto& v : a.variants)
    for (const auto& c : v.observables)
      o << v.key.generator << ',' << v.key.rounds << ',' << v.key.noise() << ',' << v.key.seeding_name() << ','
        << detail::num(v.key.dt) << ',' << c.observable << ',' << c.n << ',' << detail::num(c.value) << ','
        << detail::num(c.value_sd) << ',' << c.n_ref << ',' << detail::num(c.ref) << ',' << detail::num(c.ref_sd)
        << ',' << c.n_pairs << ',' << detail::num(c.paired ? c.diff : c.error_rate) << ','
        << detail::num(c.diff_ci) << ',' << detail::num(c.sigma) << ',' << c.test << ','
        << detail::num(c.statistic) << ',' << detail::num(c.dof) << ',' << detail::p_csv(c.decision.p) << ','
        << detail::p_csv(c.decision.p_adjusted) << ',' << int(c.decision.differs) << '\n';
  return o.str();
}

fs::path write_bilayer_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                              const fs::path& study_dir, const ReportOptions& options) {
  const fs::path dir = study_dir / "report";
  fs::create_directories(dir / "charts");
  const Analysis a = analyse(config, cells);
  const std::vector<std::string> dists = detail::distributions_of(a);

  detail::write_text(dir / "summary.csv", summary_csv(a));
  detail::write_text(dir / "bilayer_table.csv", bilayer_table_csv(a));
  detail::write_text(dir / "bilayer_differences.csv", bilayer_differences_csv(a));
  detail::write_text(dir / "verdicts.csv", verdicts_csv(a));
  detail::write_text(dir / "zeta.csv", zeta_csv(a));
  const std::vector<BudgetRow> budget = error_budget(a, config.scene.kT);
  detail::write_text(dir / "error_budget.csv", error_budget_csv(budget));
  detail::write_text(dir / "cells.csv", detail::cells_csv(cells));
  std::vector<std::string> made;
  if (options.charts) made = write_bilayer_charts(a, dir / "charts", options.log);
  const auto have = [&](const std::string& n) { return std::find(made.begin(), made.end(), n) != made.end(); };

  std::ostringstream md;
  const std::string limit = detection_limit_sentence(config, detail::calibrations(study_dir, options));
  md << detail::report_header(config, a, cells, limit)
     << detail::unreadable_cells_markdown(options.unreadable);
  md << "## Verdicts\n\n"
     << "Each generator is compared with MT19937 run with identical settings from the same initial states (one per "
        "replica). *Differs* means an observable differs at α = "
     << a.alpha
     << " under the error control stated above (paired t-tests across replicas for the scalars, L² F tests for "
        "the density profiles). The membrane's observables have no equivalence margins, so a generator that does "
        "not differ is *inconclusive*: nothing shows it equivalent. *Smallest corrected p*: the smallest "
        "P-value after that correction, below α exactly when the verdict says *differs*. Bilayer cells tap no raw "
        "numbers: the generators' χ², lag-1 t and NIST results are the water study's.\n\n- "
     << a.error_model_sentence() << "\n\n"
     << summary_markdown(a) << "\n";

  md << "## Membrane observables per generator\n\n"
     << "Replica means ± 95 % confidence half-widths (Student t over the replicas; † = a single replica, 1.96 × the "
        "run's own block standard error). T: kinetic k_BT; T_α: its component along α (Σv_α²/(N − 1)); P_αα: "
        "pressure tensor including the bond and bending virials; P_xx − P_yy: the in-plane anisotropy, averaged "
        "step by step (0 by symmetry about the normal z; P_zz differs by the tension); Σ = L_z[P_zz − (P_xx + P_yy)/2] "
        "(positive = stretched); thickness: distance between the two "
        "head-density peaks; order: P2 = ⟨3cos²θ − 1⟩/2 of the tail bonds against the normal.\n\n";
  for (const auto& d : dists) {
    md << "### " << d << "\n\n" << bilayer_table_markdown(a, d) << "\n";
    for (const auto& b : bilayer_observables())
      if (const std::string n = std::string("bilayer_") + b.name + "_" + d;
          have(n) && (std::string(b.name) == "temperature" || std::string(b.name) == "tension"))
        md << detail::chart_link(n, std::string(b.what) + " per generator, " + d);
  }

  md << "## Differences from MT19937\n\n"
     << "difference = mean over replicas of (generator − MT) on the same initial state, with its 95 % CI and the "
        "paired t-test, whose variance pools the differences' spread with the runs' own block standard errors; 1σ = the standard error of the difference. **Bold** = differs at α = "
     << a.alpha << " after the error control. Density profiles: mean relative deviation of the generator's mean "
        "profile from MT's over bins above a tenth of the peak, and the L² F test of the replicas' profiles with "
        "its effective number of independent bins d.\n\n";
  for (const auto& d : dists) md << "### " << d << "\n\n" << bilayer_differences_markdown(a, d) << "\n";

  md << "## Error budget: noise error against integrator error\n\n"
     << error_budget_text(config.scene.kT) << "\n" << error_budget_markdown(budget) << "\n";

  md << "## Density profiles\n\n";
  bool any_profile = false;
  for (const auto& d : dists)
    if (have("bilayer_profiles_" + d)) {
      md << detail::chart_link("bilayer_profiles_" + d, "H, T and W density profiles relative to the midplane, " + d);
      any_profile = true;
    }
  if (!any_profile) md << "(no chart: none stored yet, or charts were not requested)\n\n";
  md << "Every observable per generator with its CI: ";
  bool first = true;
  for (const auto& d : dists)
    for (const auto& b : bilayer_observables())
      if (const std::string n = std::string("bilayer_") + b.name + "_" + d; have(n)) {
        md << (first ? "" : ", ") << "[" << b.label << " " << d << "](charts/" << n << ".svg)";
        first = false;
      }
  md << (first ? "none.\n\n" : ".\n\n");

  md << "## Cost\n\n"
     << "Step time: wall time of the run / steps (cells ran side by side, so absolute times carry the machine's "
        "load); ns per number: the engine's calibration of generator + distribution.\n\n"
     << cost_markdown(a) << "\n";

  md << detail::broken_cells_markdown(cells);
  md << "\n## Files\n\n"
     << "`summary.csv`, `verdicts.csv` (one row per generator × observable and per generator), `error_budget.csv`, "
        "`bilayer_table.csv` (means and CIs), `bilayer_differences.csv` (differences and their tests), `zeta.csv` "
        "(the force's weighted ⟨ζ²⟩ and the temperature shift its effective power predicts beside the measured one), "
        "`cells.csv` (every scalar of every cell); charts in `charts/` (SVG and PNG, each drawn by its "
        "gnuplot script from the CSV beside it); all data in `../study.h5` (each cell's profile/z, profile/head, profile/tail, profile/water).\n";
  detail::write_text(dir / "report.md", md.str());
  return dir / "report.md";
}

}  // namespace dpdrng::study
