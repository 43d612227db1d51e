#pragma once
// The self-consistent velocity-Verlet for DPD, mass 1 (Besold, Vattulainen, Karttunen & Polson, Phys. Rev. E 62,
// R7611 (2000), whose one-iteration form is DPD-VV; Vattulainen, Karttunen, Besold & Polson, J. Chem. Phys. 116,
// 3967 (2002)). With F = F^C + F^R + F^D:
//   v' = v + ½Δt F(t)
//   r(t+Δt) = r + Δt v'
//   F^C and F^R at r(t+Δt), the random force drawn once a step; v⁰ = v'
//   K times: v^k = v' + ½Δt [F^C + F^R + F^D(r(t+Δt), v^{k−1})]
//   v(t+Δt) = v^K, and F(t+Δt) = F^C + F^R + F^D(r(t+Δt), v^K) for the next step's first half kick.
// K = 1 is DPD-VV (the dissipative force re-evaluated once, at the step's final velocities); as K grows v^K
// approaches the solution of the implicit half kick, Pagonabarraga, Hagen & Frenkel's self-consistent scheme.
//
// The first iterate needs F^C + F^R + F^D(v'): one evaluation of the full pair forces, through the pair loop and
// the pair noise MVV uses (generator × seeding × distribution × feed, the same numbers at the same step). F^D is
// linear in the velocities at fixed positions, so F^D(v^k) = F^D(v') + F^D(v^k − v'): each further dissipative
// force is the full forces plus one dissipative-only pass (no conservative force, no noise) over the velocity
// difference. A step thus costs one full pair pass and K dissipative ones.
#include <vector>

#include "dpdrng/dpd/integrator.hpp"

namespace dpdrng::dpd {

class SelfConsistentVerlet {
 public:
  SelfConsistentVerlet(double dt, int iterations, int threads) : dt_(dt), iterations_(iterations), threads_(threads) {}
  // force: all three pair forces at s.x with velocities v (overwrites s.f); dissipative: F^D alone, likewise.
  ForceSums start(System& s, const ForceFn& force);
  ForceSums step(System& s, const ForceFn& force, const ForceFn& dissipative);

 private:
  double dt_;
  int iterations_, threads_;
  std::vector<double> half_[3], full_[3], diff_[3];  // v', F^C + F^R + F^D(v'), v^k − v'
};

}  // namespace dpdrng::dpd
