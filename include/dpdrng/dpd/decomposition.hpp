#pragma once
// The decomposition check: does a pair's random number come out the same on both sides of a domain
// boundary when no message carries it? One process emulates a spatial decomposition: the box is cut into
// n_x × n_y × n_z domains, each bead is owned by the domain its wrapped position falls in, and every pair is
// evaluated by the owner of each of its beads with the separation that owner can compute:
//
//  - along a cut axis (n_a ≥ 2), from the partner's ghost copy: the ghost coordinate is x_j + s·L in floating
//    point (s = −1, 0, +1, the periodic image within reach), the separation ghost − x_i. This is what spatial
//    decomposition codes do; across the periodic boundary the owner of i computes (x_j − L) − x_i and the owner
//    of j computes (x_i + L) − x_j, whose negation x_j − (x_i + L) may differ from the first in the last bits.
//    Across an inner boundary (s = 0) both compute x_j − x_i up to sign, which IEEE-754 makes exact.
//  - along an uncut axis, by the minimum image of x_j − x_i, as HOOMD-blue does within a rank; antisymmetric
//    to the bit, as in the undecomposed engine.
//
// Every pair is thus evaluated twice (no Newton's third law across or within domains) and each owner adds
// only the force on its own bead. Pairs inside one domain are evaluated identically by both evaluations; a
// boundary pair (beads in different domains) may not be. With one domain per axis this is the undecomposed
// engine (the same separations, seeds and ζ as PairLoop; only the summation order differs).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "dpdrng/dpd/kernel.hpp"
#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/system.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::dpd {

struct DomainGrid {
  std::array<int, 3> n{1, 1, 1};
  int count() const { return n[0] * n[1] * n[2]; }
  bool cut(int axis) const { return n[axis] > 1; }
  // Row-major domain index of a position wrapped into [0, L).
  int domain_of(const Box& box, double x, double y, double z) const;
};
// "2" (= 2,1,1), "2,2" or "2,2,1"; each count 1..64. Throws InputError.
DomainGrid parse_domains(std::string_view text);
std::string to_string(const DomainGrid& g);  // "2x2x1"

// One owner's view of a pair: the separation r_j − r_i it computes, and the periodic image of the partner's
// ghost along the cut axes (uncut axes take the minimum image and report 0).
struct PairView {
  std::array<double, 3> d{};
  std::array<int, 3> shift{};
  bool shifted() const { return shift[0] != 0 || shift[1] != 0 || shift[2] != 0; }
  double r2() const { return d[0] * d[0] + d[1] * d[1] + d[2] * d[2]; }
};

// What the owner of bead i computes for partner j (see the header comment). The image is the minimum image,
// decided from x_j − x_i, so both owners pick opposite images (the comparison is antisymmetric exactly).
inline PairView view_from(const System& s, const DomainGrid& g, std::size_t i, std::size_t j) {
  const double* pos[3] = {s.x.data(), s.y.data(), s.z.data()};
  PairView v;
  for (int a = 0; a < 3; ++a) {
    const double L = s.box.L[a], h = L / 2, xi = pos[a][i], xj = pos[a][j];
    const double raw = xj - xi;
    if (g.cut(a)) {
      const int sh = raw > h ? -1 : (raw < -h ? 1 : 0);
      const double ghost = sh == 0 ? xj : (sh < 0 ? xj - L : xj + L);
      v.shift[a] = sh;
      v.d[a] = ghost - xi;
    } else {
      v.d[a] = min_image(raw, L, h);  // no ghost along this axis: shift stays 0
    }
  }
  return v;
}

// Seedings of the check: the two the engine knows and two repairs of distance seeding
// (rng/seeding_repair.hpp).
enum class DecompSeedingKind { distance, pair_step, grid, canonical };
struct DecompSeeding {
  DecompSeedingKind kind = DecompSeedingKind::distance;
  int grid_bits = 32;  // grid: the separation is rounded to a multiple of 2^-grid_bits
};
// "distance", "pair-step", "grid" (2^-32), "grid:K" (K in 8..40), "canonical". Throws InputError.
DecompSeeding parse_decomp_seeding(std::string_view text);
std::string to_string(const DecompSeeding& s);

