// The water report's charts, per noise: the temperature shift against MT with its CI and margin (against rounds,
// against cost, against the ⟨ζ²⟩ prediction), the cost and the pass fractions against rounds, and the curves
// (velocity PDF, MSD, g(r), temperature against the step). Rules: docs/charts.md.
#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <sstream>
#include <vector>

#include "dpdrng/stats/summary.hpp"
#include "dpdrng/study/report.hpp"
#include "dpdrng/study/observables.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;

namespace water_charts {

using detail::Axis;
using detail::Chart;
using detail::Line;
using detail::Scale;

constexpr std::size_t kMaxSeries = 6;

// Lines of one family: a generator with one seeding (its round counts in order) for one noise.
std::map<std::string, std::vector<const VariantReport*>> families(const Analysis& a, const std::string& dist) {
  std::map<std::string, std::vector<const VariantReport*>> f;
  bool several_dt = false;
  for (const auto& v : a.variants) several_dt |= v.key.dt != a.variants.front().key.dt;
  for (const auto& v : a.variants)
    if (!v.key.reference && v.key.noise() == dist) {
      const std::string dt = several_dt ? " dt=" + detail::num(v.key.dt) : "";
      f[v.key.generator + " " + v.key.seeding_name() + dt].push_back(&v);
    }
  return f;
}

const VariantReport* reference(const Analysis& a, const std::string& dist) {
  for (const auto& v : a.variants)
    if (v.key.reference && v.key.noise() == dist) return &v;
  return nullptr;
}

const Comparison* temperature(const VariantReport& v) {
  for (const auto& c : v.observables)
    if (c.observable == kinetic_temperature().name && c.available && std::isfinite(c.shift)) return &c;
  return nullptr;
}

double temperature_margin(const Analysis& a) {
  for (const auto& v : a.variants)
    if (const auto* c = temperature(v); c && std::isfinite(c->margin)) return c->margin;
  return NAN;
}

std::string cpu_of(const VariantReport& v) {
  for (const auto* c : v.cells)
    if (auto it = c->notes.find("cost.cpu"); it != c->notes.end()) return it->second;
  return "";
}

const Axis kShiftAxis{"k_BT shift against MT19937, 95 % CI", "%"};
// The shift charts' CSV: x first, then the shift with its CI, the point type (rounds) and, for a shift beyond
// the axis, its value.
const std::vector<std::string> kShiftColumns{"x", "shift_pct", "ci_low_pct", "ci_high_pct", "point_type",
                                             "shift_beyond_axis_pct"};

// Scales a shift axis to the effects a reader must judge: up to the furthest CI end among the shifts within 10 %
// (at least twice the margin). A shift beyond that (64TEA(1) at +2000 %) is drawn at the edge as a triangle
// pointing off the chart, named with its value one line further inward each, below the row of triangles so that
// no name runs into a neighbour's triangle. Rows: x, shift, CI low, CI high, …; labels: the variants.
void fit_shift_axis(Chart& c, double margin, std::vector<Line*> data) {
  constexpr double kEffect = 10;
  double limit = std::isfinite(margin) ? 2 * margin : 1;
  for (const Line* l : data)
    for (const auto& r : l->rows)
      if (std::abs(r[1]) <= kEffect)
        limit = std::max({limit, std::abs(r[1]), std::isfinite(r[2]) ? std::abs(r[2]) : 0.0,
                          std::isfinite(r[3]) ? std::abs(r[3]) : 0.0});
  limit *= 1.15;
  std::map<std::size_t, std::pair<Line, Line>> beyond;  // per panel: the triangles and their names
  std::map<std::size_t, std::size_t> named;             // per panel: the names placed so far
  for (Line* l : data)
    for (std::size_t k = 0; k < l->rows.size(); ++k) {
      auto& r = l->rows[k];
      if (std::abs(r[1]) <= limit) continue;
      const double edge = std::copysign(0.94 * limit, r[1]);
      const double at = edge - std::copysign(0.09 * limit * double(++named[l->panel]), r[1]);
      const std::string who = k < l->labels.size() ? l->labels[k] + " " : "";
      auto& [off, names] = beyond[l->panel];
      off = Line{"", "using 2:3:(column(7) > 0 ? 9 : 11) with points pt variable ps 1.6 lc rgb '#333333'",
                 std::move(off.rows), {}, l->panel};
      names = Line{"", "using 2:3:8 with labels offset 1,0 left font ',10' tc rgb '#333333'", std::move(names.rows),
                   std::move(names.labels), l->panel};
      off.rows.push_back({r[0], edge, NAN, NAN, NAN, r[1]});
      names.rows.push_back({r[0], at, NAN, NAN, NAN, r[1]});
      names.labels.push_back(who + detail::fmt("%+.0f %%", r[1]));
      r[1] = r[2] = r[3] = NAN;
    }
  c.extra += "set yrange [" + detail::num(-limit) + ":" + detail::num(limit) + "]\n";
  for (auto& [panel, lines] : beyond) {
    c.lines.push_back(std::move(lines.first));
    c.lines.push_back(std::move(lines.second));
  }
}

// The panels of a noise's charts: one per seeding when the study sweeps several, and within each, where the
// noise has more than six generators, one per group of generators (detail::generator_groups); none when one seeding
// and one group suffice. Panel s × groups + g holds seeding s's lines of group g's generators.
struct PanelPlan {
  std::vector<std::string> seedings;
  std::vector<std::vector<std::string>> groups;
  std::vector<std::string> titles;
  // The chart's panels: a row per seeding, a column per group when the generators are split.
  void apply(Chart& c) const {
    c.panels = titles;
    c.key_per_panel = groups.size() > 1;
    if (groups.size() > 1) c.panel_columns = groups.size();
  }
  std::size_t of(const VariantKey& k) const {
    const auto s = std::find(seedings.begin(), seedings.end(), k.seeding_name());
    const std::size_t si = s == seedings.end() ? 0 : std::size_t(s - seedings.begin());
    return si * groups.size() + detail::group_of(groups, k.generator);
  }
};

PanelPlan panel_plan(const Analysis& a, const std::string& dist) {
  PanelPlan p;
  std::vector<std::string> generators;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.key.noise() != dist) continue;
    if (std::find(p.seedings.begin(), p.seedings.end(), v.key.seeding_name()) == p.seedings.end())
      p.seedings.push_back(v.key.seeding_name());
    if (std::find(generators.begin(), generators.end(), v.key.generator) == generators.end())
      generators.push_back(v.key.generator);
  }
  std::sort(generators.begin(), generators.end());  // the order of families(): by name
  p.groups = detail::generator_groups(generators);
  if (p.seedings.size() < 2 && p.groups.size() < 2) return p;
  for (const auto& s : p.seedings)
    for (std::size_t g = 0; g < p.groups.size(); ++g)
      p.titles.push_back(detail::panel_title(p.seedings.size() < 2 ? "" : s + " seeding", g, p.groups.size()));
  return p;
}

