#pragma once
// A sequential sweep over every pair within r_c whose updates write both beads' velocities (Shardlow's S1 and the
// pairwise Nosé–Hoover–Langevin thermostat both update pair by pair). Pairs that share a bead must then be
// visited in a fixed order. With at least 3 cells of width ≥ r_c a side, the layers of cells along z are grouped
// into slabs of two, one at every layer: the slab at layer c owns the pairs within c (a cell with itself and with
// 4 of its 8 neighbours in the layer) and those between c and c+1, so that each cell pair within r_c has one
// owner. Slabs are coloured by their first layer's parity (a third colour for the last layer of an odd count,
// whose slab wraps onto layer 0): two slabs of one colour share no bead. The sweep takes the colours in turn and
// a colour's slabs in parallel, on copies of the positions and velocities sorted by cell (so that threads write
// to disjoint memory); a bead's updates within a colour all come from its one slab, in the slab's fixed pair
// order, so the result is bitwise the same for any thread count. Fewer than 3 cells a side, a cell would
// neighbour itself or another cell twice: all pairs i < j are swept on one thread.
//
// The visitor is called as visit(v, a, b, i, j, dx, dy, dz, r2, acc): beads i < j (their numbers) sit at slots
// a, b of the velocity arrays v[3], at minimum-image separation d = r_j − r_i with 0 < r² < r_c²; acc is the
// accumulator of the pair's slab (Acc: default-constructible, with merge(const Acc&)). The slabs' accumulators
// are merged in sweep order. The member templates are defined in src/dpd/pair_sweep_impl.hpp.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

class PairSweep {
 public:
  PairSweep(double rc, int threads) : rc_(rc), threads_(threads) {}
  // one_thread: run the colours' slabs on one thread (a stream drawn in sweep order).
  template <class Acc, class Visit>
  Acc sweep(System& s, bool one_thread, Visit&& visit);

  // A scheme that sweeps several times at fixed positions searches once: record() finds the pairs as sweep()
  // does and keeps each slab's (their slots, ê = d/r and w = 1 − r/r_c) with the velocities copied into cell
  // order; replay() visits them in the same order, slabs and threads as sweep() would, as often as needed, as
  // visit(v, pair, acc); release() writes the velocities back to the System.
  struct Pair {
    std::uint32_t a, b;
    double ex, ey, ez, w;
  };
  void record(const System& s);
  template <class Acc, class Visit>
  Acc replay(Visit&& visit);
  void release(System& s) const;

 private:
  void record_all_pairs(const System& s);
  std::vector<int> slab_order(std::vector<std::size_t>& colour_start) const;
  bool build_cells(const System& s);  // false: fewer than 3 cells a side
  void sort_by_cell(const System& s);
  template <class Acc, class Visit>
  Acc sweep_all_pairs(System& s, Visit& visit) const;
  template <class Acc, class Visit>
  void sweep_slab(const Box& box, int layer, Visit& visit, Acc& acc);

  double rc_;
  int threads_;  // 0: OpenMP's default
  int nc_[3] = {0, 0, 0};
  std::vector<std::uint32_t> cell_start_, cell_beads_, bead_cell_;
  std::vector<double> px_, py_, pz_, vx_, vy_, vz_;  // in cell order (bead cell_beads_[k] at k)
  std::vector<std::vector<Pair>> slab_pairs_;       // record(): each slab's pairs, slabs in sweep order
  std::vector<std::size_t> colour_start_;           // record(): the slabs of colour k are [start[k], start[k+1])
};

}  // namespace dpdrng::dpd
