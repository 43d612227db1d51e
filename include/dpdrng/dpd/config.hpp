#pragma once
// Everything a DPD water run needs, with the paper's defaults (Okada, Brumby & Yasuoka 2021): 256 beads at
// ρ = 3, a = 25, r_c = 1, k_BT = 1, γ = 6.75, λ = 0.5, Δt = 0.04, 10 000 steps of which 500 equilibrate,
// every pair evaluated every step. validate() names the first bad field in an InputError.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dpdrng/dpd/system.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::dpd {

// all: every pair every step, the random number drawn even beyond r_c (the paper's choice, so that the RNG's
// share of the cost shows). cells: linked cells, re-sorted every step; only pairs inside r_c draw numbers.
enum class PairMode { all, cells };
PairMode parse_pair_mode(std::string_view name);  // throws InputError
std::string_view to_string(PairMode m);

// mvv: Groot–Warren modified velocity-Verlet (λ). shardlow: Shardlow's S1 splitting (shardlow.hpp; λ unused).
// scmvv: the self-consistent velocity-Verlet with K dissipative-force iterations a step (self_consistent.hpp; K = 1
// is DPD-VV). pnhln: the pairwise Nosé–Hoover–Langevin thermostat with coupling μ (pnhl.hpp; no pair noise, its
// thermostat variable's noise from the mt19937 stream). Water scene only.
enum class Integrator { mvv, shardlow, scmvv, pnhln };
Integrator parse_integrator(std::string_view name);  // a bare name; throws InputError
std::string_view to_string(Integrator i);
inline constexpr int kScmvvIterations = 1;        // scmvv's default K: DPD-VV
inline constexpr int kScmvvMaxIterations = 100;
inline constexpr double kPnhlnMu = 10.0;          // pnhln's default coupling μ

// Noise replacements that keep every other cost of a step; only the benchmark uses them, to measure the RNG's
// share by difference. none: ζ = 0 without a generator call. unhashed: the seed words pass through unhashed
// into the distribution (measures the hash alone).
enum class NoiseOverride { off, none, unhashed };

// What the statistical tests may tap; empty = nothing recorded, nothing paid.
struct TapConfig {
  // Force-evaluation steps whose every raw generator word is kept (all mode: N(N−1)/2 pairs in the
  // lexicographic order (0,1), (0,2), …, (N−2,N−1); cells mode: the pairs inside r_c in list order).
  std::vector<std::int64_t> raw_steps;
  // Pairs (i < j) whose raw words and ζ are kept for every production step.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  // Production steps in_range_first..in_range_last whose pairs inside r_c (InRangeTap) go to
  // RunHooks::in_range, each step once it has passed the run's guards: the steps and pairs whose ζ the result's
  // zeta sums hold. in_range_last < in_range_first: none.
  std::int64_t in_range_first = 0, in_range_last = -1;
  bool in_range() const { return in_range_last >= in_range_first; }
};

// Limits that keep a run meaningful in double precision; InputError "invalid <field>: <why>" otherwise.
// A step must move a bead at the thermal speed √k_BT by at least 2^-32 of the box length: below that its
// coordinates (53-bit doubles of size ~L) cannot resolve the motion and every observable is frozen or noise.
void check_step_resolves(double dt, double kT, double box_length, const std::string& field);
// The box may be at most 2^24 cut-offs wide: wider, the coordinates' rounding approaches the scale of a pair.
void check_box_resolves(double box_length, double rc, const std::string& field);

struct WaterConfig;
// "mvv", "shardlow", "scmvv[:K]" (K whole, 1..100) or "pnhln[:μ]" (μ > 0) into cfg's integrator and parameter;
// InputError naming `what` (e.g. "--integrator") otherwise.
void set_integrator(WaterConfig& cfg, std::string_view text, const std::string& what);

struct WaterConfig {
  // System
  int particles = 256;
  double density = 3.0;
  double a = 25.0;      // conservative repulsion a_ij (one bead type)
  double rc = 1.0;      // cut-off radius
  double kT = 1.0;
  double gamma = 6.75;  // σ² = 2γk_BT
  // Integration (Groot & Warren 1997 modified velocity-Verlet; λ = 0.5 is plain velocity-Verlet)
  double lambda = 0.5;
  double dt = 0.04;
  Integrator integrator = Integrator::mvv;
  int scmvv_iterations = kScmvvIterations;  // K of scmvv
  double pnhln_mu = kPnhlnMu;               // μ of pnhln
  std::int64_t steps = 10000;
  std::int64_t equilibrate = 500;
  // Pair search
  PairMode pairs = PairMode::all;
  // Noise = generator ∘ seeding ∘ distribution
  rng::GeneratorSpec generator{};
  rng::Seeding seeding = rng::Seeding::distance;
  rng::Distribution distribution = rng::Distribution::gauss;
  rng::Feed feed = rng::Feed::halves;  // which uniforms feed the Gaussian (distribution.hpp)
  std::uint64_t seed = 1;         // pair-step key word, and the seed of the mt19937 reference stream
  std::uint64_t init_seed = 2021; // initial positions and velocities (the same for every generator)
  int threads = 0;                // 0 = OpenMP's default
  std::size_t team_beads = kTeamBeads;  // fewer beads run on one thread (team_threads); 0: any size shares
  // Sampling of observables (every k-th production step)
  int sample_every = 10;
  int vpdf_bins = 60;
  double vpdf_range = 6.0;   // histogram spans ±vpdf_range·√k_BT
  int rdf_bins = 100;
  double rdf_rmax = 2.5;     // clipped to half the box
  int rdf_every = 0;         // 0 = sample_every for N ≤ 2000, 20·sample_every above (g(r) costs N²-ish)
  int msd_every = 0;         // 0 = sample_every; MSD is skipped if it would need more than 2^26 stored doubles
  bool observables = true;   // false: only temperature, pressure and timings (benchmarks)
  bool series = false;       // keep the per-step time series (T, P, P_c, momentum) in the result
  int zeta_lags = 0;         // > 0: ζ autocorrelation at lags 1…zeta_lags on tracked pairs (zeta_track.hpp)
  // Stability guards: the run stops with status "unstable at step k: reason"
  double max_temperature = 100.0;  // in units of k_BT
  double min_distance = 1e-5;      // two beads closer than this
  // Taps and benchmarking
  TapConfig taps;
  NoiseOverride noise_override = NoiseOverride::off;

  // "mvv", "shardlow", "scmvv:K", "pnhln:μ" (the parameter from scmvv_iterations, pnhln_mu).
  std::string integrator_name() const;
  double box_length() const;
  void validate() const;  // throws InputError naming the field
};

}  // namespace dpdrng::dpd