// A family's line in the family's colour, in its panel (titled by the generator alone there).
Line family_line(const Chart& c, const PanelPlan& plan, const std::string& family, const VariantReport& first,
                 const std::string& style) {
  return Line{c.panels.empty() ? family : first.key.generator, style + " " + detail::colour_style(first.key.generator),
              {}, {}, plan.titles.empty() ? 0 : plan.of(first.key)};
}
const Axis kRoundsAxis{"hash rounds", "1", Scale::log2};

// k_BT's shift against the reference per family, against the rounds: the headline effect on a linear axis.
Chart temperature_shift(const Analysis& a, const std::string& dist) {
  Chart c{"temperature_shift_vs_rounds_" + dist, "Kinetic temperature against MT19937 (" + dist + ")", kRoundsAxis,
          kShiftAxis, kShiftColumns};
  c.columns.front() = "rounds";
  const double margin = 100 * temperature_margin(a);
  c.extra = detail::margin_band(margin, "equivalence margin");
  const PanelPlan plan = panel_plan(a, dist);
  plan.apply(c);
  for (const auto& [fam, vs] : families(a, dist)) {
    Line l = family_line(c, plan, fam, *vs.front(), "using 2:3:4:5 with yerrorlines lw 2 pt 7");
    for (const auto* v : vs)
      if (const auto* t = temperature(*v)) {
        l.rows.push_back({double(v->key.rounds), 100 * t->shift, 100 * t->ci_low, 100 * t->ci_high});
        l.labels.push_back(v->key.label());
      }
    c.lines.push_back(std::move(l));
  }
  std::vector<Line*> data;
  for (auto& l : c.lines) data.push_back(&l);
  fit_shift_axis(c, margin, data);
  return c;
}

