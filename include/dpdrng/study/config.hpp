#pragma once
// A study configuration: what to sweep (generators × rounds × distributions × seedings × Δt × integrators ×
// replicas), the
// scene, and the sizes of the tests. Parsed from TOML and validated completely before anything is written:
// an unknown key, a NaN or an out-of-range value is an InputError that names the key.
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::study {

struct GeneratorEntry {
  std::string name;
  std::vector<int> rounds;             // empty in TOML → the generator's default round count
  std::vector<rng::Seeding> seedings;  // empty → the study's seedings
  std::string sha256;                  // a plug-in's: the digest of its library (pinned by the config or allowed)
};

// name = "water" (the paper's fluid) or "bilayer" (the H3(T6)2 membrane of dpd/bilayer.hpp: box, lipids and a_ij
// fixed by the scene, `a` refused, particles/density must fill its 10 x 10 x 18 box; the other fields default to
// the scene's values).
struct SceneParams {
  std::string name = "water";
  int particles = 256;
  double density = 3.0;
  double a = 25.0;
  double gamma = 6.75;
  double kT = 1.0;
  double lambda = 0.5;
  std::vector<double> dt{0.04};  // more than one value makes Δt a sweep dimension
  long steps = 10000;
  long equilibrate = 500;
  // Simulated time instead of a step count (0: unused): each Δt then runs round(time / Δt) steps, of which
  // round(equilibrate_time / Δt) equilibrate, so that a Δt sweep compares runs of one physical length.
  double time = 0, equilibrate_time = 0;
  dpd::PairMode pairs = dpd::PairMode::all;

  bool is_bilayer() const { return name == "bilayer"; }
  long steps_at(double dt) const;
  long equilibrate_at(double dt) const;
};

// Which family of tests the report holds at family-wise error rate α (Holm's procedure): every comparison of
// every variant in the study, or each variant's own comparisons (then a study of k variants can raise up to
// k false alarms at α each).
enum class ErrorControl { study, variant };
const char* to_string(ErrorControl e);

struct TestParams {
  double alpha = 0.01;
  ErrorControl error_control = ErrorControl::study;
  long chi2_steps = 0;        // production steps sampled for the χ² pass fraction; 0 = every one
  long ttest_pairs = 100;     // pairs whose series get the lag-1 t-test
  long nist_sequences = 1000;
  long nist_bits = 1 << 20;
  std::vector<std::string> nist_generators;  // generators whose cells also get the NIST battery
  std::vector<rng::Distribution> nist_distributions{rng::Distribution::gauss};
  int nist_replicas = 1;      // only the first nist_replicas replicas: the outputs are the generator's either way
  // [tests.margins]: the equivalence margin δ of each observable (observables.hpp: keys and defaults), a
  // fraction of the reference's value. Every key is present, at its default unless the config sets it.
  std::map<std::string, double> margins;
};

struct CostParams {
  long numbers = 1 << 22;  // words timed per generator for ns/number
};

struct StudyConfig {
  std::string name;
  std::string description;
  std::string reference = "mt19937";
  int replicas = 4;
  // Replicas of the reference (at least `replicas`; 0: as many). Every variant is compared with its reference,
  // so extra reference replicas narrow every comparison at the cost of one cell per feed each.
  int reference_replicas = 0;
  std::uint64_t seed = 1;
  std::vector<GeneratorEntry> generators;
  std::vector<rng::Distribution> distributions{rng::Distribution::gauss, rng::Distribution::uniform};
  // Which uniforms feed the Gaussian (rng::Feed); uniform noise always takes halves, so its cells are not
  // multiplied by the feeds.
  std::vector<rng::Feed> feeds{rng::Feed::halves};
  std::vector<rng::Seeding> seedings{rng::Seeding::distance};
  // [sweep] integrators ("mvv:<λ>", "shardlow"; sweep.hpp); empty: MVV at the scene's λ, not a factor.
  std::vector<std::string> integrators;
  // [sweep] reference_gammas: friction coefficients beside the scene's γ at which the reference alone runs (its
  // first noise, every integrator, Δt and replica): a friction series that needs no generator, e.g. γ = 4.5
  // against Groot & Warren's (1997) runs. Empty: none. Water scene only.
  std::vector<double> reference_gammas;
  // [sweep] extra_replicas = { "0.03" = 8 }: more replicas at chosen Δt of [scene] dt (near the accuracy
  // frontiers, where a CI decides the bracket), every variant and the reference alike; the other Δt keep
  // `replicas`. Empty: none.
  std::map<double, int> extra_replicas;
  SceneParams scene;
  TestParams tests;
  CostParams cost;

  std::string source_text;  // the TOML as given
  std::string hash;         // of the canonical form below, so comments and layout do not matter

  nlohmann::json canonical() const;
  int reference_replica_count() const { return std::max(reference_replicas, replicas); }
  // Replicas of every variant at Δt (extra_replicas or `replicas`), and of the reference (at least as many).
  int replicas_at(double dt) const {
    const auto it = extra_replicas.find(dt);
    return it == extra_replicas.end() ? replicas : std::max(replicas, it->second);
  }
  int reference_replicas_at(double dt) const { return std::max(reference_replica_count(), replicas_at(dt)); }
};

// A config that names a plug-in (`ext:PATH`) loads native code: it is read only when its entry pins the library's
// SHA-256 (`sha256 = "…"`) or the path is allowed for this process (`--allow-plugin PATH` of the study commands).
void allow_plugin(const std::string& path);  // InputError if the path does not name a file

// `origin` names the source in messages (a path, or "<string>").
StudyConfig parse_config(const std::string& toml_text, const std::string& origin);
StudyConfig load_config(const std::string& path);  // InputError if unreadable

std::string fnv1a64_hex(const std::string& text);

}  // namespace dpdrng::study
