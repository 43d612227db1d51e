#include "dpdrng/dpd/self_consistent.hpp"

#include <omp.h>

namespace dpdrng::dpd {

namespace {

// The three components' arrays of a System or of a scratch triple.
struct Triple {
  double* c[3];
};
Triple velocities(System& s) { return {{s.vx.data(), s.vy.data(), s.vz.data()}}; }
Triple forces(System& s) { return {{s.fx.data(), s.fy.data(), s.fz.data()}}; }
Triple scratch(std::vector<double> (&a)[3], std::size_t n) {
  for (auto& v : a) v.resize(n);
  return {{a[0].data(), a[1].data(), a[2].data()}};
}

// Runs body(lo, hi) on each thread's share of n beads: per-bead work, so any team gives the same bits.
template <class Body>
void per_bead(std::size_t n, int threads, Body&& body) {
#pragma omp parallel num_threads(team_size(threads))
  {
    const auto [lo, hi] = team_share(n, omp_get_thread_num(), omp_get_num_threads());
    body(lo, hi);
  }
}

}  // namespace

ForceSums SelfConsistentVerlet::start(System& s, const ForceFn& force) {
  return force(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()});
}

ForceSums SelfConsistentVerlet::step(System& s, const ForceFn& force, const ForceFn& dissipative) {
  const std::size_t n = s.size();
  const double dt = dt_, half = 0.5 * dt_;
  const Triple v = velocities(s), f = forces(s), vh = scratch(half_, n), full = scratch(full_, n),
               dv = scratch(diff_, n);
  double *x[3] = {s.x.data(), s.y.data(), s.z.data()};
  per_bead(n, threads_, [&](std::size_t lo, std::size_t hi) {
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = lo; i < hi; ++i) {
        vh.c[a][i] = v.c[a][i] + half * f.c[a][i];
        x[a][i] += dt * vh.c[a][i];
      }
    s.wrap(lo, hi);
  });
  ForceSums sums = force(s, VelocityView{vh.c[0], vh.c[1], vh.c[2]});
  per_bead(n, threads_, [&](std::size_t lo, std::size_t hi) {
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = lo; i < hi; ++i) {
        full.c[a][i] = f.c[a][i];
        v.c[a][i] = vh.c[a][i] + half * f.c[a][i];
      }
  });
  for (int k = 1; k <= iterations_; ++k) {
    per_bead(n, threads_, [&](std::size_t lo, std::size_t hi) {
      for (int a = 0; a < 3; ++a)
        for (std::size_t i = lo; i < hi; ++i) dv.c[a][i] = v.c[a][i] - vh.c[a][i];
    });
    const ForceSums d = dissipative(s, VelocityView{dv.c[0], dv.c[1], dv.c[2]});
    const bool last = k == iterations_;
    per_bead(n, threads_, [&](std::size_t lo, std::size_t hi) {
      for (int a = 0; a < 3; ++a)
        for (std::size_t i = lo; i < hi; ++i) {
          f.c[a][i] += full.c[a][i];
          if (!last) v.c[a][i] = vh.c[a][i] + half * f.c[a][i];
        }
    });
    if (last)
      for (int a = 0; a < 3; ++a) sums.virial[a] += d.virial[a];
  }
  return sums;
}

}  // namespace dpdrng::dpd
