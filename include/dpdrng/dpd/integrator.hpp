#pragma once
// Groot & Warren (1997) modified velocity-Verlet (their eq. 13), mass 1:
//   r(t+Δt) = r + Δt v + ½Δt² f
//   ṽ       = v + λΔt f                    (predicted velocity for the dissipative force)
//   f(t+Δt) = f(r(t+Δt), ṽ)
//   v(t+Δt) = v + ½Δt (f + f(t+Δt))
// λ = 0.5 is plain velocity-Verlet. Forces come from a callback, so scenes can add bonds and angles to the
// pair forces (and their virial) without touching the integrator.
#include <functional>
#include <vector>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

// Overwrites s.f at positions s.x with velocities v for the dissipative force; returns the virial sums.
using ForceFn = std::function<ForceSums(System& s, VelocityView v)>;

class ModifiedVelocityVerlet {
 public:
  ModifiedVelocityVerlet(double dt, double lambda, int threads) : dt_(dt), lambda_(lambda), threads_(threads) {}
  // First force evaluation, with ṽ = v.
  ForceSums start(System& s, const ForceFn& force);
  ForceSums step(System& s, const ForceFn& force);

 private:
  void drift(std::size_t lo, std::size_t hi, double* __restrict x, double* __restrict v, const double* __restrict f,
             double* __restrict predicted) const;
  void kick(std::size_t lo, std::size_t hi, double* __restrict v, const double* __restrict f) const;
  double dt_, lambda_;
  int threads_;
  std::vector<double> vtx_, vty_, vtz_;
};

}  // namespace dpdrng::dpd
