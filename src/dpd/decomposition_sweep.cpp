#include "dpdrng/dpd/decomposition_sweep.hpp"

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

namespace dpdrng::dpd {

namespace {

// One TOML table whose keys are checked off as they are read, so that a misspelt key is an error.
class Keys {
 public:
  Keys(const toml::table* t, std::string path, std::string origin)
      : t_(t), path_(std::move(path)), origin_(std::move(origin)) {}
  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw InputError(origin_ + ": " + (path_.empty() ? key : path_ + "." + key) + ": " + why);
  }
  const toml::node* get(const std::string& key) {
    used_.insert(key);
    return t_ ? t_->get(key) : nullptr;
  }
  std::string str(const std::string& key, std::string def) {
    const toml::node* n = get(key);
    if (!n) return def;
    if (!n->is_string()) fail(key, "must be a string");
    return *n->value<std::string>();
  }
  std::vector<std::string> strings(const std::string& key, std::vector<std::string> def) {
    const toml::node* n = get(key);
    if (!n) return def;
    const toml::array* a = n->as_array();
    if (!a || a->empty()) fail(key, "must be a non-empty array of strings");
    std::vector<std::string> out;
    for (const auto& e : *a) {
      if (!e.is_string()) fail(key, "must be a non-empty array of strings");
      out.push_back(*e.value<std::string>());
    }
    return out;
  }
  long integer(const std::string& key, long def, long lo, long hi) {
    const toml::node* n = get(key);
    if (!n) return def;
    return check_int(key, *n, lo, hi);
  }
  std::vector<long> integers(const std::string& key, long lo, long hi) {
    const toml::node* n = get(key);
    if (!n) return {};
    std::vector<long> out;
    if (const toml::array* a = n->as_array()) {
      if (a->empty()) fail(key, "must not be empty");
      for (const auto& e : *a) out.push_back(check_int(key, e, lo, hi));
    } else {
      out.push_back(check_int(key, *n, lo, hi));
    }
    return out;
  }
  double num(const std::string& key, double def) {
    const toml::node* n = get(key);
    if (!n) return def;
    const auto v = n->value<double>();  // integers convert
    if (!v || !std::isfinite(*v)) fail(key, "must be a finite number");
    return *v;
  }
  void done() const {
    if (!t_) return;
    for (const auto& [k, v] : *t_)
      if (!used_.count(std::string(k.str()))) fail(std::string(k.str()), "unknown key");
  }

 private:
  long check_int(const std::string& key, const toml::node& n, long lo, long hi) const {
    const auto v = n.value_exact<std::int64_t>();
    if (!v || *v < lo || *v > hi) fail(key, "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return static_cast<long>(*v);
  }
  const toml::table* t_;
  std::string path_, origin_;
  std::set<std::string> used_;
};

template <class F>
auto named(const Keys& k, const std::string& key, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    k.fail(key, e.what());
  }
}

}  // namespace

