// The bilayer report's charts: every generator's H/T/W density profiles overlaid, and each membrane observable
// per generator with its 95 % CI beside the reference's.
#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

#include "dpdrng/study/report.hpp"
#include "report_chart.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {
using detail::Axis;
using detail::Chart;
using detail::Line;
using detail::Scale;

std::vector<const VariantReport*> of_distribution(const Analysis& a, const std::string& dist) {
  std::vector<const VariantReport*> out;
  for (const auto& v : a.variants)
    if (v.key.noise() == dist && !v.cells.empty()) out.push_back(&v);
  return out;
}

// One panel per bead type (small multiples), one colour per generator: the reference thick and black.
Chart profiles(const std::vector<const VariantReport*>& vs, const std::string& dist) {
  Chart c{"bilayer_profiles_" + dist, "Number density across the bilayer, replica means (" + dist + ")",
          Axis{"z relative to the bilayer midplane", "r_c"}, Axis{"number density", "r_c⁻³"}, {"z", "density"}};
  c.panels = {"heads (H)", "tails (T)", "water (W)"};
  c.key = "inside center center";  // the water panel is empty around the midplane
  const std::pair<const char*, const char*> types[] = {{"profile/head", "H"}, {"profile/tail", "T"},
                                                       {"profile/water", "W"}};
  std::map<std::string, int> of_family;  // a second variant of one family is dashed, a third dotted
  for (std::size_t k = 0; k < vs.size(); ++k) {
    const int dash = 1 + of_family[detail::family_colour(vs[k]->key.generator)]++;
    const auto z = detail::mean_series(vs[k]->cells, "profile/z");
    for (std::size_t t = 0; t < 3; ++t) {
      const auto y = detail::mean_series(vs[k]->cells, types[t].first);
      if (z.empty() || y.size() != z.size()) continue;
      std::ostringstream style;
      style << "using 2:3 with lines dt " << dash << " lw " << (vs[k]->key.reference ? 4 : 2) << ' '
            << detail::colour_style(vs[k]->key.generator);
      Line l{vs[k]->key.label_and_seeding() + " " + vs[k]->key.noise(), style.str(), {}, {}, t};
      for (std::size_t i = 0; i < z.size(); ++i) l.rows.push_back({z[i], y[i]});
      c.lines.push_back(std::move(l));
    }
  }
  return c;
}

Chart observable(const std::vector<const VariantReport*>& vs, const BilayerObservable& o, const std::string& dist) {
  Chart c{std::string("bilayer_") + o.name + "_" + dist,
          std::string(o.what) + ": replica mean ± 95 % CI (" + dist + ")", Axis{"generator", "", Scale::categories},
          Axis{o.label, o.unit}, {"position", "mean", "ci95"}};
  c.key = "off";
  Line l{"replica mean ± 95 % CI", "using 2:3:4:xtic(5) with yerrorbars pt 7 ps 1.5 lw 2", {}, {}};
  const std::string mean = o.key, sem = o.sem;
  for (const auto* v : vs) {
    const ReplicaMean m = replica_mean(v->cells, mean, sem);
    if (m.n == 0) continue;
    l.rows.push_back({double(l.rows.size()), m.mean, m.ci95});
    l.labels.push_back(v->key.label_and_seeding() + (m.from_run_sem ? " †" : ""));
    if (v->key.reference) {
      std::ostringstream s;
      s << "set arrow from graph 0, first " << m.mean << " to graph 1, first " << m.mean
        << " nohead dt 2 lw 2 lc rgb 'black'\n";
      c.extra += s.str();
    }
  }
  std::ostringstream range;
  range << "set xrange [-0.5:" << double(l.rows.size()) - 0.5 << "]\nset xtics rotate by -20\n";
  c.extra += range.str();
  c.lines.push_back(std::move(l));
  return c;
}

}  // namespace

std::vector<std::string> write_bilayer_charts(const Analysis& a, const fs::path& dir, std::ostream* log) {
  std::vector<std::string> dists;
  for (const auto& v : a.variants)
    if (std::find(dists.begin(), dists.end(), v.key.noise()) == dists.end()) dists.push_back(v.key.noise());
  detail::fresh_chart_directory(dir);
  std::vector<Chart> charts;
  for (const auto& d : dists) {
    const auto vs = of_distribution(a, d);
    charts.push_back(profiles(vs, d));
    for (const auto& o : bilayer_observables()) charts.push_back(observable(vs, o, d));
  }
  const bool run = detail::has_gnuplot();
  if (!run && log) *log << "[report] gnuplot not found: chart scripts written, not rendered\n";
  std::vector<std::string> made;
  for (const auto& c : charts)
    if (detail::render(c, dir, run, log)) made.push_back(c.name);
  return made;
}

}  // namespace dpdrng::study
