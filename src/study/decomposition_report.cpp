// The decomposition sweep's outputs: its Markdown and CSV tables, results.json and the charts, from its rows
// (read back from the store), on the report's shared writers.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "dpdrng/common/output.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {

using namespace dpdrng::dpd;
using detail::fmt;

namespace {

std::string pm(const Stat& s) { return fmt("%.4g", s.mean) + " ± " + fmt("%.1g", s.sem); }

// A CSV field: 10 significant digits, empty when not finite or (ref) when the row has no reference run.
std::string field(double v) { return std::isfinite(v) ? fmt("%.10g", v) : std::string(); }

template <class T>
std::vector<T> unique_in_order(const std::vector<DecompResult>& rows, T (*key)(const DecompResult&)) {
  std::vector<T> out;
  for (const auto& r : rows)
    if (std::find(out.begin(), out.end(), key(r)) == out.end()) out.push_back(key(r));
  return out;
}
std::string grid_of(const DecompResult& r) { return r.domains; }
std::string seeding_of(const DecompResult& r) { return r.seeding; }
std::string generator_of(const DecompResult& r) { return r.generator + " " + r.distribution; }

// One chart per grid: a cluster per seeding, a bar per generator, the value `of` a row.
detail::Chart grid_chart(const std::vector<DecompResult>& rows, const std::string& grid, const std::string& name,
                         const std::string& title, const detail::Axis& y, double (*of)(const DecompResult&)) {
  detail::Chart c{name + "_" + grid, title + ", domains " + grid, detail::Axis{"seeding", "", detail::Scale::categories},
                  y, {"position", "value"}};
  c.extra = "set style data histograms\nset style histogram clustered gap 1\n"
            "set style fill solid 0.8 border -1\nset xtics noenhanced rotate by -30\n" +
            std::string(y.scale == detail::Scale::linear ? "set yrange [0:*]\n" : "");
  const auto seedings = unique_in_order(rows, seeding_of);
  for (const auto& gen : unique_in_order(rows, generator_of)) {
    detail::Line l{gen, "using 3:xtic(4) " + detail::colour_style(gen), {}, {}};
    for (std::size_t s = 0; s < seedings.size(); ++s) {
      double v = NAN;
      for (const auto& r : rows)
        if (r.domains == grid && r.seeding == seedings[s] && generator_of(r) == gen) v = of(r);
      l.rows.push_back({double(s), v});
      l.labels.push_back(seedings[s]);
    }
    c.lines.push_back(std::move(l));
  }
  return c;
}

double mismatch_percent(const DecompResult& r) { return 100 * r.decomposed.boundary.mismatch_fraction(); }
// The log axis cannot show 0: round-off drifts are ~1e-16 anyway.
double drift(const DecompResult& r) { return std::max(r.decomposed.momentum_drift, 1e-17); }

}  // namespace

std::string decomp_table_markdown(const std::vector<DecompResult>& rows) {
  std::ostringstream o;
  o << "| generator | seeding | domains | boundary pairs/step | mismatched (run) | mean \\|Δζ\\| | "
       "momentum drift/bead (dec / ref) | k_BT (dec / ref) | D (dec / ref) | χ² pass | lag-1 pass | "
       "same-word pairs/step |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const BoundaryStats& b = r.decomposed.boundary;
    const double per_step = b.evaluations ? double(b.boundary) / b.evaluations : 0;
    const bool h = r.has_reference;
    o << "| " << r.generator << " | " << r.seeding << " | " << r.domains << " | " << fmt("%.4g", per_step) << " | "
      << fmt("%.3g", 100 * b.mismatch_fraction()) << " % | " << fmt("%.3g", b.zeta_diff_mean()) << " | "
      << fmt("%.2g", r.decomposed.momentum_drift) << " / " << (h ? fmt("%.2g", r.reference.momentum_drift) : "–")
      << " | " << pm(r.decomposed.temperature) << " / " << (h ? pm(r.reference.temperature) : "–") << " | "
      << fmt("%.3g", r.decomposed.diffusion) << " / " << (h ? fmt("%.3g", r.reference.diffusion) : "–") << " | ";
    if (h) {
      const auto& c = r.randomness;
      o << c.chi2_pass << "/" << c.chi2_tests << " | " << c.lag1_pass << "/" << c.lag1_tests << " | "
        << fmt("%.3g", c.duplicates_per_step) << " |\n";
    } else {
      o << "– | – | – |\n";
    }
  }
  return o.str();
}

