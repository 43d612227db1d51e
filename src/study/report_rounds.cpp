// The paper's per-round figures from the study's cells: the per-component temperature with its CI (its Fig. 4b),
// the components' shift against the reference (4d), the diffusion coefficient's (5b) and g(r)'s (6b), each
// against the rounds with 95 % CIs, as charts and as report/rounds_figures.csv.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "dpdrng/study/observables.hpp"
#include "dpdrng/study/report.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {

using detail::num;

constexpr double kRoundsFloor = 1e-3;  // % : the log axis's floor for an error whose CI holds 0

struct RoundsFigure {
  const char* id;          // the paper's figure
  const char* name;        // chart base name
  const char* title;
  const char* ylabel;
  std::vector<const char*> observables;
  bool shift;              // the comparison's shift (%), else the replicas' mean with its CI
};

const std::vector<RoundsFigure>& rounds_figure_specs() {
  static const std::vector<RoundsFigure> f = {
      {"4b", "temperature_components_vs_rounds", "Kinetic temperature per component, replica mean ± 95 % CI",
       "k_BT_α = Σv_α²/(N − 1) (k_BT units)", {"temperature_x_mean", "temperature_y_mean", "temperature_z_mean"},
       false},
      {"4d", "temperature_components_shift_vs_rounds", "Error rate of each temperature component against MT, |shift| with its 95 % CI",
       "(T_α − T_{α,MT}) / T_{α,MT}", {"temperature_x_mean", "temperature_y_mean", "temperature_z_mean"}, true},
      {"5b", "diffusion_shift_vs_rounds", "Error rate of the diffusion coefficient against MT, |shift| with its 95 % CI",
       "(D − D_{MT}) / D_{MT}", {"diffusion_coefficient"}, true},
      {"6b", "rdf_shift_vs_rounds", "Error rate of g(r) against MT: |shift| of the bin whose 95 % CI reaches furthest from 0",
       "(g − g_{MT}) / g_{MT} in that bin", {"rdf_vs_mt"}, true},
  };
  return f;
}

const char* sem_of(const std::string& observable) {
  for (const auto& s : scalar_observables())
    if (observable == s.name) return s.sem;
  return "";
}

const Comparison* rounds_comparison(const VariantReport& v, const std::string& name) {
  for (const auto& c : v.observables)
    if (c.observable == name && c.available) return &c;
  return nullptr;
}

// One point of a figure: the variant's value (shift in %, or mean in k_BT) with its 95 % CI.
bool rounds_point(const RoundsFigure& f, const VariantReport& v, const std::string& obs, RoundsRow& r) {
  if (f.shift) {
    const Comparison* c = rounds_comparison(v, obs);
    if (!c || !std::isfinite(c->shift)) return false;
    r.value = 100 * c->shift, r.ci_low = 100 * c->ci_low, r.ci_high = 100 * c->ci_high;
    r.unit = "percent";
    return true;
  }
  const ReplicaMean m = replica_mean(v.cells, obs, sem_of(obs));
  if (m.n == 0) return false;
  r.value = m.mean, r.ci_low = m.mean - m.ci95, r.ci_high = m.mean + m.ci95;
  r.unit = "k_BT";
  return true;
}

}  // namespace

std::vector<RoundsRow> rounds_figures(const Analysis& a) {
  std::vector<RoundsRow> rows;
  for (const auto& f : rounds_figure_specs())
    for (const auto& v : a.variants) {
      if (v.cells.empty() || (f.shift && v.key.reference)) continue;
      for (const char* obs : f.observables) {
        RoundsRow r;
        r.figure = f.id;
        r.variant = &v;
        r.observable = obs;
        if (rounds_point(f, v, obs, r)) rows.push_back(r);
      }
    }
  return rows;
}

