// The decomposition sweep's config (TOML) and a run's validation, on the study's TOML reader. Kept apart from
// the runs so that a config can be read (and fuzzed) without the engine running.
#include <fstream>
#include <limits>
#include <sstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/rng/seeding_repair.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"
#include "toml_section.hpp"

namespace dpdrng::study {

using namespace dpdrng::dpd;

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
  // A domain narrower than r_c would need ghosts from beyond its neighbours, which a spatial decomposition does
  // not exchange: the check would emulate no code.
  const double L = w.box_length();
  for (int axis = 0; axis < 3; ++axis)
    if (domains.cut(axis) && L / domains.n[axis] < w.rc)
      throw InputError("domains: " + std::to_string(domains.n[axis]) + " domains along " + "xyz"[axis] +
                       " make them " + format_g(L / domains.n[axis]) + " wide in a box of " + format_g(L) +
                       ", narrower than r_c = " + format_g(w.rc) + " (at most " +
                       std::to_string(static_cast<int>(L / w.rc)) + " per axis)");
  if (chi2_every < 0) throw InputError("chi2_every must not be negative");
  if (ttest_pairs < 0 || ttest_pairs >= w.particles) throw InputError("ttest_pairs must be in 0..particles-1");
  if (!(alpha > 0 && alpha < 1)) throw InputError("alpha must be in (0, 1)");
  if (noise.seeding.kind == DecompSeedingKind::grid &&
      (noise.seeding.grid_bits < rng::kMinGridBits || noise.seeding.grid_bits > rng::kMaxGridBits))
    throw InputError("grid seeding: grid_bits out of range");
}

nlohmann::json DecompSweep::canonical() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& g : generators) j["generators"].push_back(rng::describe(g));
  for (const auto& s : seedings) j["seedings"].push_back(to_string(s));
  for (auto d : distributions) j["distributions"].push_back(std::string(rng::to_string(d)));
  for (const auto& d : domains) j["domains"].push_back(to_string(d));
  const WaterConfig& w = base.water;
  j["scene"] = {{"particles", w.particles}, {"density", w.density}, {"a", w.a},   {"rc", w.rc},
                {"kT", w.kT},               {"gamma", w.gamma},     {"lambda", w.lambda}, {"dt", w.dt},
                {"steps", w.steps},         {"equilibrate", w.equilibrate}, {"init_seed", w.init_seed},
                {"seed", base.noise.seed},  {"feed", std::string(rng::to_string(base.noise.feed))}};
  j["tests"] = {{"chi2_every", base.chi2_every}, {"ttest_pairs", base.ttest_pairs}, {"alpha", base.alpha}};
  return j;
}

// Out-of-range scene values are refused by DecompConfig::validate(), with the water scene's messages.
constexpr double kAny = std::numeric_limits<double>::max();

DecompSweep parse_decomp_sweep(const std::string& text, const std::string& origin) {
  const toml::table root = parse_toml(text, origin);
  if (root.contains("study") || root.contains("sweep"))
    throw InputError(origin + ": this is a study config ([study], [sweep]), not a decomposition sweep: run it with "
                              "`dpdrng study run " + origin + "`");
  DecompSweep s;
  Section top(&root, "", origin);
  s.name = top.str("name", s.name);
  s.description = top.str("description", "");
  for (const auto& d : top.strings("domains", {"2"})) s.domains.push_back(named(top, "domains", [&] { return parse_domains(d); }));
  for (const auto& d : top.strings("seedings", {"distance", "pair-step", "grid", "canonical"}))
    s.seedings.push_back(named(top, "seedings", [&] { return parse_decomp_seeding(d); }));
  s.distributions.clear();
  for (const auto& d : top.strings("distributions", {"gauss"}))
    s.distributions.push_back(named(top, "distributions", [&] { return rng::parse_distribution(d); }));

  const toml::array* gens = top.array_of_tables("generators");
  if (!gens) top.fail("generators", "needs at least one [[generators]] table");
  std::size_t gi = 0;
  for (const auto& node : *gens) {
    Section g(node.as_table(), "generators[" + std::to_string(gi++) + "]", origin);
    rng::GeneratorSpec spec;
    spec.name = g.str("name", "");
    if (spec.name.empty()) g.fail("name", "is required");
    std::vector<long> rounds = g.integers("rounds", 0, 64);
    if (rounds.empty()) rounds.push_back(0);
    for (long r : rounds) {
      spec.rounds = static_cast<int>(r);
      s.generators.push_back(named(g, "rounds", [&] { return rng::validated(spec); }));
    }
    g.finish();
  }

  DecompConfig& b = s.base;
  Section scene = top.sub("scene");
  if (scene.str("name", "water") != "water") scene.fail("name", "only the water scene is supported");
  b.water.particles = static_cast<int>(scene.integer("particles", 256, 2, 20000));
  b.water.density = scene.num("density", b.water.density, -kAny, kAny);
  b.water.a = scene.num("a", b.water.a, -kAny, kAny);
  b.water.gamma = scene.num("gamma", b.water.gamma, -kAny, kAny);
  b.water.kT = scene.num("kT", b.water.kT, -kAny, kAny);
  b.water.lambda = scene.num("lambda", b.water.lambda, -kAny, kAny);
  b.water.dt = scene.num("dt", b.water.dt, -kAny, kAny);
  b.water.steps = scene.integer("steps", b.water.steps, 1, 100'000'000);
  b.water.equilibrate = scene.integer("equilibrate", b.water.equilibrate, 0, 100'000'000);
  b.water.init_seed = static_cast<std::uint64_t>(scene.integer("init_seed", 2021, 0, (1L << 62)));
  b.noise.seed = static_cast<std::uint64_t>(scene.integer("seed", 1, 0, (1L << 62)));
  scene.finish();
  Section tests = top.sub("tests");
  b.chi2_every = static_cast<int>(tests.integer("chi2_every", b.chi2_every, 0, 1'000'000));
  b.ttest_pairs = static_cast<int>(tests.integer("ttest_pairs", b.ttest_pairs, 0, b.water.particles - 1));
  b.alpha = tests.num("alpha", b.alpha, -kAny, kAny);
  if (!(b.alpha > 0 && b.alpha < 1)) tests.fail("alpha", "must be within (0, 1)");
  tests.finish();
  top.finish();
  named(top, "scene", [&] {
    DecompConfig c = b;
    c.noise.generator = s.generators.front();
    c.validate();
    return 0;
  });
  s.source_text = text;
  s.hash = fnv1a64_hex(s.canonical().dump());
  return s;
}

DecompSweep load_decomp_sweep(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_decomp_sweep(ss.str(), path);
}

}  // namespace dpdrng::study
