#pragma once
// The membrane scene: a flat H3(T6)2 lipid bilayer in water, the smallest well-documented DPD bilayer
// (Grafmüller, Shillcock & Lipowsky, Biophys. J. 96, 2658 (2009); the public Osprey-DPD bilayer example uses the
// same parameters). It stands in for the paper's POPC bilayer (Okada, Brumby & Yasuoka 2021), whose parameters
// are not public in full, to ask the same question: does 32TEA(1) change T, P_αα, the tension or the structure?
//
//   dpd::BilayerConfig cfg;                              // the model and box above
//   cfg.generator = rng::validated({"tea32", 1});
//   cfg.steps = 8000; cfg.equilibrate = 3000;
//   dpd::BilayerResult r = dpd::run_bilayer(cfg);        // throws InputError for a bad config
//
// Steps: the first `warmup` steps use dt_warmup (the pre-assembled bilayer relaxes), the rest dt; steps
// 1..equilibrate are not sampled (equilibrate ≥ warmup), production is equilibrate < k ≤ steps.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dpdrng/dpd/bonded.hpp"
#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/kernel.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/system.hpp"
#include "dpdrng/dpd/water.hpp"

namespace dpdrng::dpd {

// Bead types, the a_ij matrix index.
enum BeadType : std::uint8_t { kHead = 0, kTail = 1, kWater = 2 };

// One H3(T6)2 lipid occupies 15 consecutive beads in this order: H1 H2 H3 Ta1..Ta6 Tb1..Tb6. The backbone is
// H1–H2–H3–Ta1–…–Ta6, the second tail hangs on H2 (H2–Tb1–…–Tb6): 14 bonds. Bending acts on H3–Ta1–Ta2,
// H2–Tb1–Tb2 and every T–T–T triple: 10 angles.
inline constexpr int kLipidBeads = 15;
inline constexpr int kTailA = 3, kTailB = 9, kTailLength = 6;  // first bead of each tail within a lipid
Topology lipid_topology(std::size_t lipids);                      // lipids at beads [0, 15·lipids)

struct BilayerConfig {
  // System: box, composition (lipids first, then water), interactions
  std::array<double, 3> box{10.0, 10.0, 18.0};
  int lipids_per_leaflet = 73;  // area per lipid 100/73 = 1.37
  int particles = 5400;         // ρ = 3
  // a_ij by type (H, T, W), row-major and symmetric: HH 30, HT 35, HW 30, TT 10, TW 75, WW 25.
  std::array<double, 9> a{30, 35, 30, 35, 10, 75, 30, 75, 25};
  double rc = 1.0, kT = 1.0, gamma = 4.5;  // σ² = 2γk_BT = 9
  HarmonicBond bond{};
  CosineBend bend{};
  // Builder: straight tails at bond length along z, heads outward, water only where |z − z_c| > water_gap.
  double water_gap = 4.8;
  std::uint64_t init_seed = 2009;
  // Integration (Groot & Warren 1997 modified velocity-Verlet)
  double lambda = 0.5;
  double dt_warmup = 0.005, dt = 0.01;
  std::int64_t warmup = 1000, steps = 61000, equilibrate = 11000;
  PairMode pairs = PairMode::cells;
  // Noise = generator ∘ seeding ∘ distribution (mt19937: the reference stream, see run_bilayer)
  rng::GeneratorSpec generator{};
  rng::Seeding seeding = rng::Seeding::distance;
  rng::Distribution distribution = rng::Distribution::gauss;
  rng::Feed feed = rng::Feed::halves;
  std::uint64_t seed = 1;
  int threads = 0;
  std::size_t team_beads = kTeamBeads;  // as WaterConfig::team_beads
  // Sampling: profiles, order and the integrity check every sample_every steps
  int sample_every = 10;
  double profile_bin = 0.2;
  int blocks = 5;  // production split into blocks for the thickness's standard error
  bool series = false;
  int zeta_lags = 0;  // > 0: ζ autocorrelation at lags 1…zeta_lags on tracked pairs (zeta_track.hpp)
  // Guards. A lipid has left the bilayer when the mean |z − z_mid| of its tail beads exceeds escape_distance
  // (the hydrophobic core spans about ±2; the head-density peaks sit near ±2.5).
  double escape_distance = 4.0;
  double max_temperature = 100.0, min_distance = 1e-5, max_bond = 2.0;

