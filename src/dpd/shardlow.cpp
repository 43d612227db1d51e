#include "dpdrng/dpd/shardlow.hpp"

#include <array>
#include <cmath>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "pair_sweep_impl.hpp"

namespace dpdrng::dpd {

namespace {

std::function<double(const rng::PairInput&)> make_zeta(const WaterConfig& cfg) {
  const bool gauss = cfg.distribution == rng::Distribution::gauss;
  if (cfg.generator.name == "mt19937") {
    // A stream: the sweep's fixed pair order is the order of the draws (the blocks feed takes two words a pair).
    auto mt = std::make_shared<rng::Mt19937>(cfg.seed);
    const rng::Feed feed = cfg.feed;
    return [mt, gauss, feed](const rng::PairInput&) {
      const std::array<std::uint64_t, 1> a{mt->next64()};
      if (!gauss) return rng::uniform_unit_variance(a);
      const std::array<std::uint64_t, 1> b{feed == rng::Feed::blocks ? mt->next64() : a[0]};
      return rng::draw<rng::Distribution::gauss>(feed, a, b);
    };
  }
  return rng::with_pair_noise(
      cfg.generator, cfg.seeding, cfg.distribution, cfg.seed,
      [](auto noise) -> std::function<double(const rng::PairInput&)> {
        return [noise](const rng::PairInput& p) { return noise(p); };
      },
      cfg.feed);
}

}  // namespace

ShardlowSweep::ShardlowSweep(const WaterConfig& cfg)
    : rc_(cfg.rc),
      gamma_(cfg.gamma),
      sigma_(std::sqrt(2.0 * cfg.gamma * cfg.kT)),
      dt_(cfg.dt),
      stream_(cfg.generator.name == "mt19937"),
      zeta_(make_zeta(cfg)),
      pairs_(cfg.rc, cfg.threads) {}

// Along ê = d/r the pair's relative velocity u = ê·(v_j − v_i) obeys du = −2γw²u dt + 2σw dW, and v_i moves by
// Δ = (γw²u dt − σw dW) ê (v_j by −Δ; the sign convention of DpdKernel). S1: Δ1 explicit over Δt/2, then Δ2
// implicit over Δt/2 (u at its end), the one ζ shared by both halves. With a = γw²Δt this maps
// u → [(1 − a)u + 2σwζ√Δt] / (1 + a), whose stationary variance is exactly σ²/γ = 2k_BT.
void ShardlowSweep::update_pair(double* const (&v)[3], std::uint32_t a, std::uint32_t b, std::uint32_t i,
                                std::uint32_t j, double dx, double dy, double dz, double r2, std::uint64_t step,
                                ZetaSums& z) const {
  const double r = std::sqrt(r2);
  const double ex = dx / r, ey = dy / r, ez = dz / r;
  const double w = 1.0 - r / rc_;
  const double half_a = 0.5 * gamma_ * w * w * dt_;
  const double zeta = zeta_(rng::PairInput{i, j, dx, dy, dz, step});
  z.add(zeta);
  z.w2 += w * w, z.w2z2 += w * w * zeta * zeta;
  const double half_noise = 0.5 * sigma_ * w * std::sqrt(dt_) * zeta;
  double* const vx = v[0];
  double* const vy = v[1];
  double* const vz = v[2];
  double u = ex * (vx[b] - vx[a]) + ey * (vy[b] - vy[a]) + ez * (vz[b] - vz[a]);
  const double d1 = half_a * u - half_noise;
  u -= 2.0 * d1;
  const double d2 = (half_a * u - half_noise) / (1.0 + 2.0 * half_a);
  const double d = d1 + d2;
  vx[a] += d * ex, vy[a] += d * ey, vz[a] += d * ez;
  vx[b] -= d * ex, vy[b] -= d * ey, vz[b] -= d * ez;
}

void ShardlowSweep::sweep(System& s, std::uint64_t step) {
  zeta_sums_ = pairs_.sweep<ZetaSums>(
      s, stream_,
      [this, step](double* const (&v)[3], std::uint32_t a, std::uint32_t b, std::uint32_t i, std::uint32_t j,
                   double dx, double dy, double dz, double r2, ZetaSums& z) {
        update_pair(v, a, b, i, j, dx, dy, dz, r2, step, z);
      });
}

ForceSums ShardlowS1::start(System& s, const ForceFn& force) {
  step_ = 0;
  return force(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()});
}

ForceSums ShardlowS1::step(System& s, const ForceFn& force) {
  sweep_.sweep(s, ++step_);
  const ZetaSums drawn = sweep_.zeta_sums();
  const std::size_t n = s.size();
  const double dt = dt_, half = 0.5 * dt_;
  double *x = s.x.data(), *y = s.y.data(), *z = s.z.data();
  double *vx = s.vx.data(), *vy = s.vy.data(), *vz = s.vz.data();
  const double *fx = s.fx.data(), *fy = s.fy.data(), *fz = s.fz.data();
#pragma omp parallel for num_threads(team_size(threads_)) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    vx[i] += half * fx[i], vy[i] += half * fy[i], vz[i] += half * fz[i];
    x[i] += dt * vx[i], y[i] += dt * vy[i], z[i] += dt * vz[i];
  }
  s.wrap();
  const ForceSums sums = force(s, VelocityView{vx, vy, vz});
#pragma omp parallel for num_threads(team_size(threads_)) schedule(static)
  for (std::size_t i = 0; i < n; ++i) vx[i] += half * fx[i], vy[i] += half * fy[i], vz[i] += half * fz[i];
  ForceSums out = sums;
  out.zeta = drawn;
  return out;
}

}  // namespace dpdrng::dpd
