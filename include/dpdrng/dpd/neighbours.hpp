#pragma once
// Linked cells (g(r)) and the sorted, coloured cells of the pair loop. Everything here is built in a fixed
// order (stable counting sorts, neighbour cells in a fixed stencil order), so the pair order, and with it the
// mt19937 reference's slot of every pair, never depends on the thread count.
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

class CellGrid {
 public:
  // Cells at least `rmin` wide. usable() is false when a dimension has fewer than 3 cells (the 27-cell
  // stencil would visit a cell twice); callers then fall back to all pairs.
  void build(const System& s, double rmin);
  bool usable() const { return usable_; }
  int cell_of(double x, double y, double z) const;
  // The 27 cells around (and including) cell c, in a fixed order.
  void stencil(int c, int out[27]) const;
  const std::vector<std::uint32_t>& start() const { return start_; }  // beads of cell c: [start[c], start[c+1])
  const std::vector<std::uint32_t>& beads() const { return beads_; }

 private:
  int n_[3] = {0, 0, 0};
  double inv_w_[3] = {0, 0, 0};
  bool usable_ = false;
  std::vector<std::uint32_t> start_, beads_;
};

// The cells-mode pair search, redone every step (at Δt = 0.04 and k_BT = 1 the fastest of 24 000 beads moves
// ≈ 0.2 per step, so a Verlet list with a usable skin would be rebuilt almost every step anyway). Beads are
// sorted by cell (a stable counting sort: within a cell, by bead index), so that a cell and its neighbours are
// contiguous in memory. Every pair is owned by exactly one cell: the pairs inside the cell, and the pairs
// between the cell and its 13 forward neighbours, which lie in the cell's z-layer or the next. A layer's pairs
// thus write forces to that layer and the next only; with an even number of layers, the even layers write
// disjoint beads, and so do the odd ones. Even layers run in parallel (each layer's cells in order on one
// thread), and an odd layer after both its even neighbours: every bead receives its force contributions in
// the same order whatever the thread count, and the pair order (cell by cell, in cell index order) is fixed.
// The sort can be shared by a team: each thread counts and places a contiguous range of beads, its places
// within a cell coming after those of the lower ranges, so the order is the serial sort's for any team.
class SortedCells {
 public:
  static constexpr int kForward = 13;
  // Below this many beads, sorting and copying them serially costs less than a parallel region's fork.
  static constexpr std::size_t kParallelBeads = kTeamBeads;
  // Cells at least rc wide. If the box is too small for the grid (fewer than 3 cells along x or y, or 4
  // along z), one cell holds every bead and owns every pair. Called outside a parallel region, or by every
  // thread of one (orphaned worksharing: callers can run more work in the same region); returns with a barrier.
  void build(const System& s, double rc);
  // build() in two parts, for a caller whose region goes on to other work: prepare() by one thread (the grid,
  // and room for a team of `team`), then sort() by every thread of that team. sort() has one barrier inside
  // and none at its end, so the caller's next barrier is the one that publishes the order.
  void prepare(const System& s, double rc, int team);
  void sort(const System& s);
  bool gridded() const { return ncell_ > 1; }
  int cells() const { return ncell_; }
  // z-layers of cells: layer z holds cells [z·layer_cells(), (z + 1)·layer_cells()); its colour is z mod colours().
  int layers() const { return n_[2]; }
  int layer_cells() const { return n_[0] * n_[1]; }
  int colours() const { return gridded() ? 2 : 1; }
  // Sorted beads of cell c: [begin(c), end(c)); order()[k] is the index in the System of sorted bead k.
  std::uint32_t begin(int c) const { return start_[c]; }
  std::uint32_t end(int c) const { return start_[c + 1]; }
  const std::vector<std::uint32_t>& order() const { return order_; }
  // The forward neighbours of c: forward_count() cells from forward(c) (none in the single-cell case).
  int forward_count() const { return gridded() ? kForward : 0; }
  const std::int32_t* forward(int c) const { return forward_.data() + std::size_t(c) * kForward; }
  // Cell c's candidates (its own beads, then its forward neighbours' in order) as runs of consecutive cell
  // indices, whose sorted beads are contiguous: run r spans [begin(first), end(last)). The own cell starts the
  // first run. Without a grid, one run of the one cell.
  struct Run {
    std::int32_t first, last;
  };
  int run_count(int c) const { return run_count_[std::size_t(c)]; }
  // Whether a separation between a bead of cell c and one of its candidates can exceed half a box edge in
  // some dimension (its stencil wraps around the box, or the grid has fewer than 5 cells along a dimension),
  // so that the minimum image can differ from the plain difference. When false, every candidate of c lies
  // within two cell widths of c's beads along each axis, less than half the edge.
  bool wraps(int c) const { return wraps_[std::size_t(c)] != 0; }
  const Run* runs(int c) const { return runs_.data() + std::size_t(c) * (kForward + 1); }
  std::uint64_t builds() const { return builds_; }

 private:
  void fill_forward();
  void fill_runs();
  std::uint32_t cell_index(double x, double y, double z) const;
  void count(const System& s, std::size_t lo, std::size_t hi, std::uint32_t* counts);
  void places(std::size_t t, std::size_t team);
  int n_[3] = {1, 1, 1};
  int ncell_ = 1;
  double inv_w_[3] = {0, 0, 0};
  std::vector<std::uint32_t> start_, order_, cell_;
  std::vector<std::uint32_t> counts_, places_;  // per thread and cell: beads; the thread's next place
  std::vector<std::int32_t> forward_;  // kForward per cell, fixed order
  std::vector<Run> runs_;              // kForward + 1 per cell, run_count_ of them used
  std::vector<std::int32_t> run_count_;
  std::vector<std::uint8_t> wraps_;    // per cell (wraps())
  std::uint64_t builds_ = 0;
};

}  // namespace dpdrng::dpd
