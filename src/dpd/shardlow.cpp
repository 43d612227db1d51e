#include "dpdrng/dpd/shardlow.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <omp.h>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/dispatch.hpp"

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

// Colour of a slab along z: its first layer's parity, and 2 for the last layer of an odd count (its slab wraps
// onto layer 0, as the slab at layer 0 does).
int colour_of(int layer, int n) { return n % 2 == 1 && layer == n - 1 ? 2 : layer % 2; }

constexpr int kColours = 3;

// Half of a cell's 8 neighbours in its layer: with the other half seen from the neighbours, each pair once.
constexpr int kInLayer[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};

}  // namespace

ShardlowSweep::ShardlowSweep(const WaterConfig& cfg)
    : rc_(cfg.rc),
      gamma_(cfg.gamma),
      sigma_(std::sqrt(2.0 * cfg.gamma * cfg.kT)),
      dt_(cfg.dt),
      threads_(cfg.threads),
      stream_(cfg.generator.name == "mt19937"),
      zeta_(make_zeta(cfg)) {}

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

void ShardlowSweep::sort_by_cell(const System& s) {
  const std::size_t n = s.size();
  for (auto* a : {&px_, &py_, &pz_, &vx_, &vy_, &vz_}) a->resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = cell_beads_[k];
    px_[k] = s.x[i], py_[k] = s.y[i], pz_[k] = s.z[i];
    vx_[k] = s.vx[i], vy_[k] = s.vy[i], vz_[k] = s.vz[i];
  }
}

void ShardlowSweep::sweep_slab(const System& s, int layer, std::uint64_t step, ZetaSums& z) {
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = 0.5 * Lx, hy = 0.5 * Ly, hz = 0.5 * Lz, rc2 = rc_ * rc_;
  double* const v[3] = {vx_.data(), vy_.data(), vz_.data()};
  // Sorted slots a, b of two beads; the pair is (i < j) by bead number, d = r_j − r_i.
  auto visit = [&](std::uint32_t a, std::uint32_t b) {
    if (cell_beads_[a] > cell_beads_[b]) std::swap(a, b);
    const double dx = min_image(px_[b] - px_[a], Lx, hx), dy = min_image(py_[b] - py_[a], Ly, hy),
                 dz = min_image(pz_[b] - pz_[a], Lz, hz);
    const double r2 = dx * dx + dy * dy + dz * dz;
    if (r2 < rc2 && r2 > 0) update_pair(v, a, b, cell_beads_[a], cell_beads_[b], dx, dy, dz, r2, step, z);
  };
  auto cells = [&](std::size_t A, std::size_t B) {
    for (std::uint32_t a = cell_start_[A]; a < cell_start_[A + 1]; ++a)
      for (std::uint32_t b = cell_start_[B]; b < cell_start_[B + 1]; ++b) visit(a, b);
  };
  const int nx = nc_[0], ny = nc_[1], up = (layer + 1) % nc_[2];
  auto cell = [&](int cx, int cy, int cz) {
    return (std::size_t(cz) * ny + (cy + ny) % ny) * nx + (cx + nx) % nx;
  };
  for (int cy = 0; cy < ny; ++cy)
    for (int cx = 0; cx < nx; ++cx) {
      const std::size_t c = cell(cx, cy, layer);
      for (std::uint32_t a = cell_start_[c]; a < cell_start_[c + 1]; ++a)
        for (std::uint32_t b = a + 1; b < cell_start_[c + 1]; ++b) visit(a, b);
      for (const auto& o : kInLayer) cells(c, cell(cx + o[0], cy + o[1], layer));
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) cells(c, cell(cx + ox, cy + oy, up));
    }
}

void ShardlowSweep::sweep_all_pairs(System& s, std::uint64_t step) {
  const std::size_t n = s.size();
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = 0.5 * Lx, hy = 0.5 * Ly, hz = 0.5 * Lz, rc2 = rc_ * rc_;
  double* const v[3] = {s.vx.data(), s.vy.data(), s.vz.data()};
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const double dx = min_image(s.x[j] - s.x[i], Lx, hx), dy = min_image(s.y[j] - s.y[i], Ly, hy),
                   dz = min_image(s.z[j] - s.z[i], Lz, hz);
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < rc2 && r2 > 0) update_pair(v, i, j, i, j, dx, dy, dz, r2, step, zeta_sums_);
    }
}

void ShardlowSweep::sweep(System& s, std::uint64_t step) {
  zeta_sums_ = ZetaSums{};
  build_cells(s);
  if (std::min({nc_[0], nc_[1], nc_[2]}) < 3) return sweep_all_pairs(s, step);
  sort_by_cell(s);
  // Slabs in sweep order: colour by colour, each colour's first layers ascending.
  const int nz = nc_[2];
  std::vector<int> order;
  std::vector<std::size_t> colour_start{0};
  for (int k = 0; k < kColours; ++k) {
    for (int layer = 0; layer < nz; ++layer)
      if (colour_of(layer, nz) == k) order.push_back(layer);
    colour_start.push_back(order.size());
  }
  slab_zeta_.assign(order.size(), ZetaSums{});
  const int threads = stream_ ? 1 : threads_ > 0 ? threads_ : omp_get_max_threads();
#pragma omp parallel num_threads(threads)
  for (int k = 0; k < kColours; ++k) {
    if (colour_start[k] == colour_start[k + 1]) continue;  // the same for every thread
    // The implicit barrier at the loop's end keeps colours apart.
#pragma omp for schedule(static)
    for (std::size_t b = colour_start[k]; b < colour_start[k + 1]; ++b) sweep_slab(s, order[b], step, slab_zeta_[b]);
  }
  for (const ZetaSums& z : slab_zeta_) zeta_sums_.merge(z);
  const std::size_t n = s.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = cell_beads_[k];
    s.vx[i] = vx_[k], s.vy[i] = vy_[k], s.vz[i] = vz_[k];
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
