#pragma once
// The pair loop, compiled once (pair_loop.cpp), around a per-noise kernel (noise_kernel.hpp) that it calls once
// per batch of pairs: a group of rows (all mode) or a layer of cells (cells mode), never per pair.
//   all:   row i does its partners j > i. Sixteen rows collect their pairs inside r_c
//          (pair_filter::append_rounded: ~1 candidate in 20 is kept, so a single-precision test, 16 lanes,
//          passes a superset, which is gathered and tested exactly), draw the noise of all of them in one
//          batch (a hash's block depends on the pair alone and the stream's, which fills a number for every pair
//          slot each step, on the pair's slot, so the pairs outside r_c need no ζ), compute the group's pair
//          terms in one vectorised pass, then sum each row's forces in pair order. A tapped step, which records
//          every pair's words, does the same and then each row's geometry of all its pairs, whose words the
//          kernel hashes into the tap (NoiseKernel::row_words). Reactions are added serially.
//   cells: the beads are sorted by cell every step (neighbours.hpp) and copied into sorted arrays, both
//          shared by the team (every sorted slot written once, so any team gives the same arrays); each cell
//          does its own pairs and those with its 13 forward neighbours, writing both forces at once; a cell's
//          candidates are copied from the sorted arrays (runs of consecutive cells) into one list that each of
//          its beads filters in whole vectors, without min_image where the cell's stencil cannot wrap. A layer
//          of cells collects its pairs inside r_c first and draws their noise in one batch (long enough for
//          the vectorised hash and Box–Muller), then does the cells' forces in the same order as ever; even
//          z-layers of cells run in parallel (disjoint writes), and each odd one once its two even
//          neighbours are done. Each layer's forces go back to the System as soon as they are final.
//          Generator inputs use the beads' own indices, so nothing but the summation order depends on the
//          sorting.
// Both modes turn a batch's blocks into ζ in one call inside the kernel (the feed is switched
// on once per batch, not per pair), and compute the second blocks only under the blocks feed.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::dpd {

// Slot of pair (i < j) in the lexicographic order of all N(N−1)/2 pairs.
constexpr std::size_t pair_slot(std::size_t i, std::size_t j, std::size_t n) {
  return i * n - i * (i + 1) / 2 + (j - i - 1);
}

// Separations d = r_j − r_i (minimum image) and r² for m consecutive partners; restrict lets it vectorise.
inline void geometry(const double* __restrict x, const double* __restrict y, const double* __restrict z, double xi,
                     double yi, double zi, const Box& box, std::size_t m, double* __restrict dx,
                     double* __restrict dy, double* __restrict dz, double* __restrict r2) {
  const double Lx = box.L[0], Ly = box.L[1], Lz = box.L[2];
  const double hx = Lx / 2, hy = Ly / 2, hz = Lz / 2;
  for (std::size_t t = 0; t < m; ++t) {
    const double a = min_image(x[t] - xi, Lx, hx), b = min_image(y[t] - yi, Ly, hy), c = min_image(z[t] - zi, Lz, hz);
    dx[t] = a, dy[t] = b, dz[t] = c;
    r2[t] = a * a + b * b + c * c;
  }
}

// All mode on a tapped step, row i: its m partners i + 1 … i + m (slots slot, slot + 1, …), whose words, inside
// r_c or not, go to tap[w][t].
struct RowWords {
  std::uint32_t i;
  std::size_t m;
  const double *dx, *dy, *dz;
  std::uint64_t step;
  std::size_t slot;
  std::uint64_t* tap[2];
};

// A batch of k pairs (i[t], j[t]) inside r_c: a layer's in cells mode (bead ids in any order: the inputs are made
// canonical), a group of rows' in all mode.
struct PairBatch {
  const std::uint32_t* i;
  const std::uint32_t* j;
  std::size_t k;
  const double *dx, *dy, *dz;
  std::uint64_t step;
  std::size_t slot;       // the first pair's slot (the stream reference's order)
  std::uint64_t* tap[2];  // non-null: the pairs' words go to tap[w][t]
  double* zeta;           // out: ζ of the k pairs
  std::uint64_t* used;    // non-null: the words ζ came from (NoiseKernel::used_words), pair after pair
  const std::size_t* slots = nullptr;  // non-null: pair t's slot is slots[t], not slot + t
};

// The per-noise part of the pair loop: generator, seeding and distribution inline here, in one batch call.
// Calls from different threads pass their thread number, which picks the kernel's scratch.
class NoiseKernel {
 public:
  virtual ~NoiseKernel() = default;
  virtual int words() const = 0;
  virtual bool stream() const = 0;  // needs begin_step with the number of pairs before a step's first batch
  virtual bool zero() const = 0;    // the ζ = 0 baseline: the loop calls nothing below
  virtual rng::Feed feed() const = 0;
  // The words a pair's ζ is made from, as a batch's `used` receives them: the block's words(), then, under the
  // blocks feed, the second block's.
  int used_words() const { return words() * (feed() == rng::Feed::blocks ? 2 : 1); }
  virtual void threads(int count) = 0;
  virtual void begin_step(std::size_t slots) = 0;
  virtual void row_words(const RowWords& b, int thread) = 0;
  virtual void pairs(const PairBatch& b, int thread) = 0;
  // One pair as the loop sees it (p with i < j): its words (words() of them) and ζ.
  virtual void pair(const rng::PairInput& p, std::size_t slot, std::uint64_t* words, double& zeta) const = 0;
  // Timed like the loop uses them: the generator over a batch of pair inputs, the distribution over blocks.
  virtual double ns_per_number() const = 0;
  virtual double ns_per_zeta() const = 0;
};

// series_steps: how many steps will tap the pair series of tap_pairs (room kept for them; more still fit).
std::unique_ptr<PairForces> make_pair_loop(std::unique_ptr<NoiseKernel> noise, const DpdKernel& kernel,
                                           PairMode mode, int threads, std::size_t n,
                                           std::vector<std::pair<std::uint32_t, std::uint32_t>> tap_pairs,
                                           std::size_t series_steps);

}  // namespace dpdrng::dpd
