#pragma once
// The chart writer behind every report chart; internal to src/study. A chart is three files side by side:
// NAME.csv (the numbers drawn, one block per series), NAME.gp (a gnuplot script that reads only NAME.csv) and
// the rendered NAME.svg and NAME.png. The CSV and the script are committed with the results, so a chart can be
// redrawn or restyled without the study's cells (`dpdrng chart DIR`, redraw_charts). The rules every chart follows are in
// docs/charts.md; tests/test_chart_rules.cpp checks them on every committed chart.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "dpdrng/study/cell_result.hpp"

namespace dpdrng::study::detail {

enum class Scale { linear, log10, log2, categories };

// An axis: what it shows and its unit in DPD reduced units (r in r_c, t in τ, energy in k_BT, "1" for a pure
// number, "%" for a relative shift). The label is "quantity [unit]"; categories (generators along x) have none.
struct Axis {
  std::string quantity;
  std::string unit;
  Scale scale = Scale::linear;
  std::string label() const;
};

struct Line {
  std::string title;
  std::string style;  // gnuplot "using … with …" part; column 1 of the CSV is the series, data start at 2
  std::vector<std::vector<double>> rows;
  std::vector<std::string> labels;  // optional text column after the numbers (point labels, category names)
  std::size_t panel = 0;            // its panel in a chart of small multiples
  std::string also = {};            // a second plot element over the same rows (points over error bars), untitled
};

struct Chart {
  std::string name, title;
  Axis x, y;
  std::vector<std::string> columns;  // the CSV's numeric column names, x first
  std::string extra = {};            // more gnuplot settings (bands, reference lines, ranges)
  std::vector<Line> lines = {};
  std::string key = "inside top right";  // gnuplot's key placement ("off": none); in the last panel
  // Small multiples: panels of one quantity side by side, titled, each line in its `panel` (at most six series
  // in each; empty: one panel).
  std::vector<std::string> panels = {};
  // The key in every panel (each panel's lines are its own, as when the generators are split into groups), not
  // only beside the last.
  bool key_per_panel = false;
  std::size_t panel_columns = 0;  // the panels' columns (0: up to three)
  // Key entries that draw no data (what a point type means): gnuplot "keyentry …" plot elements.
  std::vector<std::string> key_entries = {};
};

std::string q(const std::string& s);  // a gnuplot double-quoted string
// Empties a report's charts directory before its charts are written, so that no chart of an earlier layout
// outlives the code that drew it.
void fresh_chart_directory(const std::filesystem::path& dir);
bool has_gnuplot();
// Writes NAME.csv and NAME.gp under dir and renders SVG and PNG if `run`; false when there is nothing to draw.
bool render(const Chart& c, const std::filesystem::path& dir, bool run, std::ostream* log);
std::vector<double> mean_series(const std::vector<const CellResult*>& cells, const std::string& name);

// One look per generator in every chart of every report: a colour per generator family, a point type per round
// count (filled 1–4, open beyond); the reference generator black.
std::string family_colour(const std::string& generator);
int rounds_point(int rounds);
std::string colour_style(const std::string& generator);                  // "lc rgb '#…'"
std::string generator_style(const std::string& generator, int rounds);  // "lc rgb '#…' pt N"
// Small multiples for charts that draw a line per generator: the generators (distinct, in the chart's order) split
// evenly over as few panels as hold at most six each (one group when six or fewer).
constexpr std::size_t kMaxSeriesPerPanel = 6;
std::vector<std::vector<std::string>> generator_groups(const std::vector<std::string>& generators);
std::size_t group_of(const std::vector<std::vector<std::string>>& groups, const std::string& generator);
// A panel's title: `prefix` ("distance seeding", a component, or empty) and, when there are several groups,
// "generators g of n" (each panel's key names its generators).
std::string panel_title(const std::string& prefix, std::size_t group, std::size_t groups);
// The equivalence margin ±m as a shaded band and the zero line, for a shift axis.
std::string margin_band(double margin, const std::string& what);
// A horizontal reference line with its label at the left edge.
std::string hline(double y, const std::string& title, const char* colour);

}  // namespace dpdrng::study::detail
