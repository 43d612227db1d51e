#include "dpdrng/dpd/shardlow.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/registry.hpp"

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

// Cell index along one axis; positions are wrapped into [0, L), the clamps only guard rounding.
int cell_along(double x, double inv_w, int n) {
  const double t = x * inv_w;
  if (!(t >= 0)) return 0;
  return std::min(n - 1, static_cast<int>(t));
}

}  // namespace

ShardlowSweep::ShardlowSweep(const WaterConfig& cfg)
    : rc_(cfg.rc),
      gamma_(cfg.gamma),
      sigma_(std::sqrt(2.0 * cfg.gamma * cfg.kT)),
      dt_(cfg.dt),
      zeta_(make_zeta(cfg)) {}

// Along ê = d/r the pair's relative velocity u = ê·(v_j − v_i) obeys du = −2γw²u dt + 2σw dW, and v_i moves by
// Δ = (γw²u dt − σw dW) ê (v_j by −Δ; the sign convention of DpdKernel). S1: Δ1 explicit over Δt/2, then Δ2
// implicit over Δt/2 (u at its end), the one ζ shared by both halves. With a = γw²Δt this maps
// u → [(1 − a)u + 2σwζ√Δt] / (1 + a), whose stationary variance is exactly σ²/γ = 2k_BT.
void ShardlowSweep::update_pair(System& s, std::uint32_t i, std::uint32_t j, double dx, double dy, double dz,
                                double r2, std::uint64_t step) {
  const double r = std::sqrt(r2);
  const double ex = dx / r, ey = dy / r, ez = dz / r;
  const double w = 1.0 - r / rc_;
  const double half_a = 0.5 * gamma_ * w * w * dt_;
  const double zeta = zeta_(rng::PairInput{i, j, dx, dy, dz, step});
  zeta_sums_.add(zeta);
  const double half_noise = 0.5 * sigma_ * w * std::sqrt(dt_) * zeta;
  double u = ex * (s.vx[j] - s.vx[i]) + ey * (s.vy[j] - s.vy[i]) + ez * (s.vz[j] - s.vz[i]);
  const double d1 = half_a * u - half_noise;
  u -= 2.0 * d1;
  const double d2 = (half_a * u - half_noise) / (1.0 + 2.0 * half_a);
  const double d = d1 + d2;
  s.vx[i] += d * ex, s.vy[i] += d * ey, s.vz[i] += d * ez;
  s.vx[j] -= d * ex, s.vy[j] -= d * ey, s.vz[j] -= d * ez;
}

void ShardlowSweep::build_cells(const System& s) {
  const std::size_t n = s.size();
  std::size_t ncell = 1;
  double inv_w[3];
  for (int d = 0; d < 3; ++d) {
    nc_[d] = static_cast<int>(std::floor(s.box.L[d] / rc_));
    inv_w[d] = nc_[d] / s.box.L[d];
    ncell *= static_cast<std::size_t>(std::max(nc_[d], 1));
  }
  if (std::min({nc_[0], nc_[1], nc_[2]}) < 3) return;  // fewer than 3 cells: the 27-cell stencil repeats cells
  cell_start_.assign(ncell + 1, 0);
  bead_cell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int cx = cell_along(s.x[i], inv_w[0], nc_[0]), cy = cell_along(s.y[i], inv_w[1], nc_[1]),
              cz = cell_along(s.z[i], inv_w[2], nc_[2]);
    bead_cell_[i] = static_cast<std::uint32_t>((cz * nc_[1] + cy) * nc_[0] + cx);
    ++cell_start_[bead_cell_[i] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_beads_.resize(n);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) cell_beads_[fill[bead_cell_[i]]++] = static_cast<std::uint32_t>(i);
}

void ShardlowSweep::sweep(System& s, std::uint64_t step) {
  const std::size_t n = s.size();
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = 0.5 * Lx, hy = 0.5 * Ly, hz = 0.5 * Lz, rc2 = rc_ * rc_;
  zeta_sums_ = ZetaSums{};
  auto visit = [&](std::uint32_t i, std::uint32_t j) {
    const double dx = min_image(s.x[j] - s.x[i], Lx, hx), dy = min_image(s.y[j] - s.y[i], Ly, hy),
                 dz = min_image(s.z[j] - s.z[i], Lz, hz);
    const double r2 = dx * dx + dy * dy + dz * dz;
    if (r2 < rc2 && r2 > 0) update_pair(s, i, j, dx, dy, dz, r2, step);
  };
  build_cells(s);
  if (std::min({nc_[0], nc_[1], nc_[2]}) < 3) {
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j) visit(i, j);
    return;
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const int c = static_cast<int>(bead_cell_[i]);
    const int cx = c % nc_[0], cy = (c / nc_[0]) % nc_[1], cz = c / (nc_[0] * nc_[1]);
    for (int oz = -1; oz <= 1; ++oz)
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
          const int nx = (cx + ox + nc_[0]) % nc_[0], ny = (cy + oy + nc_[1]) % nc_[1],
                    nz = (cz + oz + nc_[2]) % nc_[2];
          const std::size_t nb = std::size_t(nz * nc_[1] + ny) * nc_[0] + nx;
          for (std::uint32_t k = cell_start_[nb]; k < cell_start_[nb + 1]; ++k)
            if (cell_beads_[k] > i) visit(i, cell_beads_[k]);
        }
  }
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
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    vx[i] += half * fx[i], vy[i] += half * fy[i], vz[i] += half * fz[i];
    x[i] += dt * vx[i], y[i] += dt * vy[i], z[i] += dt * vz[i];
  }
  s.wrap();
  const ForceSums sums = force(s, VelocityView{vx, vy, vz});
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n; ++i) vx[i] += half * fx[i], vy[i] += half * fy[i], vz[i] += half * fz[i];
  ForceSums out = sums;
  out.zeta = drawn;
  return out;
}

WaterIntegrator::WaterIntegrator(const WaterConfig& cfg) : mvv_(cfg.dt, cfg.lambda, cfg.threads) {
  if (cfg.integrator == Integrator::shardlow) s1_ = std::make_unique<ShardlowS1>(cfg);
}

ForceSums WaterIntegrator::start(System& s, const ForceFn& force) {
  return s1_ ? s1_->start(s, force) : mvv_.start(s, force);
}

ForceSums WaterIntegrator::step(System& s, const ForceFn& force) {
  return s1_ ? s1_->step(s, force) : mvv_.step(s, force);
}

WaterConfig pair_force_config(const WaterConfig& cfg) {
  WaterConfig c = cfg;
  if (cfg.integrator == Integrator::shardlow) c.noise_override = NoiseOverride::none;
  return c;
}

DpdKernel pair_force_kernel(const WaterConfig& cfg) {
  const double gamma = cfg.integrator == Integrator::shardlow ? 0.0 : cfg.gamma;
  return make_kernel(cfg.a, cfg.rc, gamma, cfg.kT, cfg.dt);
}

}  // namespace dpdrng::dpd
