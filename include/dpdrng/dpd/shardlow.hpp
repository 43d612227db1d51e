#pragma once
// Shardlow's S1 splitting for DPD (Shardlow, SIAM J. Sci. Comput. 24, 1267 (2003)): the conservative force is
// integrated by velocity-Verlet, the dissipative and random forces pair by pair in a sequential sweep. Each
// pair's velocity update solves the pair's fluctuation–dissipation equation over Δt with half an explicit and
// half an implicit step; its relative velocity along the pair then has the stationary variance 2k_BT for any
// Δt, so the kinetic temperature stays at k_BT where Groot–Warren's scheme runs hot (Nikunen, Karttunen &
// Vattulainen, Comput. Phys. Commun. 153, 407 (2003), compare both).
//
// The sweep is PairSweep's (pair_sweep.hpp): bitwise the same for any thread count. The mt19937 stream is drawn
// in sweep order and so runs the sweep on one thread.
#include <functional>
#include <vector>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/kernel.hpp"
#include "dpdrng/dpd/pair_sweep.hpp"
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

  double rc_, gamma_, sigma_, dt_;
  bool stream_;  // the mt19937 stream: one thread, draws in sweep order
  std::function<double(const rng::PairInput&)> zeta_;
  ZetaSums zeta_sums_;
  PairSweep pairs_;
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

}  // namespace dpdrng::dpd
