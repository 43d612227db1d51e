#include "dpdrng/dpd/integrator.hpp"

#include <omp.h>

namespace dpdrng::dpd {

ForceSums ModifiedVelocityVerlet::start(System& s, const ForceFn& force) {
  return force(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()});
}

// One component of beads [lo, hi): position, predicted velocity, first half kick. Separate restrict-qualified
// arrays so that the loop vectorises (with the System's vectors behind plain pointers it stayed scalar).
void ModifiedVelocityVerlet::drift(std::size_t lo, std::size_t hi, double* __restrict x, double* __restrict v,
                                   const double* __restrict f, double* __restrict predicted) const {
  const double dt = dt_, half = 0.5 * dt_, half_dt2 = 0.5 * dt_ * dt_, ldt = lambda_ * dt_;
  for (std::size_t i = lo; i < hi; ++i) {
    x[i] += dt * v[i] + half_dt2 * f[i];
    predicted[i] = v[i] + ldt * f[i];
    v[i] += half * f[i];
  }
}

void ModifiedVelocityVerlet::kick(std::size_t lo, std::size_t hi, double* __restrict v,
                                  const double* __restrict f) const {
  const double half = 0.5 * dt_;
  for (std::size_t i = lo; i < hi; ++i) v[i] += half * f[i];
}

ForceSums ModifiedVelocityVerlet::step(System& s, const ForceFn& force) {
  const std::size_t n = s.size();
  vtx_.resize(n), vty_.resize(n), vtz_.resize(n);
  double *x = s.x.data(), *y = s.y.data(), *z = s.z.data();
  double *vx = s.vx.data(), *vy = s.vy.data(), *vz = s.vz.data();
  const double *fx = s.fx.data(), *fy = s.fy.data(), *fz = s.fz.data();
  double *tx = vtx_.data(), *ty = vty_.data(), *tz = vtz_.data();
  // The wrap is per bead, so it joins the drift's pass over each thread's share of the beads.
#pragma omp parallel num_threads(team_size(threads_))
  {
    const auto [lo, hi] = team_share(n, omp_get_thread_num(), omp_get_num_threads());
    drift(lo, hi, x, vx, fx, tx), drift(lo, hi, y, vy, fy, ty), drift(lo, hi, z, vz, fz, tz);
    s.wrap(lo, hi);
  }
  const ForceSums sums = force(s, VelocityView{tx, ty, tz});
#pragma omp parallel num_threads(team_size(threads_))
  {
    const auto [lo, hi] = team_share(n, omp_get_thread_num(), omp_get_num_threads());
    kick(lo, hi, vx, fx), kick(lo, hi, vy, fy), kick(lo, hi, vz, fz);
  }
  return sums;
}

}  // namespace dpdrng::dpd