// The point types' meaning as key entries (not data), for the round counts drawn.
std::vector<std::string> rounds_key(const std::vector<int>& rounds) {
  std::vector<int> r = rounds;
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  std::vector<std::string> out;
  for (int n : r)
    out.push_back("keyentry with points pt " + std::to_string(detail::rounds_point(n)) + " lc rgb 'black' title " +
                  detail::q(std::to_string(n) + (n == 1 ? " round" : " rounds")));
  return out;
}

// The cheapest variants that no cheaper one beats on |shift|: the choices worth considering.
std::vector<std::vector<double>> pareto_front(std::vector<std::vector<double>> points) {
  std::sort(points.begin(), points.end());
  std::vector<std::vector<double>> front;
  double best = INFINITY;
  for (const auto& p : points)
    if (std::abs(p[1]) < best) best = std::abs(p[1]), front.push_back({p[0], p[1]});
  return front;
}

// Cost against accuracy: every generator × rounds as a point (colour: family, shape: rounds), the margin band and
// the Pareto front; the points outside the band named.
Chart speed_accuracy(const Analysis& a, const std::string& dist) {
  const VariantReport* ref = reference(a, dist);
  const std::string cpu = ref ? cpu_of(*ref) : "";
  Chart c{"speed_vs_accuracy_" + dist,
          "Cost (best of 5 × 4096 calls in the run) against temperature shift (" + dist +
              (cpu.empty() ? "" : "; " + cpu) + ")",
          Axis{"cost per random number", "ns", Scale::log2}, kShiftAxis,
          kShiftColumns};
  c.columns.front() = "ns_per_number";
  const double margin = 100 * temperature_margin(a);
  c.extra = detail::margin_band(margin, "equivalence margin");
  if (ref && std::isfinite(ref->ns_per_number) && ref->ns_per_number > 0)
    c.extra += "set arrow from first " + detail::num(ref->ns_per_number) + ", graph 0 to first " +
               detail::num(ref->ns_per_number) + ", graph 1 nohead dt 2 lc rgb 'black'\nset label " +
               detail::q(ref->key.label()) + " at first " + detail::num(ref->ns_per_number) +
               ", graph 0.96 offset 0.5,0 font ',10'\n";
  const PanelPlan plan = panel_plan(a, dist);
  plan.apply(c);
  const std::size_t panels = std::max<std::size_t>(c.panels.size(), 1);
  std::vector<std::vector<std::vector<double>>> all(panels);
  std::vector<int> rounds;
  std::vector<Line> named(panels);
  double lo = ref && ref->ns_per_number > 0 ? ref->ns_per_number : INFINITY, hi = lo > 0 && std::isfinite(lo) ? lo : 0;
  for (const auto& [fam, vs] : families(a, dist)) {
    const std::size_t panel = plan.titles.empty() ? 0 : plan.of(vs.front()->key);
    Line l = family_line(c, plan, fam, *vs.front(), "using 2:3:4:5:6 with yerrorbars pt variable ps 1.3 lw 1.5");
    for (const auto* v : vs) {
      const auto* t = temperature(*v);
      if (!t || !std::isfinite(v->ns_per_number) || v->ns_per_number <= 0) continue;
      const double pt = detail::rounds_point(v->key.rounds);
      l.rows.push_back({v->ns_per_number, 100 * t->shift, 100 * t->ci_low, 100 * t->ci_high, pt});
      l.labels.push_back(v->key.label());
      rounds.push_back(v->key.rounds);
      all[panel].push_back({v->ns_per_number, 100 * t->shift});
      lo = std::min(lo, v->ns_per_number), hi = std::max(hi, v->ns_per_number);
      if (std::isfinite(margin) && std::abs(100 * t->shift) > margin && std::abs(100 * t->shift) <= 10) {
        named[panel].rows.push_back({v->ns_per_number, 100 * t->shift, NAN, NAN, NAN});
        named[panel].labels.push_back(v->key.label());
      }
    }
    c.lines.push_back(std::move(l));
  }
  std::vector<Line*> data;
  for (auto& l : c.lines) data.push_back(&l);
  fit_shift_axis(c, margin, data);
  for (std::size_t p = 0; p < panels; ++p) {
    // The front over every generator of the panel's seeding, also where they are split over several panels.
    const std::size_t per_seeding = plan.titles.empty() ? 1 : plan.groups.size(), first = p / per_seeding * per_seeding;
    std::vector<std::vector<double>> seeding_points;
    for (std::size_t q = first; q < first + per_seeding; ++q) seeding_points.insert(seeding_points.end(), all[q].begin(), all[q].end());
    Line front{"", "using 2:3 with steps dt 2 lw 1 lc rgb '#555555'", {}, {}, p};
    front.rows = pareto_front(seeding_points);
    if (front.rows.size() > 1) c.lines.push_back(std::move(front));
    named[p].style = "using 2:3:8 with labels offset 0.8,0.6 left font ',10' tc rgb '#333333'";
    named[p].panel = p;
    if (!named[p].rows.empty()) c.lines.push_back(std::move(named[p]));
  }
  // The reference's cost line can lie beyond every variant's: the x range holds both.
  if (std::isfinite(lo) && hi > 0) c.extra += "set xrange [" + detail::num(lo / 1.3) + ":" + detail::num(hi * 1.3) + "]\n";
  c.key_entries = rounds_key(rounds);
  c.key_entries.insert(c.key_entries.begin(), "keyentry with steps dt 2 lw 1 lc rgb '#555555' title \"Pareto front\"");
  c.key = "outside right top";
  return c;
}

