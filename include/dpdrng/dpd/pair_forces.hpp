#pragma once
// The DPD pair forces of one step behind a run-time interface (one virtual call per step). Inside, the pair
// loop calls a per-noise kernel once per batch of pairs (pair_loop.hpp), so the hash inlines into that kernel.
//
// Determinism: rows (bead i and its partners j > i) run in parallel, but each writes only its own slots; the
// reactions −F_ij are then added to the partners serially in row order, and the virial sums run over per-row
// partial sums in row order. No floating-point sum depends on the thread count.
#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/kernel.hpp"
#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

// Power sums of the ζ drawn for pairs inside r_c, from which stats/ takes the moments a run reports. Partial
// sums (per row, per cell) are merged in a fixed order, so the totals do not depend on the thread count.
struct ZetaSums {
  std::uint64_t n = 0;
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  // Σ w_R² and Σ w_R² ζ² over the same pairs (w_R = 1 − r/r_c): the noise power the force receives, each ζ
  // weighted as it enters the force (the pair loop's; a Shardlow sweep leaves them 0).
  double w2 = 0, w2z2 = 0;

  void add(const double* z, std::size_t m) {
    double a1 = 0, a2 = 0, a3 = 0, a4 = 0;
    for (std::size_t t = 0; t < m; ++t) {
      const double x = z[t], x2 = x * x;
      a1 += x, a2 += x2, a3 += x2 * x, a4 += x2 * x2;
    }
    n += m, s1 += a1, s2 += a2, s3 += a3, s4 += a4;
  }
  void add(double z) { add(&z, 1); }
  void merge(const ZetaSums& o) {
    n += o.n, s1 += o.s1, s2 += o.s2, s3 += o.s3, s4 += o.s4;
    w2 += o.w2, w2z2 += o.w2z2;
  }
};

struct ForceSums {
  std::array<double, 3> virial{};       // Σ_pairs (r_ij)_α (F_ij)_α, all three pair forces
  std::array<double, 3> virial_cons{};  // the same for the conservative force alone
  double min_r2 = 0;                    // closest pair seen (inside r_c; r_c² if none)
  std::uint64_t in_range = 0;           // pairs inside r_c
  std::uint64_t candidates = 0;         // pairs whose separation the search computed to find them
  std::uint64_t numbers = 0;            // generator calls this step
  ZetaSums zeta;                        // the ζ of the pairs inside r_c, when asked for (tap_zeta)
  // The configurational temperature's parts over the conservative potential U (kernel.hpp): Σ_i |∇_i U|² (the
  // conservative force on each bead, squared) and Σ_i ∇_i²U, on the steps that asked for them
  // (PairForces::sum_configurational). Summed in a fixed order, like the virial.
  bool configurational = false;
  double conf_force2 = 0;
  double conf_laplacian = 0;
};

// Raw generator output of one force-evaluation step; words[1] is used by two-word generators (tea64's b).
struct RawTap {
  std::int64_t step = 0;
  int words_per_pair = 1;
  std::array<std::vector<std::uint64_t>, 2> words;
};

// What one pair received on every production step: raw words (tea64: a and b apart) and ζ.
struct PairSeries {
  std::uint32_t i = 0, j = 0;
  int words_per_pair = 1;
  std::vector<std::int64_t> steps;
  std::array<std::vector<std::uint64_t>, 2> words;
  std::vector<double> zeta;
};

// The pairs inside r_c of one force evaluation, whose ζ entered the force, in the canonical order: by bead
// indices (i, j), i < j, ascending (whatever the pair mode, the sorting into cells or the thread count). Per pair:
// its key (i << 32) | j, the words_per_pair words its ζ came from (the block's words, then under the blocks feed
// the second block's) and the ζ itself.
struct InRangeTap {
  std::int64_t step = -1;
  int words_per_pair = 1;
  std::vector<std::uint64_t> keys, words;
  std::vector<double> zeta;

  std::size_t size() const { return keys.size(); }
  void clear() { keys.clear(), words.clear(), zeta.clear(); }
};

struct Taps {
  std::vector<RawTap> raw;
  std::vector<PairSeries> series;
  InRangeTap in_range;  // the last compute() under tap_in_range(true)
  // Raw taps whose words a consumer has read and given back: the next raw steps reuse their storage.
  std::vector<RawTap> recycled;
};

// Velocities used by the dissipative force (Groot–Warren's predicted ṽ).
struct VelocityView {
  const double *vx, *vy, *vz;
};

class PairForces {
 public:
  virtual ~PairForces() = default;
  // Overwrites s.f with the pair forces at s.x and velocities v, for force-evaluation number `step`.
  // tap_raw: keep this step's raw words (the pair's first block); tap_series: append to the pair series;
  // tap_zeta: fill ForceSums::zeta.
  virtual ForceSums compute(System& s, VelocityView v, std::uint64_t step, bool tap_raw, bool tap_series,
                            bool tap_zeta, Taps& taps) = 0;
  // Moves into taps what compute() still holds of them (the pair series' latest steps): once after a run's last
  // compute(), before the taps are read.
  virtual void finish_taps(Taps&) {}
  // Calibration on this run's noise: nanoseconds per generator call (raw words, batched as in the pair loop;
  // mt19937: per word of the step's buffer) and per distribution transform (ζ from a block).
  virtual double ns_per_number() const = 0;
  virtual double ns_per_zeta() const { return 0.0; }
  virtual int words_per_pair() const = 0;
  virtual std::uint64_t list_builds() const { return 0; }
  // The ζ pair (i < j) received in the last compute (step `step`, separation d = r_j − r_i as the loop saw it),
  // recomputed like the pair series; NaN where it cannot be known (the mt19937 stream outside all-pairs mode, a
  // baseline without noise).
  virtual double zeta_of(const System& s, std::uint32_t i, std::uint32_t j, std::uint64_t step) const = 0;
  // zeta_of for the n pairs (i[t] < j[t]) at once: out[t] = zeta_of(s, i[t], j[t], step), bit for bit.
  virtual void zetas_of(const System& s, const std::uint32_t* i, const std::uint32_t* j, std::size_t n,
                        std::uint64_t step, double* out) const {
    for (std::size_t t = 0; t < n; ++t) out[t] = zeta_of(s, i[t], j[t], step);
  }
  // Whether the following compute() calls sum the configurational temperature's parts (a scatter per pair: the
  // sampled steps only).
  void sum_configurational(bool on) { configurational_ = on; }
  // Whether the following compute() calls record their pairs inside r_c in Taps::in_range (a baseline without
  // noise records nothing).
  void tap_in_range(bool on) { tap_in_range_ = on; }

 protected:
  bool configurational_ = false;
  bool tap_in_range_ = false;
};

// Chooses the noise policy (hash via rng::with_pair_noise, the mt19937 stream, or a benchmark baseline) and
// the pair mode. The config must be valid.
std::unique_ptr<PairForces> make_pair_forces(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);

// The noise's share of a force evaluation by difference: `pair` (made from cfg) and a ζ = 0 loop of the same
// config evaluate the forces of state s alternately, 5 to 64 times (stopping once budget_s has passed), and
// the share is 1 − median(ζ = 0) / median(pair). Steps first_step, first_step + 1, … are used for seeding.
double rng_share_by_difference(PairForces& pair, const WaterConfig& cfg, const DpdKernel& kernel, System s,
                               std::uint64_t first_step, double budget_s);

}  // namespace dpdrng::dpd
