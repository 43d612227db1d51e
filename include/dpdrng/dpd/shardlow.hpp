#pragma once
// Shardlow's S1 splitting for DPD (Shardlow, SIAM J. Sci. Comput. 24, 1267 (2003)): the conservative force is
// integrated by velocity-Verlet, the dissipative and random forces pair by pair in a sequential sweep. Each
// pair's velocity update solves the pair's fluctuation–dissipation equation over Δt with half an explicit and
// half an implicit step; its relative velocity along the pair then has the stationary variance 2k_BT for any
// Δt, so the kinetic temperature stays at k_BT where Groot–Warren's scheme runs hot (Nikunen, Karttunen &
// Vattulainen, Comput. Phys. Commun. 153, 407 (2003), compare both).
//
// The sweep updates v_i and v_j before the next pair is visited, so pairs that share a bead must be visited in
// a fixed order. With at least 3 cells of width ≥ r_c a side, the layers of cells along z are grouped into
// slabs of two, one at every layer: the slab at layer c owns the pairs within c (a cell with itself and with 4
// of its 8 neighbours in the layer) and those between c and c+1, so that each cell pair within r_c has one
// owner. Slabs are coloured by their first layer's parity (a third colour for the last layer of an odd count,
// whose slab wraps onto layer 0): two slabs of one colour share no bead. The sweep takes the colours in turn and
// a colour's slabs in parallel, on copies of the positions and velocities sorted by cell (so that threads write
// to disjoint memory); a bead's updates within a colour all come from its one slab, in the slab's fixed pair
// order, so the result is bitwise the same for any thread count. The mt19937 stream is drawn in sweep order and
// so runs the same order on one thread. Fewer than 3 cells a side, a cell would neighbour itself or another
// cell twice: all pairs i < j are swept on one thread.
#include <functional>
#include <memory>
#include <vector>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/kernel.hpp"
#include "dpdrng/dpd/system.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::dpd {

// The dissipative + random part of one step, for every pair within r_c.
class ShardlowSweep {
 public:
  // Noise from cfg: a keyed hash (ζ of pair (i<j) at a step, as in the pair loop: generator ∘ seeding ∘
  // distribution on d = r_j − r_i) or the mt19937 stream drawn in sweep order.
  explicit ShardlowSweep(const WaterConfig& cfg);
  void sweep(System& s, std::uint64_t step);
  // The ζ the last sweep drew (in its fixed pair order).
  const ZetaSums& zeta_sums() const { return zeta_sums_; }

 private:
  // S1 update of beads a and b of velocity arrays v (i < j their bead numbers, for the noise) at
  // minimum-image separation d = r_j − r_i, r² < r_c², its ζ added to z.
  void update_pair(double* const (&v)[3], std::uint32_t a, std::uint32_t b, std::uint32_t i, std::uint32_t j,
                   double dx, double dy, double dz, double r2, std::uint64_t step, ZetaSums& z) const;
  void build_cells(const System& s);
  void sort_by_cell(const System& s);
  void sweep_slab(const System& s, int layer, std::uint64_t step, ZetaSums& z);
  void sweep_all_pairs(System& s, std::uint64_t step);

  double rc_, gamma_, sigma_, dt_;
  int threads_;  // 0: OpenMP's default
  bool stream_;  // the mt19937 stream: one thread, draws in sweep order
  std::function<double(const rng::PairInput&)> zeta_;
  ZetaSums zeta_sums_;
  int nc_[3] = {0, 0, 0};
  std::vector<std::uint32_t> cell_start_, cell_beads_, bead_cell_;
  std::vector<double> px_, py_, pz_, vx_, vy_, vz_;  // in cell order (bead cell_beads_[k] at k)
  std::vector<ZetaSums> slab_zeta_;                 // per slab, summed in sweep order after the sweep
};

// Velocity-Verlet for the forces of `force` (which must leave out the dissipative and random forces) preceded,
// every step, by the S1 sweep at the step's start positions. The same start/step interface as
// ModifiedVelocityVerlet; steps are numbered 1, 2, … for the noise.
class ShardlowS1 {
 public:
  ShardlowS1(const WaterConfig& cfg) : sweep_(cfg), dt_(cfg.dt), threads_(cfg.threads) {}
  ForceSums start(System& s, const ForceFn& force);
  ForceSums step(System& s, const ForceFn& force);

 private:
  ShardlowSweep sweep_;
  double dt_;
  int threads_;
  std::uint64_t step_ = 0;
};

// The water scene's integrator, chosen by cfg.integrator (threads must be resolved, > 0).
class WaterIntegrator {
 public:
  explicit WaterIntegrator(const WaterConfig& cfg);
  ForceSums start(System& s, const ForceFn& force);
  ForceSums step(System& s, const ForceFn& force);

 private:
  ModifiedVelocityVerlet mvv_;
  std::unique_ptr<ShardlowS1> s1_;
};

// What the pair forces must compute under cfg.integrator: everything for mvv; for shardlow the conservative
// force alone (γ = 0 and no noise: the sweep does the rest, so the reported virial is the conservative one).
WaterConfig pair_force_config(const WaterConfig& cfg);
DpdKernel pair_force_kernel(const WaterConfig& cfg);

}  // namespace dpdrng::dpd