// The temperature shift ⟨ζ²⟩'s effective power predicts against the one measured, per family: on the identity
// line when the noise's second moment explains the shift.
Chart predicted_measured(const Analysis& a) {
  Chart c{"predicted_vs_measured",
          "k_BT shift predicted from the noise's effective power (w_R²-weighted ⟨ζ²⟩ and its lag correlations) "
          "against measured",
          Axis{"predicted shift, 95 % CI", "%"},
          Axis{"measured k_BT shift against MT19937, 95 % CI", "%"},
          {"predicted_pct", "measured_pct", "predicted_ci_low_pct", "predicted_ci_high_pct", "measured_ci_low_pct",
           "measured_ci_high_pct", "point_type"}};
  c.key = "inside top left";
  double lo = 0, hi = 0;
  std::size_t off_scale = 0;
  constexpr double kShown = 10;  // % : the headline effects are a few %; 64TEA(1) reaches thousands
  const double margin = 100 * temperature_margin(a);
  std::map<std::string, Line> by_family;  // colour: family; shape: rounds; every noise and seeding in one panel
  std::vector<int> rounds;
  Line named{"", "using 2:3:9 with labels offset 1,-0.6 left font ',10' tc rgb '#333333'", {}, {}};
  std::vector<std::string> named_family;  // beside named's rows
  for (const auto& v : a.variants) {
    const auto* t = temperature(v);
    if (v.key.reference || !t || !std::isfinite(v.power_predicted_shift.value)) continue;
    const double p = 100 * v.power_predicted_shift.value, m = 100 * t->shift;
    if (std::abs(p) > kShown || std::abs(m) > kShown) {
      ++off_scale;
      continue;
    }
    lo = std::min({lo, p, 100 * t->ci_low}), hi = std::max({hi, p, 100 * t->ci_high});
    const double half = 196 * v.power_predicted_shift.se;
    Line& l = by_family[v.key.generator];
    l.title = v.key.generator;
    l.style = "using 2:3:4:5:6:7 with xyerrorbars pt 7 ps 0.6 " + detail::colour_style(v.key.generator);
    l.also = "using 2:3:8 with points pt variable ps 1.3 " + detail::colour_style(v.key.generator);
    l.rows.push_back({p, m, p - half, p + half, 100 * t->ci_low, 100 * t->ci_high,
                      double(detail::rounds_point(v.key.rounds))});
    rounds.push_back(v.key.rounds);
    if (std::isfinite(margin) && std::abs(m) > margin) {
      named.rows.push_back({p, m});
      named.labels.push_back(v.key.label_and_seeding() + " " + v.key.noise());
      named_family.push_back(v.key.generator);
    }
  }
  // More than six families: a panel per group of them, each variant's name in its family's panel.
  std::vector<std::string> families_drawn;
  for (const auto& [f, l] : by_family) families_drawn.push_back(f);
  const auto groups = detail::generator_groups(families_drawn);
  if (groups.size() > 1)
    for (std::size_t g = 0; g < groups.size(); ++g) c.panels.push_back(detail::panel_title("", g, groups.size()));
  c.key_per_panel = groups.size() > 1;
  if (groups.size() > 1) c.panel_columns = groups.size();
  std::vector<Line> names(groups.size(), named);
  for (auto& n : names) n.rows.clear(), n.labels.clear();
  for (std::size_t k = 0; k < named.rows.size(); ++k) {
    const std::size_t g = detail::group_of(groups, named_family[k]);
    names[g].rows.push_back(named.rows[k]);
    names[g].labels.push_back(named.labels[k]);
    names[g].panel = g;
  }
  for (auto& [f, l] : by_family) {
    l.panel = detail::group_of(groups, f);
    c.lines.push_back(std::move(l));
  }
  for (auto& n : names)
    if (!n.rows.empty()) c.lines.push_back(std::move(n));
  c.key_entries = rounds_key(rounds);
  if (off_scale > 0) c.title += " (" + std::to_string(off_scale) + " beyond ±10 % not drawn)";
  const double pad = 0.1 * std::max(hi - lo, 0.5);
  const std::string range = "[" + detail::num(lo - pad) + ":" + detail::num(hi + pad) + "]";
  c.extra = "set xrange " + range + "\nset yrange " + range + "\nset size ratio -1\n" +
            "set arrow from " + detail::num(lo - pad) + "," + detail::num(lo - pad) + " to " + detail::num(hi + pad) +
            "," + detail::num(hi + pad) + " nohead dt 2 lc rgb 'black'\n" +
            "set label " + detail::q("dashed: identity (prediction exact)") +
            " at graph 0.98, graph 0.04 right font ',10'\n";
  return c;
}