std::string rounds_figures_csv(const std::vector<RoundsRow>& rows) {
  std::ostringstream o;
  o << "figure,variant,generator,rounds,seeding,distribution,feed,integrator,dt,replicas,observable,value,ci_low,"
       "ci_high,unit\n";
  for (const auto& r : rows) {
    const VariantKey& k = r.variant->key;
    const bool uniform = k.distribution == rng::Distribution::uniform;
    o << detail::csv_line({r.figure, k.label(), k.generator, k.reference ? "" : std::to_string(k.rounds),
                           k.seeding_name(), std::string(rng::to_string(k.distribution)),
                           uniform ? std::string() : std::string(rng::to_string(k.feed)), k.integrator, num(k.dt),
                           std::to_string(r.variant->cells.size()), r.observable, num(r.value), num(r.ci_low),
                           num(r.ci_high), r.unit});
  }
  return o.str();
}

std::vector<std::string> write_rounds_charts(const std::vector<RoundsRow>& rows, const fs::path& dir,
                                             std::ostream* log) {
  // One chart per figure and noise; a line per generator × seeding × observable, the reference as a level.
  std::map<std::string, detail::Chart> charts;
  std::map<std::string, std::map<std::string, detail::Line>> lines;
  for (const auto& r : rows) {
    const RoundsFigure* f = nullptr;
    for (const auto& s : rounds_figure_specs())
      if (r.figure == s.id) f = &s;
    const VariantKey& k = r.variant->key;
    const std::string name = std::string(f->name) + "_" + k.noise();
    auto& c = charts[name];
    if (c.name.empty()) {
      c = detail::Chart{name, std::string(f->title) + " (" + k.noise() + "; the paper's Fig. " + f->id + ")",
                        "rounds", f->ylabel, true, false, "", {}, false};
      // Errors span from a few 0.1 % to thousands of % (64TEA(1)): |shift| on a log axis, the paper's error
      // rate; the bars span |shift| over the 95 % CI, down to the floor when the CI holds 0.
      c.logy = f->shift;
      if (f->shift) {
        c.ylabel = std::string("|") + f->ylabel + "| in % (log scale; floor " + num(kRoundsFloor) + " %: CI holds 0)";
        c.extra = "set yrange [" + num(kRoundsFloor) + ":*]\n";
      }
      c.auto_logy = !f->shift;  // 64TEA(1)'s components reach tens of k_BT
    }
    const std::string component = observable_label(r.observable);
    if (k.reference) {
      // The components' levels nearly coincide: their labels side by side.
      std::size_t at = 0;
      while (at < f->observables.size() && r.observable != f->observables[at]) ++at;
      std::ostringstream s;
      s << "set arrow from graph 0, first " << r.value << " to graph 1, first " << r.value
        << " nohead dt 2 lw 1 lc rgb 'gray40'\nset label " << detail::q(k.label() + " " + component) << " at graph "
        << 0.01 + 0.3 * double(at) << ", first " << r.value << " offset 0,0.6 tc rgb 'gray40'\n";
      c.extra += s.str();
      continue;
    }
    const std::string title = k.generator + " " + k.seeding_name() + (f->observables.size() > 1 ? " " + component : "");
    auto& l = lines[name][title];
    l.title = title;
    l.style = "using 1:2:3:4 with yerrorlines lw 2 pt 7";
    if (f->shift) {
      const double top = std::max(std::abs(r.ci_low), std::abs(r.ci_high));
      const double bottom = r.ci_low <= 0 && r.ci_high >= 0 ? kRoundsFloor
                                                            : std::min(std::abs(r.ci_low), std::abs(r.ci_high));
      l.rows.push_back({double(k.rounds), std::max(std::abs(r.value), kRoundsFloor), std::max(bottom, kRoundsFloor),
                        top});
    } else {
      l.rows.push_back({double(k.rounds), r.value, r.ci_low, r.ci_high});
    }
  }
  const bool run = detail::has_gnuplot();
  std::vector<std::string> made;
  for (auto& [name, c] : charts) {
    for (auto& [t, l] : lines[name]) c.lines.push_back(std::move(l));
    if (detail::render(c, dir, run, log)) made.push_back(name);
  }
  return made;
}

}  // namespace dpdrng::study
