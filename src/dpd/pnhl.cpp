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
    : kT_(cfg.kT),
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
#pragma omp parallel for num_threads(team_size(threads_)) schedule(static)
  for (std::size_t i = 0; i < n; ++i) x[i] += h * vx[i], y[i] += h * vy[i], z[i] += h * vz[i];
  s.wrap();
}

void PairwiseNoseHooverLangevin::kick_half(System& s) const {
  const std::size_t n = s.size();
  const double h = 0.5 * dt_;
  double *vx = s.vx.data(), *vy = s.vy.data(), *vz = s.vz.data();
  const double *fx = s.fx.data(), *fy = s.fy.data(), *fz = s.fz.data();
#pragma omp parallel for num_threads(team_size(threads_)) schedule(static)
  for (std::size_t i = 0; i < n; ++i) vx[i] += h * fx[i], vy[i] += h * fy[i], vz[i] += h * fz[i];
}

void PairwiseNoseHooverLangevin::friction_half() {
  const double rate = -2.0 * xi_ * 0.5 * dt_;
  pairs_.replay<NoSum>([rate](double* const (&v)[3], const PairSweep::Pair& p, NoSum&) {
    const std::uint32_t a = p.a, b = p.b;
    const double u = p.ex * (v[0][b] - v[0][a]) + p.ey * (v[1][b] - v[1][a]) + p.ez * (v[2][b] - v[2][a]);
    const double d = 0.5 * u * std::expm1(rate * p.w * p.w);  // half of u(t) − u
    v[0][a] -= d * p.ex, v[1][a] -= d * p.ey, v[2][a] -= d * p.ez;
    v[0][b] += d * p.ex, v[1][b] += d * p.ey, v[2][b] += d * p.ez;
  });
}

double PairwiseNoseHooverLangevin::pair_g() {
  const double two_kT = 2.0 * kT_;
  return pairs_
      .replay<GSum>([two_kT](double* const (&v)[3], const PairSweep::Pair& p, GSum& g) {
        const std::uint32_t a = p.a, b = p.b;
        const double u = p.ex * (v[0][b] - v[0][a]) + p.ey * (v[1][b] - v[1][a]) + p.ez * (v[2][b] - v[2][a]);
        g.g += p.w * p.w * (u * u - two_kT);
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
  // The positions stay put from here to the second drift: the pairs are found once.
  pairs_.record(s);
  friction_half();
  const double push = 0.5 * dt_ * pair_g() / mu_;
  const double decay = std::exp(-gamma_ * dt_);
  const double spread = std::sqrt(kT_ / mu_ * -std::expm1(-2.0 * gamma_ * dt_));
  const double zeta = rng::box_muller(std::array<std::uint64_t, 1>{mt_.next64()});
  xi_ = decay * (xi_ + push) + spread * zeta + push;
  friction_half();
  pairs_.release(s);
  drift_half(s);
  const ForceSums sums = force(s, v);
  kick_half(s);
  return sums;
}

}  // namespace dpdrng::dpd