Chart cost_rounds(const Analysis& a, const std::string& dist) {
  const VariantReport* ref = reference(a, dist);
  Chart c{"cost_vs_rounds_" + dist, "Cost of one random number inside the DPD run (" + dist + ")", kRoundsAxis,
          Axis{"cost per random number (generator + distribution)", "ns", Scale::log2}, {"rounds", "ns_per_number"}};
  c.key = "inside bottom right";
  if (ref) c.extra += detail::hline(ref->ns_per_number, ref->key.label(), "black");
  const PanelPlan plan = panel_plan(a, dist);
  plan.apply(c);
  for (const auto& [fam, vs] : families(a, dist)) {
    Line l = family_line(c, plan, fam, *vs.front(), "using 2:3 with linespoints lw 2 pt 7");
    for (const auto* v : vs)
      if (std::isfinite(v->ns_per_number) && v->ns_per_number > 0)
        l.rows.push_back({double(v->key.rounds), v->ns_per_number});
    c.lines.push_back(std::move(l));
  }
  // Panels of split generators share a range that holds the reference's level too.
  if (c.key_per_panel && ref && std::isfinite(ref->ns_per_number) && ref->ns_per_number > 0) {
    double lo = ref->ns_per_number, hi = lo;
    for (const auto& l : c.lines)
      for (const auto& r : l.rows) lo = std::min(lo, r[1]), hi = std::max(hi, r[1]);
    c.extra += "set yrange [" + detail::num(lo / 1.2) + ":" + detail::num(hi * 1.2) + "]\n";
  }
  return c;
}

