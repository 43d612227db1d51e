#include "dpdrng/study/decomposition_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"

namespace dpdrng::study {

using namespace dpdrng::dpd;

std::vector<DecompResult> run_decomp_sweep(const DecompSweep& sw, const SweepProgress& progress) {
  std::vector<DecompResult> out;
  const std::size_t total = sw.generators.size() * sw.seedings.size() * sw.distributions.size() * sw.domains.size();
  for (const auto& gen : sw.generators)
    for (const auto& seeding : sw.seedings)
      for (auto dist : sw.distributions) {
        DecompResult ref;
        for (std::size_t d = 0; d < sw.domains.size(); ++d) {
          DecompConfig c = sw.base;
          c.noise.generator = gen;
          c.noise.seeding = seeding;
          c.noise.distribution = dist;
          c.domains = sw.domains[d];
          c.reference = d == 0;  // the undecomposed run does not depend on the grid
          DecompResult r = run_decomposition(c);
          if (d == 0)
            ref = r;
          else
            r.has_reference = true, r.reference = ref.reference, r.randomness = ref.randomness;
          out.push_back(std::move(r));
          if (progress) progress(out.size(), total, out.back());
        }
      }
  return out;
}

namespace {
std::string fmt(double v, int prec = 3) {
  std::ostringstream o;
  o << std::setprecision(prec) << v;
  return o.str();
}
std::string pm(const Stat& s) { return fmt(s.mean, 4) + " ± " + fmt(s.sem, 1); }
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
    o << "| " << r.generator << " | " << r.seeding << " | " << r.domains << " | " << fmt(per_step, 4) << " | "
      << fmt(100 * b.mismatch_fraction(), 3) << " % | " << fmt(b.zeta_diff_mean(), 3) << " | "
      << fmt(r.decomposed.momentum_drift, 2) << " / " << (r.has_reference ? fmt(r.reference.momentum_drift, 2) : "–")
      << " | " << pm(r.decomposed.temperature) << " / " << (r.has_reference ? pm(r.reference.temperature) : "–")
      << " | " << fmt(r.decomposed.diffusion, 3) << " / " << (r.has_reference ? fmt(r.reference.diffusion, 3) : "–")
      << " | ";
    if (r.has_reference) {
      const auto& c = r.randomness;
      o << c.chi2_pass << "/" << c.chi2_tests << " | " << c.lag1_pass << "/" << c.lag1_tests << " | "
        << fmt(c.duplicates_per_step, 3) << " |\n";
    } else {
      o << "– | – | – |\n";
    }
  }
  return o.str();
}

std::string decomp_table_csv(const std::vector<DecompResult>& rows) {
  std::ostringstream o;
  o << std::setprecision(10);
  o << "generator,seeding,distribution,domains,particles,steps,status,snapshot_boundary,snapshot_shifted,"
       "snapshot_mismatch_fraction,run_evaluations,run_boundary,run_shifted,run_separation_mismatches,"
       "run_range_mismatches,run_zeta_mismatches,run_mismatch_fraction,zeta_diff_mean,zeta_diff_rms,zeta_diff_max,"
       "force_mismatch_max,net_force_per_bead_rms,grid_straddle_expected,momentum_drift_dec,momentum_drift_ref,"
       "com_kinetic_share_dec,temperature_dec,temperature_dec_sem,temperature_ref,temperature_ref_sem,pressure_dec,"
       "pressure_ref,diffusion_dec,diffusion_ref,chi2_tests,chi2_pass,lag1_tests,lag1_pass,lag1_max_abs_r,"
       "cross_pair_r,cross_pair_p,duplicates_per_step\n";
  for (const auto& r : rows) {
    const BoundaryStats& s = r.snapshot;
    const BoundaryStats& b = r.decomposed.boundary;
    const DecompRun& d = r.decomposed;
    const DecompRun& f = r.reference;
    const auto& c = r.randomness;
    const bool h = r.has_reference;
    auto ref = [&](double v) { return h ? fmt(v, 10) : std::string(); };
    o << r.generator << "," << r.seeding << "," << r.distribution << "," << r.domains << "," << r.particles << ","
      << d.steps_done << ",\"" << d.status << "\"," << s.boundary << "," << s.shifted << "," << s.mismatch_fraction()
      << "," << b.evaluations << "," << b.boundary << "," << b.shifted << "," << b.separation_mismatch << ","
      << b.range_mismatch << "," << b.zeta_mismatch << "," << b.mismatch_fraction() << "," << b.zeta_diff_mean()
      << "," << b.zeta_diff_rms() << "," << b.zeta_diff_max << "," << b.force_mismatch_max << ","
      << b.net_force_rms() << "," << b.grid_straddle_expected << "," << d.momentum_drift << ","
      << ref(f.momentum_drift) << "," << d.com_kinetic_share << "," << d.temperature.mean << ","
      << d.temperature.sem << "," << ref(f.temperature.mean) << "," << ref(f.temperature.sem) << ","
      << d.pressure.mean << "," << ref(f.pressure.mean) << "," << d.diffusion << "," << ref(f.diffusion) << ","
      << (h ? std::to_string(c.chi2_tests) : "") << "," << (h ? std::to_string(c.chi2_pass) : "") << ","
      << (h ? std::to_string(c.lag1_tests) : "") << "," << (h ? std::to_string(c.lag1_pass) : "") << ","
      << ref(c.lag1_max_abs_r) << "," << ref(c.cross_pair_r) << "," << ref(c.cross_pair_p) << ","
      << ref(c.duplicates_per_step) << "\n";
  }
  return o.str();
}