  std::size_t lipids() const { return 2 * static_cast<std::size_t>(lipids_per_leaflet); }
  void validate() const;  // throws InputError naming the field
};

DpdKernel bilayer_kernel(const BilayerConfig& cfg, double dt);

struct BilayerState {
  System system;
  Topology topology;
  std::size_t lipids = 0;
};
// Pre-assembled bilayer normal to z at z_c = L_z/2, Maxwell velocities at k_BT with zero total momentum;
// a pure function of the config (init_seed).
BilayerState build_bilayer(const BilayerConfig& cfg);

struct DensityProfile {
  std::vector<double> z;                  // bin centres, relative to the bilayer midplane
  std::vector<double> head, tail, water;  // number densities
  std::size_t samples = 0;
};

struct BilayerSeries {
  std::vector<std::int64_t> step;
  std::vector<double> temperature, pxx, pyy, pzz, tension, tail_order;
  std::vector<int> lipids_out;
};

struct BilayerResult {
  RunStatus status;  // disrupted when a lipid left the membrane: "disrupted at step k: n lipid(s) left …"
  bool ok() const { return status.ok(); }
  std::int64_t steps_done = 0;
  std::string generator, seeding, distribution, pairs;
  std::string feed = "halves";
  std::size_t particles = 0, lipids = 0;
  std::array<double, 3> box{};

  Stat temperature;                     // k_BT from Σv²/(3N−3)
  std::array<Stat, 3> pressure_diag;    // kinetic + pair (C, D, R) + bond + bend virial
  std::array<Stat, 3> temperature_diag; // k_BT_α = Σ v_α²/(N − 1)
  // P_xx − P_yy per production step: 0 by symmetry about the normal z; its own block error carries the two
  // components' correlation, which their separate errors cannot.
  Stat pressure_anisotropy;
  Stat zeta_weighted_second_moment;     // Σ w_R²ζ² / Σ w_R² of the pair loop's ζ, per production step
  ZetaCorrelation zeta_correlation;     // on pairs of the production steps (zeta_lags > 0)
  Stat pressure;
  // Σ = L_z [P_zz − ½(P_xx + P_yy)]: positive when the membrane is stretched (pulls its edges inward).
  Stat tension;
  Stat tension_conservative;            // pair virial of the conservative force only
  Stat tension_without_bond_virial, tension_without_bend_virial;  // what dropping either term would report
  Stat thickness;       // head-density peak to peak (whole profile); sem from `blocks` block profiles
  Stat head_separation; // per sample: mean z of the upper heads − mean z of the lower heads
  Stat tail_order;      // P2 = ⟨3cos²θ − 1⟩/2 of the T–T bonds against z
  Stat nematic_order;   // largest eigenvalue of ⟨3/2 u uᵀ − 1/2 I⟩ over the lipids' backbone axes u
  std::vector<double> order_by_bond;    // the same per bond position along the tail (5 values)
  DensityProfile profile;
  int lipids_out_max = 0;
  double momentum_drift = 0;            // max over steps of |P(t) − P(0)|, per bead
  std::array<double, 3> momentum_final{};
  BilayerSeries series;
  Timings timings;
  double bonded_s = 0;                  // time in bonded forces
};

BilayerResult run_bilayer(const BilayerConfig& cfg, const RunHooks& hooks = {});

// The membrane's scalars (<name>_mean for temperature, pressure_xx, …; status) plus their errors; arrays (profile,
// order by bond) only if `arrays`.
nlohmann::json to_json(const BilayerResult& r, bool arrays);

}  // namespace dpdrng::dpd
