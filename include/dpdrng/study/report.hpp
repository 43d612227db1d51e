#pragma once
// `dpdrng study report DIR`: Markdown and CSV tables, gnuplot charts (SVG and PNG) and report.md, all under
// DIR/report/. Everything is computed from the stored cells, so a report of a partial study is a partial
// report (it says how many cells are missing), never a wrong one.
#include <cmath>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/calibrate.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

struct ReportOptions {
  bool charts = true;          // run gnuplot (skipped with a note when it is not installed)
  std::ostream* log = nullptr;
  std::vector<std::string> unreadable;  // cell files that could not be read: listed by name in the report
  // Where the detection limit is read from (calibrate.hpp): a calibration.json or a directory holding them;
  // empty = the study directory's sibling "calibration" (results/calibration beside results/<study>) and the
  // calibration.json of any other sibling (results/<study>-at-size).
  std::filesystem::path calibration;
};

// Returns the path of report.md. A study that sweeps integrators gets the stability report (stability.hpp).
std::filesystem::path write_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                                   const std::filesystem::path& study_dir, const ReportOptions& options = {});

// Pieces, for tests and for the report itself.
std::string pass_table_markdown(const Analysis& a, const std::string& distribution);
std::string pass_table_csv(const Analysis& a);
std::string observables_csv(const Analysis& a);
std::string observables_markdown(const Analysis& a, const std::string& distribution);
std::string summary_markdown(const Analysis& a);
std::string summary_csv(const Analysis& a);
std::string cost_markdown(const Analysis& a);
// report/verdicts.csv: one row per variant × observable or test (shift, 95 % CI, margin, corrected P-values,
// equivalent | differs | inconclusive; shifts as fractions of the reference's value where relative) and one row
// per variant, observable "all", with its verdict. The reference's variants have none.
std::string verdicts_csv(const Analysis& a);
// The verdict table read from the same rows: per variant its verdict and each margin observable's shift [95 % CI].
std::string verdict_table_markdown(const Analysis& a);
// The error model's z-score check (score_dispersion) over the variants of known-good generators.
std::string score_check_markdown(const Analysis& a);
// report/equivalence_replicas.csv and its table: the replicas a generator as good as the reference needs to be
// shown equivalent 90 % of the time (equivalence_replicas), beside the rate a calibration at the study's own size
// measured at its replicas (`calibrated`, by observable; empty when there is none).
std::string equivalence_replicas_csv(const std::vector<EquivalenceReplicas>& rows,
                                     const std::map<std::string, Rate>& calibrated);
std::string equivalence_replicas_markdown(const std::vector<EquivalenceReplicas>& rows,
                                          const std::map<std::string, Rate>& calibrated);
// What a verdict assumes and how its outcomes are defined, with the margins in force.
std::string how_to_read_verdicts(const StudyConfig& config, const Analysis& a);
// Per variant: ⟨ζ²⟩ of the force's numbers with its CI and the temperature shift it predicts, beside the shift
// measured against MT.
std::string zeta_markdown(const Analysis& a);
std::string zeta_csv(const Analysis& a);
// The error budget (report/error_budget.csv): per variant and observable with a target (k_BT for the kinetic,
// configurational and per-component temperatures; 0 for the membrane's P_xx − P_yy), the noise error (variant −
// reference at the same settings: the verdict's comparison and 95 % CI), the integrator error (reference − target:
// the reference's replica mean with its 95 % CI) and the variant's own error against the target. Temperatures as
// fractions of k_BT; the anisotropy absolute. Values NaN where a side has no data.
struct BudgetPart {
  double value = NAN, ci_low = NAN, ci_high = NAN;
};
struct BudgetRow {
  const VariantReport* variant = nullptr;
  std::string observable;
  double target = NAN;
  bool relative = true;
  BudgetPart noise, integrator, total;
};
std::vector<BudgetRow> error_budget(const Analysis& a, double kT);
std::string error_budget_csv(const std::vector<BudgetRow>& rows);
std::string error_budget_markdown(const std::vector<BudgetRow>& rows);
std::string error_budget_text(double kT);  // the table's definitions, for the report
// The paper's per-round figures (report/rounds_figures.csv and charts *_vs_rounds_<noise>): per variant, "4b" the
// replicas' mean T_x, T_y, T_z with 95 % CIs (the reference's too, as its level), "4d" their shifts against the
// reference, "5b" the diffusion coefficient's shift, "6b" g(r)'s (the kept bin whose CI reaches furthest from 0),
// shifts in % with the comparisons' 95 % CIs.
struct RoundsRow {
  std::string figure;  // "4b", "4d", "5b", "6b"
  const VariantReport* variant = nullptr;
  std::string observable;
  double value = NAN, ci_low = NAN, ci_high = NAN;
  std::string unit;  // "k_BT" or "percent"
};
std::vector<RoundsRow> rounds_figures(const Analysis& a);
std::string rounds_figures_csv(const std::vector<RoundsRow>& rows);
// One chart per figure and noise; returns the chart names made.
std::vector<std::string> write_rounds_charts(const std::vector<RoundsRow>& rows, const std::filesystem::path& dir,
                                             std::ostream* log);
// Per generator × feed: which tests flag it (χ², lag-1 t, NIST, ⟨ζ²⟩, the physical observables).
std::string flags_markdown(const Analysis& a);
// The NIST reference suite's finalAnalysisReport layout for one variant's battery.
std::string nist_final_analysis_report(const VariantReport& v, double alpha);

// The membrane scene's report ([scene] name = "bilayer"; write_report hands over to it): no pass fractions or NIST,
// the membrane's observables per generator with 95 % CIs, paired differences from the reference beside the
// MT-vs-MT noise floor, density profiles and T / Σ charts.
std::filesystem::path write_bilayer_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                                           const std::filesystem::path& study_dir, const ReportOptions& options);
// One row per variant: replica mean ± 95 % CI of T, P_xx, P_yy, P_zz, Σ, thickness and tail order.
std::string bilayer_table_markdown(const Analysis& a, const std::string& distribution);
std::string bilayer_table_csv(const Analysis& a);
// One row per variant and observable: value, reference, paired difference [95 % CI], paired-t P, noise floor.
std::string bilayer_differences_markdown(const Analysis& a, const std::string& distribution);
std::string bilayer_differences_csv(const Analysis& a);
// Density profiles overlaid, and one chart per observable with CI error bars; returns the chart names made.
std::vector<std::string> write_bilayer_charts(const Analysis& a, const std::filesystem::path& dir, std::ostream* log);

// Writes the chart data and gnuplot scripts under dir and runs gnuplot; returns the chart base names made.
std::vector<std::string> write_charts(const Analysis& a, const std::vector<CellResult>& cells,
                                      const std::filesystem::path& dir, std::ostream* log);

// Draws every chart under dir again from its committed NAME.csv and NAME.gp (no cells needed); returns how many
// were drawn. InputError when dir holds no chart or gnuplot is missing.
std::size_t redraw_charts(const std::filesystem::path& dir, std::ostream* log);

}  // namespace dpdrng::study
