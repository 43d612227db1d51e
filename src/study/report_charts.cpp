// The report's charts: data files and a gnuplot script per chart, rendered to SVG and PNG by gnuplot
// (gnuplot-nox). The scripts stay beside the charts, so anyone can restyle a chart without rerunning the study.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <ostream>
#include <span>
#include <sstream>
#include <vector>

#include "dpdrng/common/output.hpp"
#include "dpdrng/stats/summary.hpp"
#include "dpdrng/study/report.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;

namespace detail {

std::string q(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

bool has_gnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

bool render(const Chart& c, const fs::path& dir, bool run, std::ostream* log) {
  std::size_t points = 0;
  for (const auto& l : c.lines) points += l.rows.size();
  if (points == 0) return false;
  fs::create_directories(dir / "data");
  std::ostringstream gp;
  gp << "# " << c.title << "\n# Rendered by: gnuplot -e \"set terminal svg; set output 'x.svg'\" " << c.name
     << ".gp\nset title " << q(c.title) << " noenhanced\nset xlabel " << q(c.xlabel) << "\nset ylabel " << q(c.ylabel)
     << "\nset grid\nset key outside right top noenhanced\nset datafile missing \"nan\"\n";
  if (c.logx) gp << "set logscale x 2\n";
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& l : c.lines)
    for (const auto& r : l.rows)
      if (r.size() > 1 && std::isfinite(r[1])) lo = std::min(lo, r[1]), hi = std::max(hi, r[1]);
  if (c.logy || (c.auto_logy && lo > 0 && hi / lo > 10)) gp << "set logscale y\n";
  if (c.logx) {
    // A little room left of the smallest x (rounds start at 1, costs at a fraction of a second).
    double xmin = INFINITY;
    for (const auto& l : c.lines)
      for (const auto& r : l.rows)
        if (!r.empty() && r[0] > 0) xmin = std::min(xmin, r[0]);
    if (std::isfinite(xmin)) gp << "set xrange [" << fmt("%g", 0.8 * xmin) << ":*]\n";
  }
  gp << c.extra << "plot ";
  bool first = true;
  for (std::size_t k = 0; k < c.lines.size(); ++k) {
    const Line& l = c.lines[k];
    if (l.rows.empty()) continue;
    const std::string file = "data/" + c.name + "_" + std::to_string(k) + ".dat";
    std::ostringstream d;
    d << "# " << l.title << "\n";
    for (std::size_t r = 0; r < l.rows.size(); ++r) {
      for (double x : l.rows[r]) d << (std::isfinite(x) ? fmt("%.10g", x) : std::string("nan")) << ' ';
      if (r < l.labels.size()) d << q(l.labels[r]);
      d << '\n';
    }
    write_text_file(dir / file, d.str());
    gp << (first ? "" : ", \\\n     ") << q(file) << ' ' << l.style << " title " << q(l.title);
    first = false;
  }
  gp << '\n';
  write_text_file(dir / (c.name + ".gp"), gp.str());
  if (!run) return true;
  for (const auto& [term, ext] : {std::pair{"svg size 900,560 dynamic font 'sans,12'", "svg"},
                                  std::pair{"pngcairo size 1100,680 font 'sans,11'", "png"}}) {
    const std::string cmd = "cd '" + dir.string() + "' && gnuplot -e \"set terminal " + term + "; set output '" +
                            c.name + "." + ext + "'\" '" + c.name + ".gp' 2>'" + c.name + ".gnuplot.log'";
    if (std::system(cmd.c_str()) != 0 && log)
      *log << "[report] gnuplot failed for " << c.name << "." << ext << " (see " << (dir / (c.name + ".gnuplot.log"))
           << ")\n";
  }
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

}  // namespace detail

namespace {

// The replicas' kinetic temperatures of a variant's cells, and their spread (0 for a single replica).
template <class Cells>
std::vector<double> temperatures(const Cells& cells) {
  std::vector<double> t;
  for (const auto* c : cells)
    if (c->has("temperature_mean")) t.push_back(c->scalar("temperature_mean", 0));
  return t;
}
double spread(std::span<const double> t) { return t.size() > 1 ? stats::sample_sd(t) : 0; }
using detail::Chart;
using detail::mean_series;
using detail::Line;
using detail::q;
using detail::render;
using detail::has_gnuplot;

// Lines of one family: a generator with one seeding (its round counts in order) for one distribution.
std::map<std::string, std::vector<const VariantReport*>> families(const Analysis& a, const std::string& dist) {
  std::map<std::string, std::vector<const VariantReport*>> f;
  bool several_dt = false;
  for (const auto& v : a.variants) several_dt |= v.key.dt != a.variants.front().key.dt;
  for (const auto& v : a.variants)
    if (!v.key.reference && v.key.noise() == dist) {
      char dt[32];
      std::snprintf(dt, sizeof dt, " dt=%g", v.key.dt);
      f[v.key.generator + " " + v.key.seeding_name() + (several_dt ? dt : "")].push_back(&v);
    }
  return f;
}

const VariantReport* reference(const Analysis& a, const std::string& dist) {
  for (const auto& v : a.variants)
    if (v.key.reference && v.key.noise() == dist) return &v;
  return nullptr;
}

std::string hline(double y, const std::string& title, const char* colour, double label_x = 0.01) {
  if (!std::isfinite(y)) return "";
  std::ostringstream s;
  s << "set arrow from graph 0, first " << y << " to graph 1, first " << y << " nohead dt 2 lw 2 lc rgb '" << colour
    << "'\nset label " << q(title) << " at graph " << label_x << ", first " << y << " offset 0,0.6 tc rgb '" << colour << "'\n";
  return s.str();
}

void overlay(std::vector<Chart>& out, const Analysis& a, const std::string& dist, const std::string& name,
             const std::string& title, const std::string& x, const std::string& y, const std::string& xs,
             const std::string& ys, bool logx, bool logy, const std::string& extra_series = "") {
  Chart c{name + "_" + dist, title + " (" + dist + ")", x, y, logx, logy, "", {}, false};
  const auto add = [&](const VariantReport& v, const std::string& t, const std::string& style) {
    const auto xv = mean_series(v.cells, xs), yv = mean_series(v.cells, ys);
    if (xv.empty() || xv.size() != yv.size()) return;
    Line l{t, style, {}, {}};
    for (std::size_t i = 0; i < xv.size(); ++i)
      if (!(logy && yv[i] <= 0) && !(logx && xv[i] <= 0)) l.rows.push_back({xv[i], yv[i]});
    c.lines.push_back(std::move(l));
  };
  if (const auto* ref = reference(a, dist)) {
    add(*ref, ref->key.label() + " (reference, " + std::to_string(ref->cells.size()) + " replicas)",
        "using 1:2 with lines lw 4 lc rgb 'black'");
    if (!extra_series.empty()) {
      const auto xv = mean_series(ref->cells, xs), ev = mean_series(ref->cells, extra_series);
      if (!xv.empty() && xv.size() == ev.size()) {
        Line l{"Maxwell–Boltzmann at k_BT", "using 1:2 with lines dt 2 lw 2 lc rgb 'gray40'", {}, {}};
        for (std::size_t i = 0; i < xv.size(); ++i)
          if (ev[i] > 0) l.rows.push_back({xv[i], ev[i]});
        c.lines.push_back(std::move(l));
      }
    }
  }
  // The fewest and the most rounds of each family: where a difference would show, and its control.
  for (const auto& [fam, vs] : families(a, dist)) {
    const VariantReport* lo = nullptr;
    const VariantReport* hi = nullptr;
    for (const auto* v : vs) {
      if (v->cells.empty()) continue;
      if (!lo || v->key.rounds < lo->key.rounds) lo = v;
      if (!hi || v->key.rounds > hi->key.rounds) hi = v;
    }
    if (lo) add(*lo, lo->key.label() + " " + lo->key.seeding_name(), "using 1:2 with lines lw 2");
    if (hi && hi != lo) add(*hi, hi->key.label() + " " + hi->key.seeding_name(), "using 1:2 with lines lw 2 dt 3");
  }
  out.push_back(std::move(c));
}

}  // namespace

std::vector<std::string> write_charts(const Analysis& a, const std::vector<CellResult>&, const fs::path& dir,
                                      std::ostream* log) {
  std::vector<std::string> dists;
  for (const auto& v : a.variants)
    if (std::find(dists.begin(), dists.end(), v.key.noise()) == dists.end()) dists.push_back(v.key.noise());
  std::vector<Chart> charts;
  for (const auto& dist : dists) {
    const auto fams = families(a, dist);
    const VariantReport* ref = reference(a, dist);

    Chart cost{"cost_vs_rounds_" + dist, "Cost of one random number inside the DPD run (" + dist + ")", "rounds",
               "ns per number (generator + distribution)", true, true, "", {}, false};
    Chart step{"step_vs_rounds_" + dist, "Time per DPD step (" + dist + ")", "rounds", "ms per step", true, false, "",
               {}, false};
    Chart pass{"pass_vs_rounds_" + dist, "Pass fractions with 99 % CIs (" + dist + ")", "rounds",
               "fraction of tests passed", true, false, "", {}, false};
    Chart temp{"temperature_vs_rounds_" + dist, "Mean temperature ± replica s.d. (" + dist + ")", "rounds",
               "k_BT (kinetic)", true, false, "", {}, false};
    // The verdict's own evidence: −log₁₀ of the smallest corrected P-value, so that a point lies above the α
    // line exactly when its verdict says "differs". Log axis: P-values above 0.98 sit on the floor at 0.01,
    // those below the report's floor of 1e-12 (no error model here supports smaller) at 12.
    Chart speed{"speed_vs_accuracy_" + dist, "Speed against evidence of a difference from MT (" + dist + ")",
                "ms per DPD step (cost)", "-log10(smallest corrected p) (log scale, clipped to [0.01, 12])",
                false, true,
                "set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1\nset yrange [0.01:*]\n", {}, false};
    if (ref) {
      cost.extra += hline(ref->ns_per_number, ref->key.label(), "black");
      step.extra += hline(ref->step_ms, ref->key.label(), "black");
      const std::vector<double> t = temperatures(ref->cells);
      const std::size_t n = t.size();
      if (n > 0) {
        const double m = stats::mean(t), s = spread(t);
        temp.extra += hline(m, ref->key.label() + " mean", "black");
        if (n > 1) {
          temp.extra += hline(m + s, "", "gray50");
          temp.extra += hline(m - s, "", "gray50");
        }
      }
    }
    pass.extra += hline(1 - a.alpha, "1 − α", "gray30") + "set yrange [*:1.005]\n";
    temp.auto_logy = true;
    speed.extra += hline(-std::log10(a.alpha), "α (" + detail::num(a.alpha) + ")", "red", 0.9);
    Line ok{"does not differ from MT", "using 1:2:3 with labels point pt 7 ps 1.2 lc rgb 'dark-green' offset 0.8,0.6 left",
            {}, {}};
    Line bad{"differs from MT", "using 1:2:3 with labels point pt 5 ps 1.2 lc rgb 'red' offset 0.8,0.6 left", {}, {}};
    for (const auto& [fam, vs] : fams) {
      Line lc{fam, "using 1:2 with linespoints lw 2 pt 7", {}, {}};
      Line ls{fam, "using 1:2 with linespoints lw 2 pt 7", {}, {}};
      Line lt{fam, "using 1:2:3 with yerrorlines lw 2 pt 7", {}, {}};
      std::map<std::string, Line> lp;
      for (const auto* v : vs) {
        const double r = v->key.rounds;
        if (std::isfinite(v->ns_per_number)) lc.rows.push_back({r, v->ns_per_number});
        if (std::isfinite(v->step_ms)) ls.rows.push_back({r, v->step_ms});
        const std::vector<double> t = temperatures(v->cells);
        if (!t.empty()) {
          const double m = stats::mean(t), s = spread(t);
          lt.rows.push_back({r, m, s});
        }
        for (const auto& p : v->passes) {
          if (!p.available || p.trials == 0) continue;
          const std::string key = fam + " " + (p.test == "chi2" ? "χ²" : "lag-1 t") + (p.stream == "x" ? "" : " " + p.stream);
          auto& l = lp[key];
          l.title = key;
          l.style = "using 1:2:3:4 with yerrorlines lw 2 pt 7";
          l.rows.push_back({r, p.fraction, p.ci_low, p.ci_high});
        }
        if (std::isfinite(v->step_ms) && std::isfinite(v->min_p)) {
          Line& target = v->min_p < a.alpha ? bad : ok;
          target.rows.push_back({v->step_ms, std::max(0.01, -std::log10(std::max(v->min_p, detail::kPFloor)))});
          target.labels.push_back(v->key.label());
        }
      }
      cost.lines.push_back(std::move(lc));
      step.lines.push_back(std::move(ls));
      temp.lines.push_back(std::move(lt));
      for (auto& [k, l] : lp) pass.lines.push_back(std::move(l));
    }
    if (ref) {
      std::map<std::string, Line> lp;
      for (const auto& p : ref->passes) {
        if (!p.available || p.trials == 0) continue;
        // The reference has no rounds: drawn as a flat band across the chart's range of rounds.
        const std::string key = ref->key.label() + " " + (p.test == "chi2" ? "χ²" : "lag-1 t");
        if (lp.count(key)) continue;
        Line l{key, "using 1:2 with lines lw 3 dt 2 lc rgb 'black'", {}, {}};
        l.rows = {{1, p.fraction}, {32, p.fraction}};
        lp[key] = std::move(l);
      }
      for (auto& [k, l] : lp) pass.lines.push_back(std::move(l));
    }
    speed.lines.push_back(std::move(ok));
    speed.lines.push_back(std::move(bad));
    charts.push_back(std::move(speed));
    charts.push_back(std::move(cost));
    charts.push_back(std::move(step));
    charts.push_back(std::move(pass));
    charts.push_back(std::move(temp));
    overlay(charts, a, dist, "vpdf", "Velocity PDF, pooled components", "v", "P(v)", "vpdf/v", "vpdf/p", false, true,
            "vpdf/mb");
    overlay(charts, a, dist, "msd", "Mean squared displacement", "τ", "MSD", "msd/tau", "msd/msd", true, true);
    overlay(charts, a, dist, "rdf", "Radial distribution function", "r", "g(r)", "rdf/r", "rdf/g", false, false);
    overlay(charts, a, dist, "temperature_series", "Kinetic temperature against the step, replica mean", "step",
            "k_BT (kinetic)", "series/step", "series/temperature", false, false);
  }
  const bool run = has_gnuplot();
  if (!run && log) *log << "[report] gnuplot not found: chart scripts written, not rendered\n";
  std::vector<std::string> made;
  for (const auto& c : charts)
    if (render(c, dir, run, log)) made.push_back(c.name);
  return made;
}

}  // namespace dpdrng::study
