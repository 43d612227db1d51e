// Writes a chart's CSV and gnuplot script and renders them with gnuplot (gnuplot-nox). The script reads nothing but
// the CSV beside it, so the committed pair redraws the chart on any machine with gnuplot.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <tuple>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/calibrate.hpp"
#include "dpdrng/study/report.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study::detail {
namespace fs = std::filesystem;

std::string Axis::label() const {
  if (scale == Scale::categories || unit.empty()) return quantity;
  return quantity + " [" + unit + "]";
}

std::string q(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

void fresh_chart_directory(const fs::path& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec) throw OutputError("cannot empty " + dir.string() + ": " + ec.message());
  fs::create_directories(dir);
}

bool has_gnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

namespace chart_render {

// A CSV field: numbers as %.10g, a missing value as "nan" (gnuplot's `missing`), text quoted.
std::string field(double x) { return std::isfinite(x) ? fmt("%.10g", x) : std::string("nan"); }

// One block per series, two blank lines apart (gnuplot's `index`); the header names the columns once.
std::string csv(const Chart& c) {
  std::ostringstream d;
  d << "series";
  for (const auto& name : c.columns) d << ',' << name;
  bool labels = false;
  for (const auto& l : c.lines) labels |= !l.labels.empty();
  if (labels) d << ",label";
  d << '\n';
  bool first = true;
  for (const auto& l : c.lines) {
    if (l.rows.empty()) continue;
    if (!first) d << "\n\n";
    first = false;
    for (std::size_t r = 0; r < l.rows.size(); ++r) {
      d << q(l.title);
      for (std::size_t k = 0; k < c.columns.size(); ++k) d << ',' << field(k < l.rows[r].size() ? l.rows[r][k] : NAN);
      if (labels) d << ',' << q(r < l.labels.size() ? l.labels[r] : std::string());
      d << '\n';
    }
  }
  return d.str();
}

// Log axes print their ticks as %g (1e-08, not 0.00000001); linear ones keep gnuplot's default, which prints as
// many decimals as the tick step needs.
std::string axis_settings(const Axis& a, const char* which) {
  std::ostringstream s;
  s << "set " << which << "label " << q(a.label()) << " noenhanced\n";
  if (a.scale == Scale::log10) s << "set logscale " << which << " 10\nset format " << which << " \"%g\"\n";
  if (a.scale == Scale::log2) s << "set logscale " << which << " 2\nset format " << which << " \"%g\"\n";
  // Points at the ends of a log axis (1 round) would sit on the frame.
  if (a.scale != Scale::linear && a.scale != Scale::categories && std::string(which) == "x")
    s << "set offsets graph 0.03, graph 0.03, 0, 0\n";
  if (a.scale == Scale::categories) s << "# " << which << " axis: categories\n";
  return s.str();
}

// The plot command of one panel: its lines, each reading its own block of the CSV.
std::string plot_command(const Chart& c, std::size_t panel) {
  std::ostringstream gp;
  gp << "plot ";
  std::size_t block = 0, drawn = 0;
  for (const auto& l : c.lines) {
    if (l.rows.empty()) continue;
    if (l.panel == panel)
      gp << (drawn++ == 0 ? "" : ", \\\n     ") << q(c.name + ".csv") << " index " << block << ' ' << l.style
         << " title " << q(l.title);
    if (l.panel == panel && !l.also.empty())
      gp << ", \\\n     " << q(c.name + ".csv") << " index " << block << ' ' << l.also << " notitle";
    ++block;
  }
  if (panel + 1 == std::max<std::size_t>(c.panels.size(), 1))
    for (const auto& k : c.key_entries) gp << (drawn++ == 0 ? "" : ", \\\n     ") << k;
  gp << '\n';
  return drawn ? gp.str() : "";
}

// Small multiples whose panels split one chart's generators share their axes, so that panels compare at a
// glance: the ranges over every panel's data (x, then y with its CI columns), unless the chart sets its own.
std::string shared_ranges(const Chart& c) {
  if (!c.key_per_panel) return "";
  std::string out;
  for (const auto& [which, axis, first, last] :
       {std::tuple{"x", &c.x, std::size_t(0), std::size_t(0)}, std::tuple{"y", &c.y, std::size_t(1), std::size_t(3)}}) {
    if (c.extra.find(std::string("set ") + which + "range") != std::string::npos) continue;
    double lo = INFINITY, hi = -INFINITY;
    const bool log = axis->scale == Scale::log10 || axis->scale == Scale::log2;
    for (const auto& l : c.lines)
      for (const auto& r : l.rows)
        for (std::size_t k = first; k <= last && k < r.size(); ++k)
          if (std::isfinite(r[k]) && (!log || r[k] > 0)) lo = std::min(lo, r[k]), hi = std::max(hi, r[k]);
    if (!(lo <= hi)) continue;
    const double pad = log ? 0 : 0.05 * std::max(hi - lo, std::abs(hi) * 1e-3 + 1e-12);
    out += std::string("set ") + which + "range [" + num(log ? lo / 1.2 : lo - pad) + ":" +
           num(log ? hi * 1.2 : hi + pad) + "]\n";
  }
  return out;
}

std::string script(const Chart& c) {
  std::ostringstream gp;
  gp << "# " << c.title << "\n# Data: " << c.name << ".csv (column 1 the series; one block per series)\n"
     << "# Redraw: gnuplot -e \"set terminal svg; set output '" << c.name << ".svg'\" " << c.name << ".gp\n";
  if (!c.panels.empty()) gp << "# small multiples: " << c.panels.size() << " panels\n";
  const std::size_t cols = c.panel_columns ? c.panel_columns : std::min<std::size_t>(c.panels.size(), 3);
  const std::size_t rows = c.panels.empty() ? 1 : (c.panels.size() + cols - 1) / cols;
  // Panels keep a readable size: beyond two rows, or with a key beside each panel, the canvas grows.
  if (rows > 2 || c.key_per_panel) gp << "# canvas: 900," << (c.key_per_panel ? 400 : 280) * std::max<std::size_t>(rows, 2) << "\n";
  gp << axis_settings(c.x, "x") << axis_settings(c.y, "y")
     << "set grid\nset datafile separator comma\nset datafile missing \"nan\"\n";
  const std::string key =
      c.key == "off" ? "unset key\n" : "set key " + c.key + " noenhanced opaque box samplen 2 spacing 1.1 font ',10'\n";
  gp << (c.panels.empty() ? key : "unset key\n") << c.extra << shared_ranges(c);
  if (c.panels.empty()) return gp.str() + "set title " + q(c.title) + " noenhanced\n" + plot_command(c, 0);
  gp << "set multiplot layout " << rows << ',' << cols << " title " << q(c.title) << " noenhanced\n";
  for (std::size_t p = 0; p < c.panels.size(); ++p) {
    const bool last = p + 1 == c.panels.size();
    // The key (in every panel when each holds lines of its own) and a palette's colour box beside the last panel.
    gp << "set title " << q(c.panels[p]) << " noenhanced\n" << (last || c.key_per_panel ? key : "")
       << (last ? "set colorbox\n" : "unset colorbox\n") << plot_command(c, p);
  }
  gp << "unset multiplot\n";
  return gp.str();
}

// The canvas a script declares ("# canvas: W,H" among its first lines, for the SVG), else 900 × 560; the PNG's
// is 11/9 as wide and 17/14 as tall (1100 × 680 by default).
std::pair<int, int> canvas(const fs::path& script) {
  std::ifstream in(script);
  std::string line;
  int w = 900, h = 560;
  for (int k = 0; k < 8 && std::getline(in, line); ++k)
    if (std::sscanf(line.c_str(), "# canvas: %d,%d", &w, &h) == 2) break;
  return {w, h};
}

bool draw(const fs::path& dir, const std::string& name, std::ostream* log) {
  bool ok = true;
  const auto [w, h] = canvas(dir / (name + ".gp"));
  const std::string svg = "svg size " + std::to_string(w) + "," + std::to_string(h) + " dynamic font 'sans,12'";
  const std::string png = "pngcairo size " + std::to_string(w * 11 / 9) + "," + std::to_string(h * 17 / 14) +
                          " font 'sans,11'";
  for (const auto& [term, ext] : {std::pair{svg.c_str(), "svg"}, std::pair{png.c_str(), "png"}}) {
    const std::string cmd = "cd '" + dir.string() + "' && gnuplot -e \"set terminal " + term + "; set output '" +
                            name + "." + ext + "'\" '" + name + ".gp' 2>'" + name + ".gnuplot.log'";
    if (std::system(cmd.c_str()) != 0) {
      ok = false;
      if (log)
        *log << "[report] gnuplot failed for " << name << "." << ext << " (see " << (dir / (name + ".gnuplot.log"))
             << ")\n";
    }
  }
  return ok;
}

}  // namespace chart_render