// Per test, each family's worst output word (the lowest pass fraction at each round count) with its CI; the
// reference's fraction and 1 − α as levels.
Chart pass_rounds(const Analysis& a, const std::string& dist, const std::string& test) {
  const std::string what = test == "chi2" ? "χ² per step" : "lag-1 t per pair";
  Chart c{"pass_vs_rounds_" + test + "_" + dist,
          "Pass fraction of " + what + ", worst output word, CI at 1 − α (" + dist + "; the paper's Fig. 2)",
          kRoundsAxis, Axis{"fraction of tests passed", "1"}, {"rounds", "fraction", "ci_low", "ci_high"}};
  c.key = "inside bottom right";
  c.extra = detail::hline(1 - a.alpha, "1 − α", "#555555");
  if (const auto* ref = reference(a, dist))
    for (const auto& p : ref->passes)
      if (p.available && p.trials > 0 && p.test == test) {
        c.extra += detail::hline(p.fraction, "", "black");
        break;
      }
  const PanelPlan plan = panel_plan(a, dist);
  plan.apply(c);
  for (const auto& [fam, vs] : families(a, dist)) {
    Line l = family_line(c, plan, fam, *vs.front(), "using 2:3:4:5 with yerrorlines lw 2 pt 7");
    for (const auto* v : vs) {
      const PassSummary* worst = nullptr;
      for (const auto& p : v->passes)
        if (p.available && p.trials > 0 && p.test == test && (!worst || p.fraction < worst->fraction)) worst = &p;
      if (worst) l.rows.push_back({double(v->key.rounds), worst->fraction, worst->ci_low, worst->ci_high});
    }
    c.lines.push_back(std::move(l));
  }
  return c;
}

struct Curve {
  const char* name;
  const char* title;
  Axis x, y;
  const char* xs;
  const char* ys;
  const char* extra_series;  // drawn for the reference, dashed (the Maxwell–Boltzmann PDF)
};

const std::vector<Curve>& curves() {
  static const std::vector<Curve> c = {
      {"vpdf", "Velocity PDF, pooled components", Axis{"velocity component v_α", "√(k_BT/m)"},
       Axis{"probability density P(v_α)", "√(m/k_BT)", Scale::log10}, "vpdf/v", "vpdf/p", "vpdf/mb"},
      {"msd", "Mean squared displacement", Axis{"lag time t", "τ", Scale::log10},
       Axis{"mean squared displacement", "r_c²", Scale::log10}, "msd/tau", "msd/msd", ""},
      {"rdf", "Radial distribution function", Axis{"pair distance r", "r_c"}, Axis{"g(r)", "1"}, "rdf/r", "rdf/g", ""},
      {"temperature_series", "Kinetic temperature against the step, replica mean", Axis{"step", "1"},
       Axis{"kinetic temperature", "k_BT"}, "series/step", "series/temperature", ""},
  };
  return c;
}

// The variants a curve chart draws: each family's fewest rounds, then its most rounds, up to `room`.
std::vector<const VariantReport*> curve_variants(const Analysis& a, const std::string& dist, std::size_t room) {
  std::vector<const VariantReport*> fewest, most;
  for (const auto& [fam, vs] : families(a, dist)) {
    const VariantReport* lo = nullptr;
    const VariantReport* hi = nullptr;
    for (const auto* v : vs) {
      if (v->cells.empty()) continue;
      if (!lo || v->key.rounds < lo->key.rounds) lo = v;
      if (!hi || v->key.rounds > hi->key.rounds) hi = v;
    }
    if (lo) fewest.push_back(lo);
    if (hi && hi != lo) most.push_back(hi);
  }
  fewest.insert(fewest.end(), most.begin(), most.end());
  if (fewest.size() > room) fewest.resize(room);
  return fewest;
}

