// report.md: the tables and charts of one study, with what each verdict rests on.
#include "dpdrng/study/report.hpp"
#include "dpdrng/study/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>

#include "dpdrng/common/output.hpp"
#include "dpdrng/study/stability.hpp"
#include "dpdrng/study/store.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;

namespace detail {

void write_text(const fs::path& p, const std::string& text) { write_text_file(p, text); }

std::string num(double x) {
  if (!std::isfinite(x)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string fmt(const char* f, double x) {
  if (!std::isfinite(x)) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

std::string p_text(double p) {
  if (!std::isfinite(p)) return "–";
  if (p < kPFloor) return "< 1e-12";
  return fmt("%.2g", p);
}

std::string p_csv(double p) {
  if (std::isfinite(p) && p < kPFloor) return "<1e-12";
  return num(p);
}

std::vector<std::string> distributions_of(const Analysis& a) {
  std::vector<std::string> dists;
  for (const auto& v : a.variants)
    if (std::find(dists.begin(), dists.end(), v.key.noise()) == dists.end()) dists.push_back(v.key.noise());
  return dists;
}

// Every scalar of every cell, one row a cell: the flat view for spreadsheets.
std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    line += csv_quote(fields[i]);
  }
  return line + '\n';
}

std::string cells_csv(const std::vector<CellResult>& cells) {
  std::set<std::string> names;
  for (const auto& c : cells)
    for (const auto& [k, v] : c.scalars) names.insert(k);
  std::ostringstream o;
  o << "id,generator,rounds,distribution,feed,seeding,dt,integrator,replica,status,unstable_step,seconds";
  for (const auto& n : names) o << ',' << n;
  o << '\n';
  for (const auto& c : cells) {
    o << c.cell.id() << ',' << c.cell.generator << ',' << c.cell.rounds << ',' << rng::to_string(c.cell.distribution)
      << ',' << rng::to_string(c.cell.feed) << ',' << c.cell.seeding_name() << ',' << num(c.cell.dt) << ','
      << c.cell.integrator << ',' << c.cell.replica << ',' << to_string(c.status) << ','
      << c.unstable_step << ',' << num(c.seconds);
    for (const auto& n : names) o << ',' << (c.has(n) ? num(c.scalar(n, NAN)) : "");
    o << '\n';
  }
  return o.str();
}

std::string chart_link(const std::string& name, const std::string& alt) {
  return "![" + alt + "](charts/" + name + ".png)  \n[SVG](charts/" + name + ".svg) · [data](charts/" + name + ".csv) · [gnuplot script](charts/" +
         name + ".gp)\n\n";
}

namespace {
// The sweep's integrators replace the scene's λ, which then applies to no cell.
std::string integrator_text(const StudyConfig& config) {
  if (config.integrators.empty()) return "λ = " + num(config.scene.lambda);
  std::string list;
  for (const auto& i : config.integrators) list += (list.empty() ? "" : ", ") + i;
  return "integrators swept: " + list;
}
}  // namespace

std::string report_header(const StudyConfig& config, const Analysis& a, const std::vector<CellResult>& cells,
                          const std::string& detection_limit) {
  const std::size_t expected = enumerate_cells(config).size();
  std::size_t unstable = 0, failed = 0, disrupted = 0;
  for (const auto& c : cells)
    unstable += c.status == CellStatus::unstable, failed += c.status == CellStatus::failed,
    disrupted += c.status == CellStatus::disrupted;
  const auto& s = config.scene;
  std::ostringstream md;
  const std::time_t now = std::time(nullptr);
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  md << "# Study `" << config.name << "`\n\n";
  if (!config.description.empty()) md << config.description << "\n\n";
  md << "- cells stored: **" << cells.size() << " of " << expected << "**"
     << (cells.size() < expected ? " (partial: the missing cells are not in any table)" : "") << "; unstable: "
     << unstable << "; failed: " << failed
     << (disrupted ? "; disrupted (a lipid left the bilayer): " + std::to_string(disrupted) : "") << "\n";
  if (s.is_bilayer())
    md << "- scene: bilayer (H3(T6)2 lipids in water; box, lipids and a_ij fixed by the scene), " << s.particles
       << " beads, ρ = " << s.density << ", γ = " << s.gamma << ", k_BT = " << s.kT << ", λ = " << s.lambda << ", "
       << s.steps << " steps (" << s.equilibrate << " discarded; the first min(1000, " << s.equilibrate
       << ") at Δt = 0.005), pairs: " << dpd::to_string(s.pairs) << "\n";
  else
    md << "- scene: " << s.name << ", " << s.particles << " beads, ρ = " << s.density << ", a = " << s.a
       << ", γ = " << s.gamma << ", k_BT = " << s.kT << ", " << integrator_text(config) << ", "
       << (s.time > 0 ? num(s.time) + " units of simulated time at every Δt (" + num(s.equilibrate_time) +
                            " discarded)"
                      : std::to_string(s.steps) + " steps (" + std::to_string(s.equilibrate) + " discarded)")
       << ", pairs: " << dpd::to_string(s.pairs) << "\n";
  md << "- replicas per variant: " << config.replicas << "; reference: " << config.reference << " ("
     << config.reference_replica_count() << " replicas under each noise); α = " << a.alpha
     << "\n- "
     << (a.family_size ? a.error_control_sentence() : "Error control: none needed (no tests, no verdicts)")
     << "\n- " << detection_limit << "\n";
  if (const std::string own = temperature_limit_sentence(a); !own.empty()) md << "- " << own << "\n";
  md << "- config hash `" << config.hash
     << "` (the config is stored in study.h5 and study.toml); generated "
     << when << "\n\n";
  return md.str();
}

std::vector<CalibrationRecord> calibrations(const fs::path& study_dir, const ReportOptions& options) {
  if (!options.calibration.empty()) return read_calibrations({options.calibration});
  fs::path study = fs::absolute(study_dir).lexically_normal();
  if (!study.has_filename()) study = study.parent_path();  // "results/ci/" names the same directory
  const fs::path results = study.parent_path();
  std::vector<fs::path> places;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(results, ec))
    if (e.is_directory(ec) && e.path().filename() != "calibration" &&
        fs::is_regular_file(e.path() / "calibration.json", ec))
      places.push_back(e.path() / "calibration.json");
  std::sort(places.begin(), places.end());
  places.insert(places.begin(), results / "calibration");
  return read_calibrations(places);
}

std::string unreadable_cells_markdown(const std::vector<std::string>& files) {
  if (files.empty()) return "";
  std::ostringstream md;
  md << "**Unreadable cell files** (left out of every table; `study run` computes them again):\n\n";
  for (const auto& f : files) md << "- `" << f << "`\n";
  md << "\n";
  return md.str();
}

std::string broken_cells_markdown(const std::vector<CellResult>& cells) {
  std::ostringstream md;
  md << "## Unstable and failed cells\n\n";
  std::size_t broken = 0;
  for (const auto& c : cells) broken += c.status != CellStatus::ok;
  if (broken == 0) md << "None.\n\n";
  for (const auto& c : cells)
    if (c.status != CellStatus::ok)
      md << "- `" << c.cell.id() << "`: " << to_string(c.status)
         << (c.unstable_step >= 0 ? " at step " + std::to_string(c.unstable_step) : "") << " — " << c.reason << "\n";
  for (const auto& c : cells)
    for (const auto& [k, v] : c.notes) md << "- `" << c.cell.id() << "` " << k << ": " << v << "\n";
  return md.str();
}

}  // namespace detail

