#pragma once
// The gnuplot chart writer behind every report chart (report_charts.cpp, report_bilayer.cpp); internal to src/study.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "dpdrng/study/cell_result.hpp"

namespace dpdrng::study::detail {

struct Line {
  std::string title;
  std::string style;  // gnuplot "using … with …" part
  std::vector<std::vector<double>> rows;
  std::vector<std::string> labels;  // optional last column (quoted)
};

struct Chart {
  std::string name, title, xlabel, ylabel;
  bool logx = false, logy = false;
  std::string extra;  // more gnuplot settings
  std::vector<Line> lines;
  bool auto_logy = false;  // switch to a log y axis when the values span more than a decade
};

std::string q(const std::string& s);  // a gnuplot double-quoted string
bool has_gnuplot();
// Writes the chart's data files and script under dir, and renders SVG and PNG if `run`; false when there is
// nothing to draw.
bool render(const Chart& c, const std::filesystem::path& dir, bool run, std::ostream* log);
std::vector<double> mean_series(const std::vector<const CellResult*>& cells, const std::string& name);

}  // namespace dpdrng::study::detail