// The replicas' values of one bin of a curve (cells whose curve has another length are left out).
std::vector<double> bin_values(const std::vector<const CellResult*>& cells, const std::string& name, std::size_t i,
                               std::size_t size) {
  std::vector<double> v;
  for (const auto* c : cells)
    if (const auto* s = c->find_series(name); s && s->size() == size) v.push_back((*s)[i]);
  return v;
}

// The reference (thick, black) and each family's fewest rounds, where a difference would show; then their most
// rounds while the panel holds fewer than six series.
Chart overlay(const Analysis& a, const std::string& dist, const Curve& k) {
  Chart c{std::string(k.name) + "_" + dist, std::string(k.title) + " (" + dist + ")", k.x, k.y, {k.xs, k.ys}};
  const bool logx = k.x.scale != Scale::linear, logy = k.y.scale != Scale::linear;
  const auto add = [&](const VariantReport& v, const std::string& title, const std::string& ys,
                       const std::string& style) {
    const auto xv = detail::mean_series(v.cells, k.xs), yv = detail::mean_series(v.cells, ys);
    if (xv.empty() || xv.size() != yv.size()) return;
    Line l{title, style, {}, {}};
    for (std::size_t i = 0; i < xv.size(); ++i)
      if (!(logy && yv[i] <= 0) && !(logx && xv[i] <= 0)) l.rows.push_back({xv[i], yv[i]});
    if (!l.rows.empty()) c.lines.push_back(std::move(l));
  };
  if (const auto* ref = reference(a, dist)) {
    add(*ref, ref->key.label() + " (reference, " + std::to_string(ref->cells.size()) + " replicas)", k.ys,
        "using 2:3 with lines lw 4 lc rgb 'black'");
    if (*k.extra_series) add(*ref, "Maxwell–Boltzmann at k_BT", k.extra_series, "using 2:3 with lines dt 2 lw 2 lc rgb '#777777'");
  }
  std::map<std::string, int> of_family;  // a family's second line (its most rounds) dotted
  for (const auto* v : curve_variants(a, dist, kMaxSeries - c.lines.size()))
    add(*v, v->key.label_and_seeding(), k.ys,
        "using 2:3 with lines lw 2 dt " + std::to_string(1 + 2 * of_family[v->key.generator + v->key.seeding_name()]++) +
            " " + detail::colour_style(v->key.generator));
  return c;
}

