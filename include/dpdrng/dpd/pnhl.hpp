#pragma once
// The pairwise Nosé–Hoover–Langevin thermostat (Leimkuhler & Shang, J. Comput. Phys. 280, 72 (2015)), mass 1:
//   dr_i = v_i dt
//   dv_i = F^C_i dt − ξ Σ_j w²(r_ij) (ê_ij·v_ij) ê_ij dt                       (pairwise friction ξ, no noise)
//   dξ   = μ⁻¹ G dt − γ ξ dt + √(2γk_BT/μ) dW,   G = Σ_{i<j} w²(r_ij) [(ê_ij·v_ij)² − 2k_BT]
// with w = 1 − r/r_c, v_ij = v_i − v_j, γ the scene's γ and μ the coupling. The 2k_BT is k_BT over the pair's
// reduced mass ½: the extended density exp(−[H + μξ²/2]/k_BT) is invariant, so the kinetic temperature along the
// pairs is pinned to k_BT by feedback and only ξ is stochastic. Momentum is conserved pair by pair.
//
// The step is the nonsymmetric splitting A½ B½ C½ D½ O D½ C½ A½ B½ (A: positions, B: conservative kick with the
// force at the positions reached, C: the friction's exact flow pair by pair, D: ξ by G/μ, O: ξ's exact
// Ornstein–Uhlenbeck flow), two conservative force evaluations a step. C: for one pair, u = ê·v_ij decays as
// u e^{−2ξw²t} (ξ < 0 makes it grow), each bead taking half the change; the pairs are swept in PairSweep's fixed
// order (pair_sweep.hpp), so the result does not depend on the thread count. The positions do not move from the
// first B½ to the second A½: the pairs are found once a step (PairSweep::record) and both C½ sweeps and the sum G,
// taken after the first, replay them. The noise of O, one Gaussian a step, comes from the mt19937 reference stream seeded with the
// run's seed (Box–Muller on one 64-bit word): the pair generator, seeding, distribution and feed play no part.
// ξ starts at 0, its stationary mean.
#include <cstdint>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/pair_sweep.hpp"
#include "dpdrng/rng/mt.hpp"

namespace dpdrng::dpd {

class PairwiseNoseHooverLangevin {
 public:
  explicit PairwiseNoseHooverLangevin(const WaterConfig& cfg);
  // force: the conservative pair forces alone (overwrites s.f).
  ForceSums start(System& s, const ForceFn& force);
  ForceSums step(System& s, const ForceFn& force);
  double xi() const { return xi_; }

 private:
  void drift_half(System& s) const;
  void kick_half(System& s) const;
  // On the pairs and velocities pairs_ recorded: C over Δt/2 with the current ξ; G at the current state.
  void friction_half();
  double pair_g();

  double kT_, gamma_, mu_, dt_;
  int threads_;
  double xi_ = 0;
  rng::Mt19937 mt_;
  PairSweep pairs_;
};

}  // namespace dpdrng::dpd
