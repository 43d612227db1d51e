// The decomposition check's inputs: the --domains and --seeding texts, a run's validation, and the sweep config
// (TOML). Kept apart from the engine so that a config can be read (and fuzzed) without it.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/decomposition_sweep.hpp"
#include "dpdrng/rng/seeding_repair.hpp"

namespace dpdrng::dpd {

DomainGrid parse_domains(std::string_view text) {
  DomainGrid g;
  const std::string t(text);
  const std::string why = "--domains must be 1 to 3 comma-separated counts in 1..64 (\"2\", \"2,2,1\"), got '" + t + "'";
  std::size_t pos = 0;
  int axis = 0;
  while (true) {
    if (axis == 3) throw InputError(why);
    const std::size_t comma = t.find(',', pos);
    const std::string part = t.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (part.empty() || part.size() > 2 || !std::all_of(part.begin(), part.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
      throw InputError(why);
    const int v = std::stoi(part);
    if (v < 1 || v > 64) throw InputError(why);
    g.n[axis++] = v;
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return g;
}

std::string to_string(const DomainGrid& g) {
  return std::to_string(g.n[0]) + "x" + std::to_string(g.n[1]) + "x" + std::to_string(g.n[2]);
}

DecompSeeding parse_decomp_seeding(std::string_view text) {
  DecompSeeding s;
  if (text == "distance") return s;
  if (text == "pair-step") return s.kind = DecompSeedingKind::pair_step, s;
  if (text == "canonical") return s.kind = DecompSeedingKind::canonical, s;
  if (text == "grid") return s.kind = DecompSeedingKind::grid, s;
  if (text.starts_with("grid:")) {
    const std::string k(text.substr(5));
    const bool digits = !k.empty() && k.size() <= 2 && std::all_of(k.begin(), k.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int bits = digits ? std::stoi(k) : -1;
    if (bits < rng::kMinGridBits || bits > rng::kMaxGridBits)
      throw InputError("grid seeding: the grid exponent K in 'grid:K' must be " + std::to_string(rng::kMinGridBits) +
                       ".." + std::to_string(rng::kMaxGridBits) + ", got '" + k + "'");
    s.kind = DecompSeedingKind::grid;
    s.grid_bits = bits;
    return s;
  }
  throw InputError("unknown seeding '" + std::string(text) +
                   "' (known: distance, pair-step, grid, grid:K, canonical)");
}

std::string to_string(const DecompSeeding& s) {
  switch (s.kind) {
    case DecompSeedingKind::distance: return "distance";
    case DecompSeedingKind::pair_step: return "pair-step";
    case DecompSeedingKind::canonical: return "canonical";
    case DecompSeedingKind::grid: return "grid:" + std::to_string(s.grid_bits);
  }
  return "?";
}

void DecompConfig::validate() const {
  WaterConfig w = water;
  w.generator = noise.generator;
  w.distribution = noise.distribution;
  w.feed = noise.feed;
  w.seeding = rng::Seeding::distance;
  w.taps = {};
  w.validate();
  // Every pair is visited every step (twice): fine for the paper's 256 beads, not for a membrane.
  if (w.particles > 20000) throw InputError("particles: the decomposition check visits all pairs; at most 20000");
  if (chi2_every < 0) throw InputError("chi2_every must not be negative");
  if (ttest_pairs < 0 || ttest_pairs >= w.particles) throw InputError("ttest_pairs must be in 0..particles-1");
  if (!(alpha > 0 && alpha < 1)) throw InputError("alpha must be in (0, 1)");
  if (noise.seeding.kind == DecompSeedingKind::grid &&
      (noise.seeding.grid_bits < rng::kMinGridBits || noise.seeding.grid_bits > rng::kMaxGridBits))
    throw InputError("grid seeding: grid_bits out of range");
}

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
  // A sub-table, or nullptr when the key is absent; a key that is not a table is an error.
  const toml::table* table(const std::string& key) {
    const toml::node* n = get(key);
    if (n && !n->is_table()) fail(key, "must be a table ([" + key + "])");
    return n ? n->as_table() : nullptr;
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
  if (root.contains("study") || root.contains("sweep"))
    throw InputError(origin + ": this is a study config ([study], [sweep]), not a decomposition sweep: run it with "
                              "`dpdrng study run " + origin + "`");
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
  Keys scene(top.table("scene"), "scene", origin);
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
  Keys tests(top.table("tests"), "tests", origin);
  b.chi2_every = static_cast<int>(tests.integer("chi2_every", b.chi2_every, 0, 1'000'000));
  b.ttest_pairs = static_cast<int>(tests.integer("ttest_pairs", b.ttest_pairs, 0, b.water.particles - 1));
  b.alpha = tests.num("alpha", b.alpha);
  if (!(b.alpha > 0 && b.alpha < 1)) tests.fail("alpha", "must be within (0, 1)");
  tests.done();
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

}  // namespace dpdrng::dpd