std::string decomp_table_csv(const std::vector<DecompResult>& rows) {
  std::string out = detail::csv_line(
      {"generator", "seeding", "distribution", "domains", "particles", "steps", "status", "snapshot_boundary",
       "snapshot_shifted", "snapshot_mismatch_fraction", "run_evaluations", "run_boundary", "run_shifted",
       "run_separation_mismatches", "run_range_mismatches", "run_zeta_mismatches", "run_mismatch_fraction",
       "zeta_diff_mean", "zeta_diff_rms", "zeta_diff_max", "force_mismatch_max", "net_force_per_bead_rms",
       "grid_straddle_expected", "momentum_drift_dec", "momentum_drift_ref", "com_kinetic_share_dec",
       "temperature_dec", "temperature_dec_sem", "temperature_ref", "temperature_ref_sem", "pressure_dec",
       "pressure_ref", "diffusion_dec", "diffusion_ref", "chi2_tests", "chi2_pass", "lag1_tests", "lag1_pass",
       "lag1_max_abs_r", "cross_pair_r", "cross_pair_p", "duplicates_per_step"});
  for (const auto& r : rows) {
    const BoundaryStats& s = r.snapshot;
    const BoundaryStats& b = r.decomposed.boundary;
    const DecompRun& d = r.decomposed;
    const DecompRun& f = r.reference;
    const auto& c = r.randomness;
    const bool h = r.has_reference;
    const auto ref = [&](double v) { return h ? field(v) : std::string(); };
    const auto count = [&](std::size_t n) { return h ? std::to_string(n) : std::string(); };
    out += detail::csv_line(
        {r.generator, r.seeding, r.distribution, r.domains, std::to_string(r.particles), std::to_string(d.steps_done),
         d.status.text(), std::to_string(s.boundary), std::to_string(s.shifted), field(s.mismatch_fraction()),
         std::to_string(b.evaluations), std::to_string(b.boundary), std::to_string(b.shifted),
         std::to_string(b.separation_mismatch), std::to_string(b.range_mismatch), std::to_string(b.zeta_mismatch),
         field(b.mismatch_fraction()), field(b.zeta_diff_mean()), field(b.zeta_diff_rms()), field(b.zeta_diff_max),
         field(b.force_mismatch_max), field(b.net_force_rms()), field(b.grid_straddle_expected),
         field(d.momentum_drift), ref(f.momentum_drift), field(d.com_kinetic_share), field(d.temperature.mean),
         field(d.temperature.sem), ref(f.temperature.mean), ref(f.temperature.sem), field(d.pressure.mean),
         ref(f.pressure.mean), field(d.diffusion), ref(f.diffusion), count(c.chi2_tests), count(c.chi2_pass),
         count(c.lag1_tests), count(c.lag1_pass), ref(c.lag1_max_abs_r), ref(c.cross_pair_r), ref(c.cross_pair_p),
         ref(c.duplicates_per_step)});
  }
  return out;
}

std::string write_decomp_outputs(const DecompSweep& sw, const std::vector<DecompResult>& rows, const std::string& out,
                                 std::ostream* log) {
  const std::filesystem::path dir(out);
  prepare_output_directory(dir, "output directory");
  std::string md = "# " + sw.name + "\n\n" + (sw.description.empty() ? "" : sw.description + "\n\n") +
                   decomp_table_markdown(rows) + "\n";
  write_text_file(dir / "table.csv", decomp_table_csv(rows));
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : rows) j.push_back(to_json(r));
  write_text_file(dir / "results.json", j.dump(1) + "\n");
  const bool gnuplot = detail::has_gnuplot();
  detail::fresh_chart_directory(dir / "charts");
  for (const auto& g : unique_in_order(rows, grid_of))
    for (const auto& c : {grid_chart(rows, g, "mismatch", "Boundary pairs whose two ζ differ",
                                     detail::Axis{"boundary pairs mismatched", "%"}, mismatch_percent),
                          grid_chart(rows, g, "drift", "Momentum drift per bead, max |P(t) − P(0)|/N",
                                     detail::Axis{"momentum drift per bead", "m r_c/τ", detail::Scale::log10}, drift)})
      if (detail::render(c, dir / "charts", gnuplot, log)) md += detail::chart_link(c.name, c.title);
  write_text_file(dir / "table.md", md);
  return md;
}

}  // namespace dpdrng::study
