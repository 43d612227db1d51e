#include "dpdrng/dpd/pnhl.hpp"

#include <array>
#include <cmath>

#include "dpdrng/rng/distribution.hpp"
#include "pair_sweep_impl.hpp"

namespace dpdrng::dpd {

namespace {

// A slab's partial sum of G (merged in sweep order).
struct GSum {
  double g = 0;
  void merge(const GSum& o) { g += o.g; }
};

// The friction sweep draws nothing and sums nothing.
struct NoSum {
  void merge(const NoSum&) {}
};

}  // namespace

PairwiseNoseHooverLangevin::PairwiseNoseHooverLangevin(const WaterConfig& cfg)
    : rc_(cfg.rc),
      kT_(cfg.kT),
      gamma_(cfg.gamma),
      mu_(cfg.pnhln_mu),
      dt_(cfg.dt),
      threads_(cfg.threads),
      mt_(cfg.seed),
      pairs_(cfg.rc, cfg.threads) {}

void PairwiseNoseHooverLangevin::drift_half(System& s) const {
  const std::size_t n = s.size();
  const double h = 0.5 * dt_;
  double *x = s.x.data(), *y = s.y.data(), *z = s.z.data();
  const double *vx = s.vx.data(), *vy = s.vy.data(), *vz = s.vz.data();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n; ++i) x[i] += h * vx[i], y[i] += h * vy[i], z[i] += h * vz[i];
  s.wrap();
}

void PairwiseNoseHooverLangevin::kick_half(System& s) const {
  const std::size_t n = s.size();
  const double h = 0.5 * dt_;
  double *vx = s.vx.data(), *vy = s.vy.data(), *vz = s.vz.data();
  const double *fx = s.fx.data(), *fy = s.fy.data(), *fz = s.fz.data();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n; ++i) vx[i] += h * fx[i], vy[i] += h * fy[i], vz[i] += h * fz[i];
}

void PairwiseNoseHooverLangevin::friction_half(System& s) {
  const double rate = -2.0 * xi_ * 0.5 * dt_, inv_rc = 1.0 / rc_;
  pairs_.sweep<NoSum>(s, false,
                      [rate, inv_rc](double* const (&v)[3], std::uint32_t a, std::uint32_t b, std::uint32_t,
                                     std::uint32_t, double dx, double dy, double dz, double r2, NoSum&) {
                        const double r = std::sqrt(r2);
                        const double ex = dx / r, ey = dy / r, ez = dz / r;
                        const double w = 1.0 - r * inv_rc;
                        double* const vx = v[0];
                        double* const vy = v[1];
                        double* const vz = v[2];
                        const double u = ex * (vx[b] - vx[a]) + ey * (vy[b] - vy[a]) + ez * (vz[b] - vz[a]);
                        const double d = 0.5 * u * std::expm1(rate * w * w);  // half of u(t) − u
                        vx[a] -= d * ex, vy[a] -= d * ey, vz[a] -= d * ez;
                        vx[b] += d * ex, vy[b] += d * ey, vz[b] += d * ez;
                      });
}

double PairwiseNoseHooverLangevin::pair_g(System& s) {
  const double two_kT = 2.0 * kT_, inv_rc = 1.0 / rc_;
  return pairs_
      .sweep<GSum>(s, false,
                   [two_kT, inv_rc](double* const (&v)[3], std::uint32_t a, std::uint32_t b, std::uint32_t,
                                    std::uint32_t, double dx, double dy, double dz, double r2, GSum& g) {
                     const double r = std::sqrt(r2);
                     const double w = 1.0 - r * inv_rc;
                     const double u = (dx * (v[0][b] - v[0][a]) + dy * (v[1][b] - v[1][a]) +
                                       dz * (v[2][b] - v[2][a])) / r;
                     g.g += w * w * (u * u - two_kT);
                   })
      .g;
}

ForceSums PairwiseNoseHooverLangevin::start(System& s, const ForceFn& force) {
  return force(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()});
}

ForceSums PairwiseNoseHooverLangevin::step(System& s, const ForceFn& force) {
  const VelocityView v{s.vx.data(), s.vy.data(), s.vz.data()};
  drift_half(s);
  force(s, v);
  kick_half(s);
  friction_half(s);
  const double push = 0.5 * dt_ * pair_g(s) / mu_;
  const double decay = std::exp(-gamma_ * dt_);
  const double spread = std::sqrt(kT_ / mu_ * -std::expm1(-2.0 * gamma_ * dt_));
  const double zeta = rng::box_muller(std::array<std::uint64_t, 1>{mt_.next64()});
  xi_ = decay * (xi_ + push) + spread * zeta + push;
  friction_half(s);
  drift_half(s);
  const ForceSums sums = force(s, v);
  kick_half(s);
  return sums;
}

}  // namespace dpdrng::dpd