DecompSweep parse_decomp_sweep(const std::string& text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    std::ostringstream o;
    o << origin << ": " << e.description() << " (line " << e.source().begin.line << ")";
    throw InputError(o.str());
  }
  DecompSweep s;
  Keys top(&root, "", origin);
  s.name = top.str("name", s.name);
  s.description = top.str("description", "");
  for (const auto& d : top.strings("domains", {"2"})) s.domains.push_back(named(top, "domains", [&] { return parse_domains(d); }));
  for (const auto& d : top.strings("seedings", {"distance", "pair-step", "grid", "canonical"}))
    s.seedings.push_back(named(top, "seedings", [&] { return parse_decomp_seeding(d); }));
  s.distributions.clear();
  for (const auto& d : top.strings("distributions", {"gauss"}))
    s.distributions.push_back(named(top, "distributions", [&] { return rng::parse_distribution(d); }));

  const toml::node* gens = top.get("generators");
  if (!gens || !gens->is_array_of_tables()) top.fail("generators", "needs at least one [[generators]] table");
  std::size_t gi = 0;
  for (const auto& node : *gens->as_array()) {
    Keys g(node.as_table(), "generators[" + std::to_string(gi++) + "]", origin);
    rng::GeneratorSpec spec;
    spec.name = g.str("name", "");
    if (spec.name.empty()) g.fail("name", "is required");
    std::vector<long> rounds = g.integers("rounds", 0, 64);
    if (rounds.empty()) rounds.push_back(0);
    for (long r : rounds) {
      spec.rounds = static_cast<int>(r);
      s.generators.push_back(named(g, "rounds", [&] { return rng::validated(spec); }));
    }
    g.done();
  }

  DecompConfig& b = s.base;
  Keys scene(root["scene"].as_table(), "scene", origin);
  if (scene.str("name", "water") != "water") scene.fail("name", "only the water scene is supported");
  b.water.particles = static_cast<int>(scene.integer("particles", 256, 2, 20000));
  b.water.density = scene.num("density", b.water.density);
  b.water.a = scene.num("a", b.water.a);
  b.water.gamma = scene.num("gamma", b.water.gamma);
  b.water.kT = scene.num("kT", b.water.kT);
  b.water.lambda = scene.num("lambda", b.water.lambda);
  b.water.dt = scene.num("dt", b.water.dt);
  b.water.steps = scene.integer("steps", b.water.steps, 1, 100'000'000);
  b.water.equilibrate = scene.integer("equilibrate", b.water.equilibrate, 0, 100'000'000);
  b.water.init_seed = static_cast<std::uint64_t>(scene.integer("init_seed", 2021, 0, (1L << 62)));
  b.noise.seed = static_cast<std::uint64_t>(scene.integer("seed", 1, 0, (1L << 62)));
  scene.done();
  Keys tests(root["tests"].as_table(), "tests", origin);
  b.chi2_every = static_cast<int>(tests.integer("chi2_every", b.chi2_every, 0, 1'000'000));
  b.ttest_pairs = static_cast<int>(tests.integer("ttest_pairs", b.ttest_pairs, 0, 20000));
  b.alpha = tests.num("alpha", b.alpha);
  tests.done();
  top.get("scene"), top.get("tests");
  top.done();
  named(top, "scene", [&] {
    DecompConfig c = b;
    c.noise.generator = s.generators.front();
    c.validate();
    return 0;
  });
  return s;
}

DecompSweep load_decomp_sweep(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_decomp_sweep(ss.str(), path);
}

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

namespace {
void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream o(p);
  if (!o) throw InputError("cannot write " + p.string());
  o << text;
  if (!o) throw std::runtime_error("write failed: " + p.string());
}
}  // namespace

std::string write_decomp_outputs(const DecompSweep& sw, const std::vector<DecompResult>& rows, const std::string& out,
                                 std::ostream* log) {
  const std::filesystem::path dir(out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("cannot create " + out + ": " + ec.message());
  std::string md = "# " + sw.name + "\n\n" + (sw.description.empty() ? "" : sw.description + "\n\n") +
                   decomp_table_markdown(rows);
  write_file(dir / "table.csv", decomp_table_csv(rows));
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : rows) j.push_back(to_json(r));
  write_file(dir / "results.json", j.dump(1) + "\n");
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  for (const auto& c : decomp_charts(rows)) {
    write_file(dir / (c.name + ".dat"), c.data);
    write_file(dir / (c.name + ".gp"), c.script);
    md += "\n![" + c.name + "](" + c.name + ".svg)\n";
    if (!gnuplot) continue;
    const std::string cmd = "cd '" + dir.string() + "' && gnuplot -e \"set terminal svg size 1100,520 dynamic; set output '" +
                            c.name + ".svg'\" '" + c.name + ".gp' 2>'" + c.name + ".gnuplot.log'";
    if (std::system(cmd.c_str()) != 0 && log) *log << "gnuplot failed for " << c.name << " (see its .gnuplot.log)\n";
  }
  write_file(dir / "table.md", md);
  return md;
}

}  // namespace dpdrng::dpd