namespace {
using detail::cells_csv;
using detail::num;

void write(const fs::path& p, const std::string& text) { detail::write_text(p, text); }

std::string chart(const std::string& name, const std::string& alt) { return detail::chart_link(name, alt); }

std::string correlation_markdown(const Analysis& a) {
  std::ostringstream o;
  o << "| generator | distribution | ζ(i,j,t) vs ζ(i,j+1,t): r (p) | ζ(i,j,t) vs ζ(i,j,t+1): r (p) |\n|---|---|---|---|\n";
  bool any = false;
  for (const auto& v : a.variants) {
    if (v.correlations.empty()) continue;
    any = true;
    const auto cell = [&](const std::string& what) {
      for (const auto& c : v.correlations)
        if (c.what == what && c.available) {
          const std::string b = c.decision.differs ? "**" : "";
          return b + detail::fmt("%+.4f", c.worst_r) + b + " (" +
                 detail::p_text(c.decision.p_adjusted) + ")";
        }
      return std::string("–");
    };
    o << "| " << v.key.label_and_seeding() << " | " << v.key.noise() << " | "
      << cell("pair") << " | " << cell("time") << " |\n";
  }
  return any ? o.str() : "(no correlation taps stored)\n";
}

}  // namespace

fs::path write_report(const StudyConfig& config, const std::vector<CellResult>& cells, const fs::path& study_dir,
                      const ReportOptions& options) {
  if (config.scene.is_bilayer()) return write_bilayer_report(config, cells, study_dir, options);
  if (!config.integrators.empty()) return write_stability_report(config, cells, study_dir, options);
  const fs::path dir = study_dir / "report";
  fs::create_directories(dir / "charts");
  const Analysis a = analyse(config, cells);
  const std::vector<std::string> dists = detail::distributions_of(a);

  write(dir / "summary.csv", summary_csv(a));
  write(dir / "verdicts.csv", verdicts_csv(a));
  write(dir / "pass_table.csv", pass_table_csv(a));
  write(dir / "observables.csv", observables_csv(a));
  write(dir / "zeta.csv", zeta_csv(a));
  const std::vector<BudgetRow> budget = error_budget(a, config.scene.kT);
  write(dir / "error_budget.csv", error_budget_csv(budget));
  write(dir / "cells.csv", cells_csv(cells));
  std::vector<std::string> nist_files;
  for (const auto& v : a.variants)
    if (!v.nist.empty()) {
      const std::string f = "nist_" + v.nist_cell + ".txt";
      write(dir / f, v.nist_report.empty() ? nist_final_analysis_report(v, a.alpha) : v.nist_report);
      nist_files.push_back(f);
    }
  const std::vector<RoundsRow> rounds = rounds_figures(a);
  write(dir / "rounds_figures.csv", rounds_figures_csv(rounds));
  const std::vector<EquivalenceReplicas> replicas_for = equivalence_replicas(a);
  const std::vector<CalibrationRecord> calibrations = detail::calibrations(study_dir, options);
  const std::map<std::string, Rate> calibrated = calibrated_equivalence(config, calibrations);
  write(dir / "equivalence_replicas.csv", equivalence_replicas_csv(replicas_for, calibrated));
  std::vector<std::string> made;
  if (options.charts) {
    detail::fresh_chart_directory(dir / "charts");
    made = write_charts(a, cells, dir / "charts", options.log);
    for (auto& n : write_rounds_charts(rounds, dir / "charts", options.log)) made.push_back(std::move(n));
  }
  const auto have = [&](const std::string& n) { return std::find(made.begin(), made.end(), n) != made.end(); };

  std::ostringstream md;
  md << detail::report_header(config, a, cells, detection_limit_sentence(config, calibrations))
     << detail::unreadable_cells_markdown(options.unreadable);

  md << "## Verdicts\n\n"
     << how_to_read_verdicts(config, a) << "\n"
     << "- " << a.error_model_sentence() << "\n\n"
     << "The table is `verdicts.csv` (its rows \"all\" are the verdicts; the others each observable's and test's "
        "shift, 95 % CI, margin, corrected P-values and outcome). **Bold**: differs.\n\n"
     << verdict_table_markdown(a) << "\n"
     << "### Error model check\n\n" << score_check_markdown(a) << "\n"
     << "### Replicas for equivalence\n\n" << equivalence_replicas_markdown(replicas_for, calibrated) << "\n"
     << "### Variants, cost and NIST\n\n"
     << "*Smallest corrected p*: the smallest two-sided P-value of the variant after the error control (below α "
        "exactly when the verdict says *differs*). A variant whose MT19937 replicas are missing or unreadable gets "
        "no verdict.\n\n"
     << summary_markdown(a) << "\n";
  for (const auto& d : dists)
    if (have("speed_vs_accuracy_" + d)) md << chart("speed_vs_accuracy_" + d, "speed against accuracy, " + d);

  md << "## Error budget: noise error against integrator error\n\n"
     << error_budget_text(config.scene.kT) << "\n" << error_budget_markdown(budget) << "\n";

  md << "## The numbers the force uses: ζ and the temperature\n\n"
     << "The ζ of every production step's pairs inside r_c, pooled over the replicas. *Noise* names the "
        "distribution and, unless it is `halves`, the feed: `halves` feeds Box–Muller the two 32-bit halves of a "
        "one-word block (32TEA, SplitMix64, Saru, MT19937) or the first two words of a longer one; `blocks` takes "
        "u1 and u2 as 53-bit uniforms from two blocks of the pair (distance seeding: the second hashes the "
        "rotated separation (dy, dz, dx); pair-step: the complemented step); `inverse` puts one uniform of the "
        "first block through Φ⁻¹. By fluctuation–dissipation k_BT ∝ σ²⟨ζ²⟩, so ⟨ζ²⟩/⟨ζ²⟩_MT − 1 predicts the "
        "temperature shift; the measured one (replica means against MT of the same feed, 95 % from the "
        "comparison's pooled σ) stands beside it. ⟨ζ²⟩ = 1 is tested on the large-sample normal law of the mean "
        "of ζ² (its variance from ⟨ζ⁴⟩), a member of the study's one Holm family; **bold** = differs.\n\n"
     << zeta_markdown(a) << "\n"
     << (have("predicted_vs_measured") ? chart("predicted_vs_measured", "predicted against measured temperature shift")
                                       : std::string())
     << "### Which tests flag each generator × feed\n\n"
     << "χ² and lag-1 t look at one output word at a time and NIST at its bits; none of them sees how two "
        "uniforms combine into ζ, which ⟨ζ²⟩ does, and which the physics feels. χ², lag-1 t: **flags** when a "
        "pass fraction differs from 1 − α after the error control (the pass-fraction tables below). NIST reads "
        "the pair's first block, the same words under every feed, so a feed that did not run the battery shows "
        "the one that did. Physics: the observables that differ from MT after the error control.\n\n"
     << flags_markdown(a) << "\n";

  md << "## Pass fractions (the paper's Fig. 2)\n\n"
     << "χ²: one test per tapped production step on all the step's numbers (Sturges bins), α = " << a.alpha
     << ". Lag-1 t: one test per tapped pair on the numbers it receives over all production steps. Output words "
        "are judged apart (a, b for two-word generators such as 64TEA). Fractions are pooled over replicas with "
        "central Clopper–Pearson intervals at 1 − α; **bold** = inconsistent with 1 − α: the central exact "
        "binomial test (p = 2·min(P[X ≤ k], P[X ≥ k]), the test that agrees with that interval), after the "
        "error control.\n\n";
  for (const auto& d : dists) {
    md << "### " << d << "\n\n" << pass_table_markdown(a, d) << "\n";
    for (const char* t : {"chi2", "ttest"})
      if (have(std::string("pass_vs_rounds_") + t + "_" + d))
        md << chart(std::string("pass_vs_rounds_") + t + "_" + d, std::string("pass fraction vs rounds, ") + t + ", " + d);
  }

  md << "## Physical observables against MT\n\n"
     << "Each cell: the shift against MT with its 95 % CI, the outcome (equiv. = equivalent, ? = inconclusive) "
        "and the corrected two-sided P-value. Scalars (T, its fluctuation, P, D): shift = (mean − mean_MT) / "
        "mean_MT over the replicas, in %, Student's two-sample t on the replicas' values (n + m − 2 degrees of "
        "freedom). Curves (velocity PDF, g(r), MSD): the shift is the relative difference from MT's mean curve "
        "in the kept bin whose 95 % CI reaches furthest from 0; equivalence needs every kept bin inside the "
        "margin; the two-sided test is the L² F test of the replicas' curves (the squared difference of the mean "
        "curves summed over the bins, weighted by counting noise for the histograms and relatively for the MSD, "
        "calibrated by the effective number of independent bins). **Bold** = differs after the error control.\n\n";
  for (const auto& d : dists) {
    md << "### " << d << "\n\n" << observables_markdown(a, d) << "\n";
    for (const auto& [n, alt] : {std::pair{"temperature_shift_vs_rounds_", "temperature shift vs rounds"},
                                 std::pair{"vpdf_", "velocity PDF"}, std::pair{"vpdf_difference_", "velocity PDF against MT"},
                                 std::pair{"msd_", "MSD"}, std::pair{"msd_difference_", "MSD against MT"},
                                 std::pair{"rdf_", "g(r)"}, std::pair{"rdf_difference_", "g(r) against MT"}})
      if (have(n + d)) md << chart(n + d, std::string(alt) + ", " + d);
  }

  md << "## The paper's figures against rounds (Figs. 3a, 4b, 4d, 5b, 6b)\n\n"
     << "From the same cells: the kinetic temperature against the step (Fig. 3a; the replicas' mean series, "
        "thinned to at most 1 000 points, for MT and each family's fewest and most rounds); T_x, T_y, T_z with "
        "their replicas' 95 % CIs (4b; MT's as dashed levels); the error rates against MT, |shift| in % on a log "
        "axis with the 95 % CIs of the comparisons behind the verdicts (down to the floor where a CI holds 0), of "
        "the components (4d), the diffusion coefficient (5b) and g(r) (6b, the kept bin whose 95 % CI reaches "
        "furthest from 0). Data, with the signed shifts: `rounds_figures.csv`.\n\n";
  bool any_rounds_chart = false;
  for (const auto& d : dists)
    for (const auto& [n, alt] : {std::pair{"temperature_series_", "Fig. 3a: kinetic temperature against the step"},
                                 std::pair{"temperature_components_vs_rounds_", "Fig. 4b: T_x, T_y, T_z against rounds"},
                                 std::pair{"temperature_components_shift_vs_rounds_", "Fig. 4d: their error rates against MT"},
                                 std::pair{"diffusion_shift_vs_rounds_", "Fig. 5b: D's error rate against MT"},
                                 std::pair{"rdf_shift_vs_rounds_", "Fig. 6b: g(r)'s error rate against MT"}})
      if (have(n + d)) md << chart(n + d, std::string(alt) + ", " + d), any_rounds_chart = true;
  if (!any_rounds_chart) md << "(no chart: charts were not requested, or the cells hold none of these data)\n\n";

  md << "## Correlations of ζ across neighbouring pairs and consecutive steps\n\n"
     << "A weak hash fed neighbouring inputs can pass χ² with correlated outputs. Pooled Pearson r of ζ between "
        "the tapped couples of neighbouring pair ids and between consecutive steps of one pair, the largest |r| "
        "over the replicas shown; the replicas' tests combined (Stouffer) into one corrected P-value in "
        "parentheses; **bold** = differs after the error control.\n\n"
     << correlation_markdown(a) << "\n";

  md << "## NIST SP 800-22\n\n";
  if (nist_files.empty()) {
    md << "(no cell of this study ran the NIST battery)\n\n";
  } else {
    md << "The battery (15 tests, 188 P-value columns with the reference's defaults) on each variant's own raw "
          "outputs, with the reference's second-level checks (proportion passing within (1−α) ± 3√(α(1−α)/m), "
          "uniformity P_T ≥ 0.0001). With 188 columns, a good generator fails about one by chance; the full "
          "finalAnalysisReport of each is in the linked file.\n\n"
       << "| generator | distribution | sequences × bits | columns failed | failing columns | full report |\n"
          "|---|---|---|---|---|---|\n";
    for (const auto& v : a.variants) {
      if (v.nist.empty()) continue;
      std::string failing;
      int shown = 0;
      for (const auto& r : v.nist)
        if (r.applicable > 0 && !r.ok && shown++ < 6)
          failing += (failing.empty() ? "" : ", ") + r.test + (r.variant.empty() || r.variant == "-" ? "" : " " + r.variant);
      if (shown > 6) failing += ", …";
      md << "| " << v.key.label() << " | " << v.key.noise() << " | " << v.nist_sequences << " × "
         << config.tests.nist_bits << " | " << num(v.nist_failed) << " / " << v.nist_columns << " | "
         << (failing.empty() ? "none" : failing) << " | [nist_" << v.nist_cell << ".txt](nist_" << v.nist_cell
         << ".txt) |\n";
    }
    md << "\n";
  }

  md << "## Cost\n\n"
     << "ns per number: the engine's calibration of generator + distribution in a tight loop. Step time: wall "
        "time of the run / steps (cells ran side by side, so absolute times carry the machine's load). RNG share "
        "= numbers per step × ns per number / force time (an estimate; `dpdrng bench dpd` measures it by "
        "difference).\n\n"
     << cost_markdown(a) << "\n";
  for (const auto& d : dists) {
    if (have("cost_vs_rounds_" + d)) md << chart("cost_vs_rounds_" + d, "cost vs rounds (paper's Fig. 1), " + d);
  }

  md << detail::broken_cells_markdown(cells);
  md << "\n## Files\n\n"
     << "`verdicts.csv` (one row per variant × observable or test, and per variant), `error_budget.csv`, `summary.csv`, "
        "`pass_table.csv`, `observables.csv`, `zeta.csv`, `rounds_figures.csv`, `cells.csv` (every scalar of every cell)";
  for (const auto& f : nist_files) md << ", `" << f << "`";
  md << "; charts in `charts/` (SVG and PNG, each drawn by its gnuplot script from the CSV beside it); all data in `../study.h5` (h5py: "
        "`h5py.File('study.h5')['cells']`).\n";

  write(dir / "report.md", md.str());
  return dir / "report.md";
}

}  // namespace dpdrng::study
