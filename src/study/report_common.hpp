#pragma once
// Pieces the water report (report.cpp, report_tables.cpp), the bilayer report (report_bilayer.cpp) and the
// decomposition sweep's outputs (decomposition_report.cpp) share; internal to src/study.
#include <filesystem>
#include <string>
#include <vector>

#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/calibrate.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/report.hpp"

namespace dpdrng::study::detail {

void write_text(const std::filesystem::path& p, const std::string& text);  // throws if it cannot
std::string num(double x);                                                  // "%.6g", "" when not finite
std::string fmt(const char* f, double x);                                   // printf format f, "–" when not finite
// A P-value for reading: "%.2g", "< 1e-12" below the floor (no error model here supports smaller), "–" for NaN.
inline constexpr double kPFloor = 1e-12;
std::string p_text(double p);
// A P-value for a CSV cell: "%.6g", "<1e-12" below the floor, "" for NaN.
std::string p_csv(double p);
std::string csv_quote(const std::string& s);                                 // RFC 4180 quoting where needed
std::string csv_line(const std::vector<std::string>& fields);                // quoted fields, commas, '\n'
std::string cells_csv(const std::vector<CellResult>& cells);                // every scalar of every cell
// The distributions the analysis holds, in the order they first appear: one report section each.
std::vector<std::string> distributions_of(const Analysis& a);
std::string chart_link(const std::string& name, const std::string& alt);    // PNG inline, SVG and script linked
// Title, description, cells stored and broken, scene, replicas, error control, detection limit and config hash.
std::string report_header(const StudyConfig& config, const Analysis& a, const std::vector<CellResult>& cells,
                          const std::string& detection_limit);
// A study's calibrations, each read once: options.calibration when given; else <study dir>/../calibration and
// the calibration.json of every other sibling directory (a calibration at the study's own size).
std::vector<CalibrationRecord> calibrations(const std::filesystem::path& study_dir, const ReportOptions& options);
// The "Unstable and failed cells" section, with every cell's notes.
std::string broken_cells_markdown(const std::vector<CellResult>& cells);
// The cell files that exist but could not be read (empty when there are none).
std::string unreadable_cells_markdown(const std::vector<std::string>& files);

}  // namespace dpdrng::study::detail
