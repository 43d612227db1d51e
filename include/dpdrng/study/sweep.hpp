#pragma once
// The sweep: a study expands into independent cells, one DPD run (plus its tests) each. The order is
// deterministic, so `--shard k/N` picks the same subset on every machine and a merge of all shards equals
// a single run.
#include <cstdint>
#include <string>
#include <vector>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/seeding.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

// One integrator of the sweep ([sweep] integrators): Groot–Warren MVV with its λ ("mvv:0.65"), Shardlow's S1
// splitting ("shardlow", λ unused), the self-consistent velocity-Verlet with K iterations ("scmvv:5") or the
// pairwise Nosé–Hoover–Langevin thermostat with coupling μ ("pnhln:10"). Cells of a study that sweeps none carry
// the empty name: MVV at the scene's λ.
struct IntegratorSpec {
  dpd::Integrator kind = dpd::Integrator::mvv;
  double lambda = 0.5;
  int iterations = dpd::kScmvvIterations;
  double mu = dpd::kPnhlnMu;
  bool operator==(const IntegratorSpec&) const = default;
  // mvv and scmvv draw their pair noise in the pair loop, whose numbers the tests tap; shardlow draws in its own
  // sweep and pnhln draws no pair noise.
  bool tapped() const { return kind == dpd::Integrator::mvv || kind == dpd::Integrator::scmvv; }
};
// InputError unless "mvv:<λ in [0, 1]>", "shardlow", "scmvv:<K in 1..100>" or "pnhln:<μ > 0>".
IntegratorSpec parse_integrator_spec(const std::string& text);
// The spec a cell runs: the named one, or MVV at the scene's λ for the empty name.
IntegratorSpec integrator_of(const std::string& name, const SceneParams& scene);

// The distribution with its feed when that is not halves: "gauss", "gauss-blocks", "uniform".
std::string noise_name(rng::Distribution d, rng::Feed f);
// The seeding's name, "stream" for the reference (the text stores and reports carry).
std::string seeding_name(rng::Seeding s, bool reference);

// The generator's part of a cell id, which is a file name: a plug-in (`ext:PATH`) becomes "ext-" and its library's
// file stem, other characters than letters, digits, '_' and '.' replaced by '_'.
std::string generator_tag(const std::string& generator);

struct Cell {
  std::string generator;
  int rounds = 1;
  rng::Distribution distribution = rng::Distribution::gauss;
  rng::Feed feed = rng::Feed::halves;  // a store written without the field reads halves
  rng::Seeding seeding = rng::Seeding::distance;  // unused by the reference, which draws from its stream
  double dt = 0.04;
  std::string integrator;  // [sweep] integrators entry; empty: MVV at the scene's λ (stores without the field)
  double gamma = 0;  // a [sweep] reference_gammas value; 0: the scene's γ (stores without the field)
  int replica = 0;
  bool reference = false;
  bool nist = false;  // this cell also feeds its outputs to the NIST battery
  std::uint64_t seed = 0;  // shared by all cells of one replica: paired comparisons start from the same state

  std::string noise() const;         // noise_name(distribution, feed)
  std::string seeding_name() const;  // "stream" for the reference
  // e.g. "tea32-r01-gauss-distance-dt0.04-rep00", a valid file and group name; an integrator named by the sweep
  // follows the Δt ("…-dt0.04-mvv0.65-rep00"), a reference_gammas value after it ("…-mvv0.65-gamma4.5-rep00").
  std::string id() const;
  std::string label() const;  // e.g. "tea32(1)"
};

std::vector<Cell> enumerate_cells(const StudyConfig& config);

struct Shard {
  int index = 1, count = 1;  // 1-based, as Slurm's --array=1-N gives SLURM_ARRAY_TASK_ID
};
Shard parse_shard(const std::string& text);  // "k/N"; InputError otherwise
// Round-robin over the canonical order, so every shard gets a mix of cheap and expensive cells.
bool in_shard(std::size_t index, Shard shard);  // index: 0-based position in the canonical order
std::vector<Cell> select_shard(const std::vector<Cell>& cells, Shard shard);

}  // namespace dpdrng::study
