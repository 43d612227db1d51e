#include "dpdrng/study/config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/common/sha256.hpp"
#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/study/observables.hpp"
#include "dpdrng/study/sweep.hpp"
#include "toml_section.hpp"

namespace dpdrng::study {
namespace {

// The one rule for lists: a value given twice is refused, naming it.
std::string value_text(double x) { return exact_decimal(x); }
template <class E>
std::string value_text(E e) {
  return std::string(rng::to_string(e));
}

template <class T>
void check_unique(Section& s, const std::string& key, const std::vector<T>& v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (v[j] == v[i]) s.fail(key, "lists " + value_text(v[i]) + " twice");
}

template <class E>
std::vector<std::string> names_of(const std::vector<E>& v) {
  std::vector<std::string> out;
  for (E e : v) out.emplace_back(rng::to_string(e));
  return out;
}

// Each name through `parse`, whose InputError becomes the key's; a name listed twice is refused.
template <class Parse>
auto parsed_list(Section& s, const std::string& key, const std::vector<std::string>& names, Parse parse) {
  std::vector<decltype(parse(std::string_view{}))> out;
  for (const auto& name : names) try {
      out.push_back(parse(name));
    } catch (const InputError& e) {
      s.fail(key, e.what());
    }
  check_unique(s, key, out);
  return out;
}

std::vector<rng::Distribution> valid_distributions(Section& s, const std::string& key,
                                                   const std::vector<rng::Distribution>& def) {
  return parsed_list(s, key, s.strings(key, names_of(def)), rng::parse_distribution);
}

std::vector<rng::Feed> valid_feeds(Section& s, const std::string& key, const std::vector<rng::Feed>& def) {
  const std::vector<std::string> names = s.strings(key, names_of(def));
  if (names.empty()) s.fail(key, "needs at least one feed");
  return parsed_list(s, key, names, rng::parse_feed);
}

std::vector<std::string> valid_integrators(Section& s, const std::string& key, std::vector<std::string> v) {
  if (v.empty()) s.fail(key, "needs at least one integrator (leave the key out for MVV at the scene's lambda)");
  std::vector<IntegratorSpec> specs;
  for (const auto& name : v) try {
      specs.push_back(parse_integrator_spec(name));
    } catch (const InputError& e) {
      s.fail(key, e.what());
    }
  // Two spellings of one integrator ("scmvv:5" and "scmvv:05") would run the same cells twice.
  for (std::size_t i = 0; i < specs.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (specs[j] == specs[i]) s.fail(key, "'" + v[j] + "' and '" + v[i] + "' name the same integrator");
  return v;
}

std::vector<rng::Seeding> valid_seedings(Section& s, const std::string& key, const std::vector<rng::Seeding>& def) {
  return parsed_list(s, key, s.strings(key, names_of(def)), [](std::string_view name) {
    const rng::Seeding seeding = rng::parse_seeding(name);
    if (seeding == rng::Seeding::counter) throw InputError("'counter' makes standalone streams, not pair noise");
    return seeding;
  });
}

std::set<std::string>& allowed_plugins() {
  static std::set<std::string> allowed;
  return allowed;
}

std::string canonical_file(const std::string& path) {
  std::error_code ec;
  const auto c = std::filesystem::canonical(path, ec);
  if (ec) throw InputError("plug-in '" + path + "': " + ec.message());
  return c.string();
}

// The digest of the library an ext: entry names, after its pin or the command line allowed it; then it loads.
std::string consented_plugin(Section& g, const std::string& name) {
  const std::string path = name.substr(rng::kPluginPrefix.size());
  const std::string pinned = g.str("sha256", "");
  std::string actual;
  try {
    actual = sha256_file(canonical_file(path));
  } catch (const InputError& e) {
    g.fail("name", e.what());
  }
  if (!pinned.empty() && pinned != actual)
    g.fail("sha256", "pins " + pinned + " but '" + path + "' has " + actual +
                         ": refusing to load a library other than the one the config names");
  if (pinned.empty() && !allowed_plugins().contains(canonical_file(path)))
    g.fail("name", "'" + name + "' loads native code: pin it with sha256 = \"" + actual +
                       "\" in this entry (the library's digest now), or allow it for this run with --allow-plugin " +
                       path);
  return actual;
}

const rng::GeneratorInfo& known_generator(Section& s, const std::string& key, const std::string& name) {
  try {
    return rng::find_generator(name);
  } catch (const InputError& e) {
    s.fail(key, e.what());
  }
}

// The bilayer scene fixes its box, composition and a_ij (dpd::BilayerConfig); the study may set the rest.
SceneParams bilayer_scene_defaults() {
  const dpd::BilayerConfig b;
  SceneParams s;
  s.name = "bilayer";
  s.particles = b.particles;
  s.density = b.particles / (b.box[0] * b.box[1] * b.box[2]);
  s.a = 0;
  s.gamma = b.gamma;
  s.kT = b.kT;
  s.lambda = b.lambda;
  s.dt = {b.dt};
  s.steps = b.steps;
  s.equilibrate = b.equilibrate;
  s.pairs = b.pairs;
  return s;
}

// particles and density both appear in the config (as for water), but the box is the scene's: they must agree.
void check_bilayer_box(Section& sc, const SceneParams& s) {
  const dpd::BilayerConfig b;
  const double volume = b.box[0] * b.box[1] * b.box[2];
  if (std::abs(s.particles - s.density * volume) > 0.5) {
    std::ostringstream msg;
    msg << s.particles << " beads at density " << s.density << " do not fill the bilayer scene's fixed box "
        << b.box[0] << " x " << b.box[1] << " x " << b.box[2] << " (volume " << volume << "; e.g. "
        << std::lround(s.density * volume) << " beads at this density)";
    sc.fail("particles", msg.str());
  }
  const long lipid_beads = 2L * b.lipids_per_leaflet * dpd::kLipidBeads;
  if (s.particles < lipid_beads)
    sc.fail("particles", std::to_string(s.particles) + " is fewer than the " + std::to_string(lipid_beads) +
                             " beads of the scene's lipids");
}

// [tests.margins]: each key an observable's (observables.hpp), each value in (0, 1]; the rest at their defaults.
std::map<std::string, double> valid_margins(Section& te) {
  Section m = te.sub("margins");
  std::map<std::string, double> out;
  for (const auto& d : margin_defaults()) out[d.key] = m.num(d.key, d.margin, 0, 1, true);
  m.finish();
  return out;
}

}  // namespace

std::string fnv1a64_hex(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

long SceneParams::steps_at(double dt) const { return time > 0 ? std::lround(time / dt) : steps; }
long SceneParams::equilibrate_at(double dt) const {
  return time > 0 ? std::lround(equilibrate_time / dt) : equilibrate;
}

const char* to_string(ErrorControl e) { return e == ErrorControl::study ? "study" : "variant"; }

nlohmann::json StudyConfig::canonical() const {
  // Keys are only ever added for new scenes: a changed canonical form of a water config would change its hash,
  // and existing result directories would refuse to resume or report.
  nlohmann::json scene_json = {{"name", scene.name},   {"particles", scene.particles}, {"density", scene.density},
                               {"gamma", scene.gamma}, {"kT", scene.kT},               {"lambda", scene.lambda},
                               {"dt", scene.dt},       {"steps", scene.steps},         {"equilibrate", scene.equilibrate},
                               {"pairs", dpd::to_string(scene.pairs)}};
  if (!scene.is_bilayer()) scene_json["a"] = scene.a;  // the bilayer's a_ij are fixed by the scene
  nlohmann::json gens = nlohmann::json::array();
  for (const auto& g : generators) {
    gens.push_back({{"name", g.name}, {"rounds", g.rounds}, {"seedings", names_of(g.seedings)}});
    // A changed plug-in library changes the hash: a study refuses to resume or merge under another library.
    if (!g.sha256.empty()) gens.back()["sha256"] = g.sha256;
  }
  nlohmann::json j = {
      {"name", name},
      {"reference", reference},
      {"replicas", replicas},
      {"seed", seed},
      {"generators", gens},
      {"distributions", names_of(distributions)},
      {"seedings", names_of(seedings)},
      {"scene", scene_json},
      {"tests",
       {{"alpha", tests.alpha}, {"chi2_steps", tests.chi2_steps}, {"ttest_pairs", tests.ttest_pairs},
        {"nist_sequences", tests.nist_sequences}, {"nist_bits", tests.nist_bits},
        {"nist_generators", tests.nist_generators}, {"nist_distributions", names_of(tests.nist_distributions)},
        {"nist_replicas", tests.nist_replicas}}},
      {"cost", {{"numbers", cost.numbers}}},
  };
  // The margins are left out: they judge the cells, they do not make them, so a study directory may be
  // reported again under other margins.
  // Present only when it is not the default, so that configs without the key keep their hash.
  if (reference_replica_count() != replicas) j["reference_replicas"] = reference_replica_count();
  if (tests.error_control != ErrorControl::study) j["tests"]["error_control"] = to_string(tests.error_control);
  if (feeds != std::vector<rng::Feed>{rng::Feed::halves}) j["feeds"] = names_of(feeds);
  if (!integrators.empty()) j["integrators"] = integrators;
  if (!reference_gammas.empty()) j["reference_gammas"] = reference_gammas;
  if (!extra_replicas.empty()) {
    nlohmann::json e = nlohmann::json::object();
    for (const auto& [dt, n] : extra_replicas) e[exact_decimal(dt)] = n;
    j["extra_replicas"] = e;
  }
  if (scene.time > 0) j["scene"]["time"] = scene.time, j["scene"]["equilibrate_time"] = scene.equilibrate_time;
  return j;
}

void allow_plugin(const std::string& path) { allowed_plugins().insert(canonical_file(path)); }

StudyConfig parse_config(const std::string& toml_text, const std::string& origin) {
  const toml::table root = parse_toml(toml_text, origin);
  if (!root.contains("study") && (root.contains("domains") || root.contains("generators")))
    throw InputError(origin + ": this is a decomposition sweep (top-level domains/generators), not a study config: "
                              "run it with `dpdrng decompose --study " + origin + "`");
  StudyConfig c;
  c.source_text = toml_text;
  Section top(&root, "", origin);

  Section st = top.sub("study");
  c.name = st.str("name", "");
  if (c.name.empty()) st.fail("name", "is required");
  if (c.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") !=
      std::string::npos)
    st.fail("name", "may contain only letters, digits, '_', '-' and '.' (it names a directory)");
  c.description = st.str("description", "");
  c.reference = st.str("reference", c.reference);
  if (known_generator(st, "reference", c.reference).keyed_hash)
    st.fail("reference", "must be a stream generator (mt19937)");
  c.replicas = static_cast<int>(st.integer("replicas", c.replicas, 1, 1000));
  if (st.get("reference_replicas"))
    c.reference_replicas = static_cast<int>(st.integer("reference_replicas", 0, c.replicas, 1000));
  c.seed = static_cast<std::uint64_t>(st.integer("seed", 1, 0, std::numeric_limits<long>::max()));
  st.finish();

  Section sw = top.sub("sweep");
  c.distributions = valid_distributions(sw, "distributions", c.distributions);
  c.seedings = valid_seedings(sw, "seedings", c.seedings);
  c.feeds = valid_feeds(sw, "feeds", c.feeds);
  if (sw.get("integrators")) c.integrators = valid_integrators(sw, "integrators", sw.strings("integrators", {}));
  if (sw.get("reference_gammas")) {
    c.reference_gammas = sw.numbers("reference_gammas", {}, 0, 1e6, true);
    if (c.reference_gammas.empty()) sw.fail("reference_gammas", "needs at least one value (or leave the key out)");
    check_unique(sw, "reference_gammas", c.reference_gammas);
  }
  if (sw.get("extra_replicas")) {
    Section er = sw.sub("extra_replicas");
    const toml::node* n = sw.get("extra_replicas");
    for (const auto& [k, v] : *n->as_table()) {
      const std::string key(k.str());
      const double dt = named(er, key, [&] { return parse_real(key, "the Δt"); });
      c.extra_replicas[dt] = static_cast<int>(er.integer(key, 0, c.replicas + 1, 1000));
    }
    if (c.extra_replicas.empty()) sw.fail("extra_replicas", "needs at least one Δt (or leave the key out)");
    er.finish();
  }
  const toml::array* gens = sw.array_of_tables("generator");
  if (!gens || gens->empty()) sw.fail("generator", "at least one [[sweep.generator]] is required");
  for (std::size_t k = 0; k < gens->size(); ++k) {
    Section g(gens->get(k)->as_table(), sw.full("generator") + "[" + std::to_string(k) + "]", origin);
    GeneratorEntry e;
    e.name = g.str("name", "");
    if (e.name.empty()) g.fail("name", "is required");
    if (rng::is_plugin(e.name))
      e.sha256 = consented_plugin(g, e.name);
    else if (g.get("sha256"))
      g.fail("sha256", "pins a plug-in library: '" + e.name + "' is a built-in generator");
    if (!known_generator(g, "name", e.name).keyed_hash)
      g.fail("name", "'" + e.name + "' is a stream, not a pair-keyed hash (it is the reference, always run)");
    for (long r : g.integers("rounds", 1, 1 << 20)) {
      rng::GeneratorSpec spec;
      spec.name = e.name;
      spec.rounds = static_cast<int>(r);
      try {
        rng::validated(spec);
      } catch (const InputError& ex) {
        g.fail("rounds", ex.what());
      }
      if (std::find(e.rounds.begin(), e.rounds.end(), r) != e.rounds.end()) g.fail("rounds", "lists a value twice");
      e.rounds.push_back(static_cast<int>(r));
    }
    if (e.rounds.empty()) e.rounds.push_back(rng::validated(rng::GeneratorSpec{e.name, 0, rng::kPaperTeaKey}).rounds);
    if (g.get("seedings")) e.seedings = valid_seedings(g, "seedings", {});
    g.finish();
    for (const auto& prev : c.generators) {
      if (prev.name == e.name) g.fail("name", "'" + e.name + "' appears twice; list all its rounds in one entry");
      if (generator_tag(prev.name) == generator_tag(e.name))
        g.fail("name", "'" + e.name + "' and '" + prev.name + "' would share the cell ids " + generator_tag(e.name) +
                           "-…: give the libraries different file names");
    }
    c.generators.push_back(std::move(e));
  }
  sw.finish();

  Section sc = top.sub("scene");
  auto& s = c.scene;
  s.name = sc.str("name", s.name);
  if (s.name == "bilayer")
    s = bilayer_scene_defaults();
  else if (s.name != "water")
    sc.fail("name", "unknown scene '" + s.name + "' (known: water, bilayer)");
  const bool bilayer = s.name == "bilayer";
  s.particles = static_cast<int>(sc.integer("particles", s.particles, 2, 10'000'000));
  s.density = sc.num("density", s.density, 0, 100, true);
  if (bilayer) {
    if (sc.get("a"))
      sc.fail("a", "not used by the bilayer scene, whose a_ij matrix is fixed (HH 30, HT 35, HW 30, TT 10, TW 75, "
                   "WW 25): remove the key");
    check_bilayer_box(sc, s);
  } else {
    s.a = sc.num("a", s.a, 0, 1e6);
  }
  s.gamma = sc.num("gamma", s.gamma, 0, 1e6);
  s.kT = sc.num("kT", s.kT, 0, 1e6, true);
  s.lambda = sc.num("lambda", s.lambda, 0, 1);
  s.dt = sc.numbers("dt", s.dt, 0, 10, true);
  check_unique(sc, "dt", s.dt);
  if (sc.get("time")) {
    if (bilayer) sc.fail("time", "is for the water scene (the bilayer runs scene.steps)");
    if (sc.get("steps") || sc.get("equilibrate"))
      sc.fail("time", "replaces steps and equilibrate (give time and equilibrate_time, or steps and equilibrate)");
    s.time = sc.num("time", 0, 0, 1e9, true);
    s.equilibrate_time = sc.num("equilibrate_time", 0.05 * s.time, 0, s.time);
    for (double dt : s.dt) {
      if (s.time / dt > 1e9) sc.fail("time", "gives more than 1e9 steps at dt = " + exact_decimal(dt));
      if (s.steps_at(dt) < 2) sc.fail("time", "gives fewer than 2 steps at dt = " + exact_decimal(dt));
      if (s.equilibrate_at(dt) >= s.steps_at(dt))
        sc.fail("equilibrate_time", "leaves no production step at dt = " + exact_decimal(dt));
    }
  } else {
    if (sc.get("equilibrate_time")) sc.fail("equilibrate_time", "needs scene.time");
    s.steps = sc.integer("steps", s.steps, 2, 1'000'000'000);
    s.equilibrate = sc.integer("equilibrate", s.equilibrate, 0, 1'000'000'000);
    if (s.equilibrate >= s.steps) sc.fail("equilibrate", "must be less than scene.steps");
  }
  const std::string pair_mode = sc.str("pairs", std::string(dpd::to_string(s.pairs)));
  if (pair_mode != "all" && pair_mode != "cells") sc.fail("pairs", "must be 'all' or 'cells'");
  s.pairs = dpd::parse_pair_mode(pair_mode);
  sc.finish();
  if (bilayer && !c.integrators.empty())
    throw InputError(origin + ": sweep.integrators: the bilayer scene runs MVV at its lambda only (remove the key)");
  if (bilayer && !c.reference_gammas.empty())
    throw InputError(origin + ": sweep.reference_gammas: is for the water scene (remove the key)");
  for (const auto& [dt, n] : c.extra_replicas)
    if (std::find(s.dt.begin(), s.dt.end(), dt) == s.dt.end())
      throw InputError(origin + ": sweep.extra_replicas: " + exact_decimal(dt) + " is not one of scene.dt");
  for (double g : c.reference_gammas)
    if (g == s.gamma)
      throw InputError(origin + ": sweep.reference_gammas: " + exact_decimal(g) +
                       " is the scene's gamma, whose cells run anyway (remove it)");

  Section te = top.sub("tests");
  auto& t = c.tests;
  t.alpha = te.num("alpha", t.alpha, 0, 0.5, true);
  const std::string control = te.str("error_control", to_string(t.error_control));
  if (control == "study")
    t.error_control = ErrorControl::study;
  else if (control == "variant")
    t.error_control = ErrorControl::variant;
  else
    te.fail("error_control", std::string("must be \"study\" or \"variant\", not ").append(control));
  // Bilayer cells measure physics only: the engine taps no raw numbers there, so the generators' own tests
  // default to off and asking for them is an error rather than an empty table.
  if (bilayer) t.chi2_steps = 0, t.ttest_pairs = 0;
  // The shortest production of any Δt bounds what the tests may sample.
  long production = s.steps - s.equilibrate;
  for (double dt : s.dt) production = std::min(production, s.steps_at(dt) - s.equilibrate_at(dt));
  t.chi2_steps = te.integer("chi2_steps", t.chi2_steps, 0, production);
  const long pairs = static_cast<long>(s.particles) * (s.particles - 1) / 2;
  t.ttest_pairs = te.integer("ttest_pairs", t.ttest_pairs, 0, pairs);
  if (t.ttest_pairs > 0 && production < 4) te.fail("ttest_pairs", "needs at least 4 production steps");
  t.nist_sequences = te.integer("nist_sequences", t.nist_sequences, 1, 100'000);
  t.nist_bits = te.integer("nist_bits", t.nist_bits, 64, 1L << 30);
  if (t.nist_bits % 64 != 0) te.fail("nist_bits", "must be a multiple of 64 (sequences are cut from 64-bit words)");
  // An explicit empty list is how a config says "no NIST" (the bilayer's must say so).
  const toml::node* nist_gens = te.get("nist_generators");
  const bool none = nist_gens && nist_gens->as_array() && nist_gens->as_array()->empty();
  t.nist_generators = nist_gens && !none ? te.strings("nist_generators", {}) : std::vector<std::string>{};
  for (const auto& g : t.nist_generators) {
    const bool known = g == c.reference || std::any_of(c.generators.begin(), c.generators.end(),
                                                        [&](const GeneratorEntry& e) { return e.name == g; });
    if (!known) te.fail("nist_generators", "'" + g + "' is not swept by this study");
  }
  t.nist_distributions = valid_distributions(te, "nist_distributions", t.nist_distributions);
  t.nist_replicas = static_cast<int>(te.integer("nist_replicas", t.nist_replicas, 0, c.replicas));
  t.margins = valid_margins(te);
  if (bilayer) {
    const char* why = "must be 0 for the bilayer scene: its cells tap no raw numbers (the water scene tests the "
                      "generators' outputs)";
    if (t.chi2_steps != 0) te.fail("chi2_steps", why);
    if (t.ttest_pairs != 0) te.fail("ttest_pairs", why);
    if (!t.nist_generators.empty())
      te.fail("nist_generators", "must be empty for the bilayer scene: its cells tap no raw numbers");
  }
  te.finish();

  Section co = top.sub("cost");
  c.cost.numbers = co.integer("numbers", c.cost.numbers, 1024, 1L << 32);
  co.finish();

  top.finish();
  // A cell's id names its file and its group in study.h5: two cells under one id would overwrite each other.
  std::set<std::string> ids;
  for (const Cell& cell : enumerate_cells(c))
    if (!ids.insert(cell.id()).second)
      throw InputError(origin + ": two cells of this config share the id " + cell.id() +
                       " (sweep entries that differ only in how they are written?)");
  c.hash = fnv1a64_hex(c.canonical().dump());
  return c;
}

StudyConfig load_config(const std::string& path) {
  // A directory opens like an empty file: without this it would read as a config that lacks every key.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a study config (TOML)" +
                     (std::filesystem::exists(std::filesystem::path(path) / "study.toml", ec)
                          ? std::string("; the study it holds was made with ") + path + "/study.toml"
                          : std::string("; it holds no study (no study.toml)")));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the study config");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_config(text.str(), path);
}

}  // namespace dpdrng::study
