#pragma once
// `dpdrng study report DIR`: Markdown and CSV tables, gnuplot charts (SVG and PNG) and report.md, all under
// DIR/report/. Everything is computed from the stored cells, so a report of a partial study is a partial
// report (it says how many cells are missing), never a wrong one.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

struct ReportOptions {
  bool charts = true;          // run gnuplot (skipped with a note when it is not installed)
  std::ostream* log = nullptr;
};

// Returns the path of report.md.
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
// The NIST reference suite's finalAnalysisReport layout for one variant's battery.
std::string nist_final_analysis_report(const VariantReport& v, double alpha);

// Writes the chart data and gnuplot scripts under dir and runs gnuplot; returns the chart base names made.
std::vector<std::string> write_charts(const Analysis& a, const std::vector<CellResult>& cells,
                                      const std::filesystem::path& dir, std::ostream* log);

}  // namespace dpdrng::study