// One force evaluation's boundary bookkeeping, or their sum over a run (merge()).
struct BoundaryStats {
  std::uint64_t evaluations = 0;          // force evaluations summed
  std::uint64_t in_range = 0;             // pairs inside r_c (as either owner sees them)
  std::uint64_t boundary = 0;             // of these, pairs whose beads lie in different domains
  std::uint64_t shifted = 0;              // of these, pairs seen through a periodic ghost shift (cut axes)
  std::uint64_t separation_mismatch = 0;  // boundary pairs whose two separations differ in any bit
  std::uint64_t range_mismatch = 0;       // boundary pairs one owner sees inside r_c and the other not
  std::uint64_t zeta_mismatch = 0;        // boundary pairs, both in range, whose two ζ differ in any bit
  double zeta_diff_sum = 0, zeta_diff_sum2 = 0, zeta_diff_max = 0;  // |ζ_A − ζ_B| over the ζ mismatches
  double force_mismatch_max = 0;          // max |F_i(A) + F_j(B)| over boundary pairs
  // |Σ_i F_i| per bead: the rate at which the evaluation changes the total momentum (round-off when the two
  // owners agree). max over evaluations, and the sum of squares for an rms.
  double net_force_max = 0, net_force_sum2 = 0;
  // grid seeding: Σ over boundary pairs and components of min(1, |d_A − d_B|·2^k), the expected number of
  // pairs whose two views round to different grid points if the midpoints fall uniformly.
  double grid_straddle_expected = 0;

  void merge(const BoundaryStats& o);
  double mismatch_fraction() const { return boundary ? double(zeta_mismatch + range_mismatch) / boundary : 0.0; }
  double zeta_diff_mean() const { return zeta_mismatch ? zeta_diff_sum / zeta_mismatch : 0.0; }
  double zeta_diff_rms() const;
  double net_force_rms() const;
};

// Both views of one boundary pair (i < j), with B's separation already negated into r_j − r_i.
struct BoundaryPair {
  std::uint32_t i = 0, j = 0;
  int domain_i = 0, domain_j = 0;
  PairView a, b;
  bool in_a = false, in_b = false;
  double zeta_a = 0, zeta_b = 0;
};

struct DecompNoise {
  rng::GeneratorSpec generator{};
  DecompSeeding seeding{};
  rng::Distribution distribution = rng::Distribution::gauss;
  rng::Feed feed = rng::Feed::halves;  // the blocks feed's second block goes through the same repair
  std::uint64_t seed = 1;  // pair-step key word
};

class DecomposedForces {
 public:
  virtual ~DecomposedForces() = default;
  // Overwrites s.f with the forces each owner computes at s.x, velocities v, force-evaluation number `step`.
  // Virial sums average the two owners' halves. stats (if given) gets this evaluation merged in; pairs (if
  // given) is filled with every boundary pair.
  virtual ForceSums compute(System& s, VelocityView v, std::uint64_t step, BoundaryStats* stats,
                            std::vector<BoundaryPair>* pairs) = 0;
  // Raw output block of pair (i < j) under the seeding, from the undecomposed minimum-image separation: what
  // the statistical tests look at. words[1] only for two-word generators.
  virtual std::array<std::uint64_t, 2> raw(const System& s, std::uint32_t i, std::uint32_t j,
                                           std::uint64_t step) const = 0;
  virtual int words_per_pair() const = 0;
};

// Throws InputError for a generator that is not a keyed hash (mt19937: a stream cannot give two domains the
// same number without a message) or a bad seeding.
std::unique_ptr<DecomposedForces> make_decomposed_forces(const DecompNoise& noise, const DpdKernel& kernel,
                                                         const DomainGrid& domains);

}  // namespace dpdrng::dpd
