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
       "k_BT_α = Σv_α²/(N − 1)", {"temperature_x_mean", "temperature_y_mean", "temperature_z_mean"},
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

std::size_t component_index(const RoundsFigure& f, const std::string& observable) {
  std::size_t at = 0;
  while (at < f.observables.size() && observable != f.observables[at]) ++at;
  return at < f.observables.size() ? at : 0;
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

namespace {

// Whose a chart line is: a generator and its seeding, or the reference's level (seeding empty).
struct Origin {
  std::string generator, seeding;
};

// With several seedings, each (component) panel splits into one per seeding, each generator's line in its
// seeding's panel titled by the generator alone; with more than six generators, each splits again into one per
// group of generators (detail::generator_groups). The reference's level is drawn in every panel of its component.
// `origins` runs parallel to the chart's lines.
void split_panels(detail::Chart& c, const std::vector<Origin>& origins) {
  std::vector<std::string> seedings, generators;
  for (const auto& o : origins) {
    if (o.seeding.empty()) continue;
    if (std::find(seedings.begin(), seedings.end(), o.seeding) == seedings.end()) seedings.push_back(o.seeding);
    if (std::find(generators.begin(), generators.end(), o.generator) == generators.end())
      generators.push_back(o.generator);
  }
  std::sort(generators.begin(), generators.end());
  const auto groups = detail::generator_groups(generators);
  const bool by_seeding = seedings.size() > 1, by_group = groups.size() > 1;
  if (!by_seeding && !by_group) return;
  const std::vector<std::string> components = c.panels.empty() ? std::vector<std::string>{""} : c.panels;
  c.panels.clear();
  for (const auto& comp : components)
    for (const auto& s : seedings)
      for (std::size_t g = 0; g < groups.size(); ++g) {
        std::string t = comp;
        if (by_seeding) t += (t.empty() ? "" : ", ") + s + " seeding";
        c.panels.push_back(detail::panel_title(t, g, groups.size()));
      }
  c.key_per_panel = by_group;
  if (by_group) c.panel_columns = groups.size();
  const std::size_t per_component = seedings.size() * groups.size();
  std::vector<detail::Line> out;
  for (std::size_t k = 0; k < c.lines.size(); ++k) {
    detail::Line& l = c.lines[k];
    const std::size_t first = l.panel * per_component;
    if (origins[k].seeding.empty()) {  // the reference's level, in each panel of its component
      for (std::size_t s = 0; s < per_component; ++s) {
        out.push_back(l);
        out.back().panel = first + s;
      }
      continue;
    }
    if (by_seeding) l.title = origins[k].generator;
    const std::size_t s = std::size_t(std::find(seedings.begin(), seedings.end(), origins[k].seeding) - seedings.begin());
    l.panel = first + s * groups.size() + detail::group_of(groups, origins[k].generator);
    out.push_back(std::move(l));
  }
  c.lines = std::move(out);
}

}  // namespace

std::vector<std::string> write_rounds_charts(const std::vector<RoundsRow>& rows, const fs::path& dir,
                                             std::ostream* log) {
  // One chart per figure and noise; a line per generator × seeding × observable, the reference as a level.
  std::map<std::string, detail::Chart> charts;
  std::map<std::string, std::map<std::string, detail::Line>> lines;
  std::map<std::string, std::map<std::string, Origin>> origins;  // beside `lines`, by the same keys
  for (const auto& r : rows) {
    const RoundsFigure* f = nullptr;
    for (const auto& s : rounds_figure_specs())
      if (r.figure == s.id) f = &s;
    const VariantKey& k = r.variant->key;
    const std::string name = std::string(f->name) + "_" + k.noise();
    auto& c = charts[name];
    if (c.name.empty()) {
      // Errors span from a few 0.1 % to thousands of % (64TEA(1)): |shift| on a log axis, the paper's error
      // rate; the bars span |shift| over the 95 % CI, down to the floor when the CI holds 0. The components
      // themselves span decades too where 64TEA(1) heats the fluid to tens of k_BT.
      c = detail::Chart{name,
                        std::string(f->title) + " (" + k.noise() + "; Fig. " + f->id +
                            (f->shift ? "; floor " + num(kRoundsFloor) + " % where the CI holds 0)" : ")"),
                        detail::Axis{"hash rounds", "1", detail::Scale::log2},
                        detail::Axis{f->shift ? "|shift| against MT19937" : f->ylabel, f->shift ? "%" : "k_BT",
                                     detail::Scale::log10},
                        {"rounds", "value", "ci_low", "ci_high"}};
      c.key = "inside top right";
      if (f->shift) c.extra = "set yrange [" + num(kRoundsFloor) + ":*]\n";
    }
    // The three components in three panels (small multiples), each family's line in each; the reference's value
    // a dashed level in its component's panel.
    const std::size_t panel = component_index(*f, r.observable);
    if (f->observables.size() > 1 && c.panels.empty())
      for (const char* o : f->observables) c.panels.push_back(observable_label(o));
    const std::string title = (k.reference ? k.label() + " (reference)" : k.generator + " " + k.seeding_name());
    auto& l = lines[name][title + "\t" + std::to_string(panel)];
    l.title = title;
    l.panel = panel;
    origins[name][title + "\t" + std::to_string(panel)] = {k.generator, k.reference ? "" : k.seeding_name()};
    if (k.reference) {
      // Its level is an annotation of each panel, named once in the key (not one of the panel's series).
      l.title = "";
      if (c.key_entries.empty())
        c.key_entries.push_back("keyentry with lines dt 2 lw 2 lc rgb 'black' title " + detail::q(k.label() + " (reference)"));
      l.style = "using 2:3 with lines dt 2 lw 2 lc rgb 'black'";
      l.rows = {{1, r.value}, {1, r.value}};  // its right end set once the chart's rounds are known
      continue;
    }
    l.style = "using 2:3:4:5 with yerrorlines lw 2 pt 7 " + detail::colour_style(k.generator);
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
    auto& chart_origins = origins[name];  // a named reference: some compilers cannot capture a structured binding
    const auto is_level = [&](const std::string& key) { return chart_origins[key].seeding.empty(); };
    double most = 1;  // the reference's level spans the rounds drawn
    for (auto& [t, l] : lines[name])
      if (!is_level(t))
        for (const auto& row : l.rows) most = std::max(most, row[0]);
    double lo = INFINITY, hi = 0;
    std::vector<Origin> order;
    for (auto& [t, l] : lines[name]) {
      if (is_level(t)) l.rows.back()[0] = most;
      for (const auto& row : l.rows) lo = std::min(lo, row[1]), hi = std::max(hi, row[1]);
      c.lines.push_back(std::move(l));
      order.push_back(origins[name][t]);
    }
    split_panels(c, order);
    // A log axis only where the values span a decade (64TEA(1)'s components at tens of k_BT); otherwise the
    // few-% differences stay visible on a linear one.
    if (c.y.unit == "k_BT" && !(lo > 0 && hi / lo > 10)) c.y.scale = detail::Scale::linear;
    if (detail::render(c, dir, run, log)) made.push_back(name);
  }
  return made;
}

}  // namespace dpdrng::study