bool render(const Chart& c, const fs::path& dir, bool run, std::ostream* log) {
  std::size_t points = 0;
  for (const auto& l : c.lines) points += l.rows.size();
  if (points == 0) return false;
  fs::create_directories(dir);
  write_text_file(dir / (c.name + ".csv"), chart_render::csv(c));
  write_text_file(dir / (c.name + ".gp"), chart_render::script(c));
  if (run) chart_render::draw(dir, c.name, log);
  return true;
}

// Element-wise mean over the cells that hold the series (those of another length are skipped).
std::vector<double> mean_series(const std::vector<const CellResult*>& cells, const std::string& name) {
  std::vector<double> m;
  std::size_t n = 0;
  for (const auto* c : cells)
    if (const auto* s = c->find_series(name)) {
      if (m.empty()) m.assign(s->size(), 0.0);
      if (s->size() != m.size()) continue;
      for (std::size_t i = 0; i < m.size(); ++i) m[i] += (*s)[i];
      ++n;
    }
  for (double& x : m) x /= double(n);
  return m;
}

}  // namespace dpdrng::study::detail

namespace dpdrng::study {

std::size_t redraw_charts(const fs::path& dir, std::ostream* log) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError("chart: " + dir.string() + " is not a directory");
  // A calibration whose charts have no CSV yet (drawn before the chart rules) gets them from its tables.
  std::vector<fs::path> calibrations;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file() && e.path().filename() == "calibration.json" &&
        !fs::exists(e.path().parent_path() / "charts" / "false_alarms.csv"))
      calibrations.push_back(e.path().parent_path());
  for (const auto& c : calibrations) write_calibration_charts(read_calibration_tables(c), c, false, log);
  std::vector<fs::path> scripts;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file() && e.path().extension() == ".gp" &&
        fs::exists(fs::path(e.path()).replace_extension(".csv")))
      scripts.push_back(e.path());
  if (ec) throw InputError("chart: cannot read " + dir.string() + ": " + ec.message());
  if (scripts.empty())
    throw InputError("chart: " + dir.string() + " holds no chart (a NAME.gp beside its NAME.csv)");
  if (!detail::has_gnuplot()) throw InputError("chart: gnuplot is not installed (Debian package gnuplot-nox)");
  std::sort(scripts.begin(), scripts.end());
  std::size_t drawn = 0;
  for (const auto& s : scripts) drawn += detail::chart_render::draw(s.parent_path(), s.stem().string(), log);
  return drawn;
}

}  // namespace dpdrng::study