std::vector<DecompChart> decomp_charts(const std::vector<DecompResult>& rows) {
  std::vector<std::string> grids, seedings, gens;
  auto add = [](std::vector<std::string>& v, const std::string& x) {
    if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
  };
  for (const auto& r : rows) add(grids, r.domains), add(seedings, r.seeding), add(gens, r.generator + " " + r.distribution);
  std::vector<DecompChart> out;
  for (const auto& g : grids) {
    DecompChart c;
    c.name = "decomposition_" + g;
    std::ostringstream d;
    d << std::setprecision(6) << "seeding";
    for (const auto& gen : gens) d << " \"" << gen << "\" \"" << gen << "\"";  // mismatch %, drift
    d << "\n";
    for (const auto& s : seedings) {
      d << s;
      for (const auto& gen : gens) {
        const DecompResult* hit = nullptr;
        for (const auto& r : rows)
          if (r.domains == g && r.seeding == s && r.generator + " " + r.distribution == gen) hit = &r;
        if (!hit) {
          d << " nan nan";
          continue;
        }
        // The log axis of the drift panel cannot show 0: round-off drifts are ~1e-16 anyway.
        d << " " << 100 * hit->decomposed.boundary.mismatch_fraction() << " "
          << std::max(hit->decomposed.momentum_drift, 1e-17);
      }
      d << "\n";
    }
    c.data = d.str();
    const std::size_t n = gens.size();
    std::ostringstream gp;
    gp << "# Decomposition check, domains " << g << ". Render: gnuplot -e \"set terminal svg; set output '" << c.name
       << ".svg'\" " << c.name << ".gp\n"
       << "set datafile missing 'nan'\nset style data histograms\nset style histogram clustered gap 1\n"
       << "set style fill solid 0.8 border -1\nset grid ytics\nset key top right noenhanced\n"
       << "set xtics noenhanced rotate by -30\nset multiplot layout 1,2 title 'domains " << g << "' noenhanced\n"
       << "set title 'boundary pairs whose two {/Symbol z} differ'\nset ylabel '%'\nset yrange [0:*]\n"
       << "plot for [k=0:" << n - 1 << "] '" << c.name << ".dat' using (column(2+2*k)):xtic(1) title columnheader(2+2*k)\n"
       << "set title 'momentum drift per bead, max |P(t)-P(0)|/N'\nset ylabel ''\nset logscale y\nset yrange [*:*]\n"
       << "plot for [k=0:" << n - 1 << "] '" << c.name << ".dat' using (column(3+2*k)):xtic(1) title columnheader(3+2*k)\n"
       << "unset multiplot\n";
    c.script = gp.str();
    out.push_back(std::move(c));
  }
  return out;
}

std::string write_decomp_outputs(const DecompSweep& sw, const std::vector<DecompResult>& rows, const std::string& out,
                                 std::ostream* log) {
  const std::filesystem::path dir(out);
  prepare_output_directory(dir, "output directory");
  std::string md = "# " + sw.name + "\n\n" + (sw.description.empty() ? "" : sw.description + "\n\n") +
                   decomp_table_markdown(rows);
  write_text_file(dir / "table.csv", decomp_table_csv(rows));
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : rows) j.push_back(to_json(r));
  write_text_file(dir / "results.json", j.dump(1) + "\n");
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  for (const auto& c : decomp_charts(rows)) {
    write_text_file(dir / (c.name + ".dat"), c.data);
    write_text_file(dir / (c.name + ".gp"), c.script);
    md += "\n![" + c.name + "](" + c.name + ".svg)\n";
    if (!gnuplot) continue;
    const std::string cmd = "cd '" + dir.string() + "' && gnuplot -e \"set terminal svg size 1100,520 dynamic; set output '" +
                            c.name + ".svg'\" '" + c.name + ".gp' 2>'" + c.name + ".gnuplot.log'";
    if (std::system(cmd.c_str()) != 0 && log) *log << "gnuplot failed for " << c.name << " (see its .gnuplot.log)\n";
  }
  write_text_file(dir / "table.md", md);
  return md;
}

}  // namespace dpdrng::study
