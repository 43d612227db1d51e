#include "dpdrng/dpd/integrator.hpp"

namespace dpdrng::dpd {

ForceSums ModifiedVelocityVerlet::start(System& s, const ForceFn& force) {
  return force(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()});
}

ForceSums ModifiedVelocityVerlet::step(System& s, const ForceFn& force) {
  const std::size_t n = s.size();
  vtx_.resize(n), vty_.resize(n), vtz_.resize(n);
  const double dt = dt_, half = 0.5 * dt_, half_dt2 = 0.5 * dt_ * dt_, ldt = lambda_ * dt_;
  double *x = s.x.data(), *y = s.y.data(), *z = s.z.data();
  double *vx = s.vx.data(), *vy = s.vy.data(), *vz = s.vz.data();
  const double *fx = s.fx.data(), *fy = s.fy.data(), *fz = s.fz.data();
  double *tx = vtx_.data(), *ty = vty_.data(), *tz = vtz_.data();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    x[i] += dt * vx[i] + half_dt2 * fx[i];
    y[i] += dt * vy[i] + half_dt2 * fy[i];
    z[i] += dt * vz[i] + half_dt2 * fz[i];
    tx[i] = vx[i] + ldt * fx[i];
    ty[i] = vy[i] + ldt * fy[i];
    tz[i] = vz[i] + ldt * fz[i];
    vx[i] += half * fx[i];
    vy[i] += half * fy[i];
    vz[i] += half * fz[i];
  }
  s.wrap();
  const ForceSums sums = force(s, VelocityView{tx, ty, tz});
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    vx[i] += half * fx[i];
    vy[i] += half * fy[i];
    vz[i] += half * fz[i];
  }
  return sums;
}

}  // namespace dpdrng::dpd