// Where curves overlap, their difference: each variant's mean curve against the reference's, relative, in %, with
// the 95 % CI of the difference of two means (Welch), over the bins where the reference is at least `floor` of its
// largest value (the velocity PDF's tails and g(r) inside the core carry no relative information).
Chart difference(const Analysis& a, const std::string& dist, const Curve& k, double floor) {
  Chart c{std::string(k.name) + "_difference_" + dist,
          std::string(k.title) + ": relative difference from MT19937, 95 % CI (" + dist + ")", k.x,
          Axis{"difference from MT19937", "%"}, {k.xs, "difference_pct", "ci_low_pct", "ci_high_pct"}};
  c.x.scale = k.x.scale;
  const VariantReport* ref = reference(a, dist);
  if (!ref) return c;
  const auto xs = detail::mean_series(ref->cells, k.xs), rm = detail::mean_series(ref->cells, k.ys);
  if (xs.empty() || rm.size() != xs.size()) return c;
  const double top = *std::max_element(rm.begin(), rm.end());
  c.extra = "set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'\n";
  constexpr double kCurveShown = 20;  // % : the differences a good generator's could be confused with
  std::vector<std::string> beyond;
  std::map<std::string, int> of_family;  // a family's second line (its most rounds) dashed, open points
  for (const auto* v : curve_variants(a, dist, kMaxSeries)) {
    const bool second = of_family[v->key.generator + v->key.seeding_name()]++ > 0;
    Line l{v->key.label_and_seeding(),
           std::string("using 2:3:4:5 with yerrorlines lw 1.5 ps 0.6 ") + (second ? "dt 2 pt 6 " : "pt 7 ") +
               detail::colour_style(v->key.generator),
           {}, {}};
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const auto vv = bin_values(v->cells, k.ys, i, xs.size()), rv = bin_values(ref->cells, k.ys, i, xs.size());
      const double r = stats::mean(rv);
      if (vv.size() < 2 || rv.size() < 2 || !(r > floor * top) || (k.x.scale != Scale::linear && xs[i] <= 0)) continue;
      const double sv = stats::sample_sd(vv), sr = stats::sample_sd(rv);
      const double a2 = sv * sv / double(vv.size()), b2 = sr * sr / double(rv.size()), se = std::sqrt(a2 + b2);
      const double dof = se > 0 ? std::pow(a2 + b2, 2) / (a2 * a2 / double(vv.size() - 1) + b2 * b2 / double(rv.size() - 1))
                                : double(vv.size() + rv.size() - 2);
      const double d = 100 * (stats::mean(vv) - r) / r, h = 100 * stats::t_half_width_factor(dof, 0.95) * se / r;
      l.rows.push_back({xs[i], d, d - h, d + h});
    }
    // A variant far off (64TEA(1): +10 000 % in the PDF's tails) would flatten the others: named, not drawn.
    double furthest = 0;
    for (const auto& r : l.rows) furthest = std::max(furthest, std::abs(r[1]));
    if (furthest > kCurveShown)
      beyond.push_back(v->key.label_and_seeding());
    else if (!l.rows.empty())
      c.lines.push_back(std::move(l));
  }
  if (!beyond.empty()) {
    std::string names;
    for (const auto& b : beyond) names += (names.empty() ? "" : ", ") + b;
    c.title += "; beyond ±" + detail::num(kCurveShown) + " %, not drawn: " + names;
  }
  return c;
}

std::vector<std::string> distributions(const Analysis& a) {
  std::vector<std::string> dists;
  for (const auto& v : a.variants)
    if (std::find(dists.begin(), dists.end(), v.key.noise()) == dists.end()) dists.push_back(v.key.noise());
  return dists;
}

}  // namespace water_charts

std::vector<std::string> write_charts(const Analysis& a, const std::vector<CellResult>&, const fs::path& dir,
                                      std::ostream* log) {
  using namespace water_charts;
  const auto dists = distributions(a);
  std::vector<Chart> charts;
  charts.push_back(predicted_measured(a));
  for (const auto& dist : dists) {
    charts.push_back(speed_accuracy(a, dist));
    charts.push_back(temperature_shift(a, dist));
    charts.push_back(cost_rounds(a, dist));
    for (const char* test : {"chi2", "ttest"}) charts.push_back(pass_rounds(a, dist, test));
    for (const auto& k : curves()) charts.push_back(overlay(a, dist, k));
    // The curves that overlap at the chart's scale, as differences from the reference: the velocity PDF where
    // it is at least 1e-3 of its peak, g(r) where g_ref ≥ 0.1 of its peak (outside the core), the MSD everywhere.
    for (const auto& [name, floor] : {std::pair{"vpdf", 1e-3}, std::pair{"rdf", 0.1}, std::pair{"msd", 0.0}})
      for (const auto& k : curves())
        if (std::string(k.name) == name) charts.push_back(difference(a, dist, k, floor));
  }
  const bool run = detail::has_gnuplot();
  if (!run && log) *log << "[report] gnuplot not found: chart scripts written, not rendered\n";
  std::vector<std::string> made;
  for (const auto& c : charts)
    if (detail::render(c, dir, run, log)) made.push_back(c.name);
  return made;
}

}  // namespace dpdrng::study
