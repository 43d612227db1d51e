// The bilayer's model (topology, a_ij) and its pre-assembled starting configuration.
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/dpd/bilayer.hpp"
#include "validate.hpp"

namespace dpdrng::dpd {

Topology lipid_topology(std::size_t lipids) {
  Topology t;
  t.bonds.reserve(14 * lipids);
  t.angles.reserve(10 * lipids);
  for (std::size_t l = 0; l < lipids; ++l) {
    const auto b = static_cast<std::uint32_t>(l * kLipidBeads);
    const std::uint32_t H1 = b, H2 = b + 1, H3 = b + 2, Ta = b + kTailA, Tb = b + kTailB;
    t.bonds.push_back({H1, H2});
    t.bonds.push_back({H2, H3});
    t.bonds.push_back({H3, Ta});
    t.bonds.push_back({H2, Tb});
    for (std::uint32_t k = 0; k + 1 < kTailLength; ++k) t.bonds.push_back({Ta + k, Ta + k + 1});
    for (std::uint32_t k = 0; k + 1 < kTailLength; ++k) t.bonds.push_back({Tb + k, Tb + k + 1});
    t.angles.push_back({H3, Ta, Ta + 1});
    t.angles.push_back({H2, Tb, Tb + 1});
    for (std::uint32_t k = 0; k + 2 < kTailLength; ++k) t.angles.push_back({Ta + k, Ta + k + 1, Ta + k + 2});
    for (std::uint32_t k = 0; k + 2 < kTailLength; ++k) t.angles.push_back({Tb + k, Tb + k + 1, Tb + k + 2});
  }
  return t;
}

DpdKernel bilayer_kernel(const BilayerConfig& cfg, double dt) {
  DpdKernel k;
  k.rc = cfg.rc;
  k.gamma = cfg.gamma;
  k.sigma = std::sqrt(2.0 * cfg.gamma * cfg.kT);
  k.inv_sqrt_dt = 1.0 / std::sqrt(dt);
  k.ntypes = 3;
  k.a.assign(cfg.a.begin(), cfg.a.end());
  return k;
}

namespace {
using validate::bad;
using validate::positive;
// Height of H1 above the midplane in the pre-assembled bilayer: 8.5 bond lengths (see build_bilayer).
double head_height(const BilayerConfig& c) { return 8.5 * c.bond.r0; }
}  // namespace

void BilayerConfig::validate() const {
  for (int d = 0; d < 3; ++d) {
    positive(box[d], "box");
    if (!(box[d] > 2 * rc)) bad("box", "every side must exceed 2*rc");
  }
  positive(rc, "rc");
  positive(kT, "kT");
  if (!(gamma >= 0) || !std::isfinite(gamma)) bad("gamma", "must be finite and not negative");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (!std::isfinite(a[3 * i + j])) bad("a", "must be finite");
      if (a[3 * i + j] != a[3 * j + i]) bad("a", "the a_ij matrix must be symmetric");
    }
  positive(bond.k, "bond.k");
  positive(bond.r0, "bond.r0");
  if (!(bend.k >= 0) || !std::isfinite(bend.k)) bad("bend.k", "must be finite and not negative");
  if (lipids_per_leaflet < 1) bad("lipids_per_leaflet", "at least 1");
  if (particles < static_cast<long long>(lipids()) * kLipidBeads || particles > 50'000'000)
    bad("particles", std::to_string(particles) + " (at least 15 per lipid, at most 5e7)");
  if (!(head_height(*this) < 0.5 * box[2])) bad("box", "L_z too small for the pre-assembled bilayer");
  if (!(water_gap >= 0) || !(water_gap < 0.5 * box[2]))
    bad("water_gap", exact_decimal(water_gap) + " (0 <= water_gap < L_z/2)");
  if (!(lambda >= 0 && lambda <= 1)) bad("lambda", exact_decimal(lambda) + " (0..1)");
  positive(dt, "dt");
  positive(dt_warmup, "dt_warmup");
  const double longest = std::max({box[0], box[1], box[2]});
  check_step_resolves(dt, kT, longest, "dt");
  check_step_resolves(dt_warmup, kT, longest, "dt_warmup");
  if (steps < 1) bad("steps", std::to_string(steps) + " (at least 1)");
  if (warmup < 0 || warmup > steps) bad("warmup", std::to_string(warmup) + " (0..steps)");
  if (equilibrate < warmup || equilibrate >= steps)
    bad("equilibrate", std::to_string(equilibrate) + " (warmup <= equilibrate < steps)");
  rng::validated(generator);
  if (seeding == rng::Seeding::counter) bad("seeding", "'counter' makes streams; pair noise needs distance or pair-step");
  if (distribution == rng::Distribution::uniform && feed != rng::Feed::halves)
    bad("feed", std::string(rng::to_string(feed)) + " applies to Gaussian noise only (uniform takes feed halves)");
  if (threads < 0) bad("threads", "must not be negative");
  if (sample_every < 1) bad("sample_every", "at least 1");
  if (zeta_lags < 0 || zeta_lags > 1000) bad("zeta_lags", "must lie in 0..1000");
  positive(profile_bin, "profile_bin");
  if (blocks < 2) bad("blocks", "at least 2");
  positive(escape_distance, "escape_distance");
  positive(max_temperature, "max_temperature");
  if (!(min_distance >= 0)) bad("min_distance", "must not be negative");
  positive(max_bond, "max_bond");
  if (!(max_bond < 0.5 * std::min({box[0], box[1], box[2]})))
    bad("max_bond", "must stay below half the shortest box side (minimum image)");
}

namespace {
// Lateral sites of one leaflet: the rank-1 lattice {(k/N, frac(k·g/N))}·(L_x, L_y), k = 0…N−1, which tiles the
// periodic plane exactly; g is the multiplier whose lattice has the largest nearest-neighbour distance, so
// the sites come out as close to hexagonal as N allows.
std::vector<std::array<double, 2>> leaflet_sites(int n, double Lx, double Ly) {
  auto min_dist2 = [&](int g) {
    double best = INFINITY;
    for (int k = 1; k < n; ++k) {
      const double dx = min_image(Lx * k / n, Lx, 0.5 * Lx);
      const double dy = min_image(Ly * double((long long)k * g % n) / n, Ly, 0.5 * Ly);
      best = std::min(best, dx * dx + dy * dy);
    }
    return best;
  };
  int g_best = 1;
  double d_best = -1;
  for (int g = 1; g < std::max(2, n); ++g) {
    const double d = n > 1 ? min_dist2(g) : 0.0;
    if (d > d_best) d_best = d, g_best = g;
  }
  std::vector<std::array<double, 2>> sites(n);
  for (int k = 0; k < n; ++k) sites[k] = {Lx * k / n, Ly * double((long long)k * g_best % n) / n};
  return sites;
}
}  // namespace

BilayerState build_bilayer(const BilayerConfig& cfg) {
  cfg.validate();
  BilayerState st;
  st.lipids = cfg.lipids();
  st.topology = lipid_topology(st.lipids);
  System& s = st.system;
  s.box = Box{cfg.box};
  const std::size_t n = static_cast<std::size_t>(cfg.particles);
  s.resize(n);
  std::mt19937_64 eng(cfg.init_seed);
  // Hand-written transforms rather than std:: distributions, whose output differs between standard libraries.
  auto unit = [&] { return static_cast<double>(eng() >> 11) * 0x1p-53; };
  auto gauss = [&] {
    const double u1 = 1.0 - unit(), u2 = unit();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  };
  const double Lx = cfg.box[0], Ly = cfg.box[1], Lz = cfg.box[2], zc = 0.5 * Lz, b = cfg.bond.r0;
  auto put = [&](std::size_t i, double x, double y, double z, BeadType t) {
    s.x[i] = x, s.y[i] = y, s.z[i] = z, s.type[i] = t;
  };
  // Straight tails at bond length along z, their ends meeting at the midplane: Ta6 at b/2, …, Ta1 at 5.5 b,
  // H3 6.5 b, H2 7.5 b, H1 8.5 b from the midplane. Tb1 hangs off H2 at bond length (0.8 b sideways, in a
  // random direction per lipid, and 0.6 b down) and Tb runs straight down from there. Heads face the water.
  const auto sites = leaflet_sites(cfg.lipids_per_leaflet, Lx, Ly);
  std::size_t i = 0;
  for (int leaflet = 0; leaflet < 2; ++leaflet) {
    const double sign = leaflet == 0 ? 1.0 : -1.0;
    for (const auto& site : sites) {
      const double x = site[0], y = site[1];
      const double phi = 2.0 * std::numbers::pi * unit();
      const double bx = x + 0.8 * b * std::cos(phi), by = y + 0.8 * b * std::sin(phi);
      put(i + 0, x, y, zc + sign * 8.5 * b, kHead);
      put(i + 1, x, y, zc + sign * 7.5 * b, kHead);
      put(i + 2, x, y, zc + sign * 6.5 * b, kHead);
      for (int k = 0; k < kTailLength; ++k) {
        put(i + kTailA + k, x, y, zc + sign * (5.5 - k) * b, kTail);
        put(i + kTailB + k, bx, by, zc + sign * (6.9 - k) * b, kTail);
      }
      i += kLipidBeads;
    }
  }
  // Water uniformly where |z − z_c| > water_gap.
  const double slab = Lz - 2.0 * cfg.water_gap;
  for (; i < n; ++i) put(i, unit() * Lx, unit() * Ly, zc + cfg.water_gap + unit() * slab, kWater);
  s.wrap();
  // The lattice sites need no image history: start every image counter at zero.
  for (auto* v : {&s.ix, &s.iy, &s.iz}) v->assign(n, 0);

  const double sd = std::sqrt(cfg.kT);
  for (std::size_t k = 0; k < n; ++k) s.vx[k] = sd * gauss(), s.vy[k] = sd * gauss(), s.vz[k] = sd * gauss();
  if (n > 1) {
    const auto p = s.momentum();
    for (std::size_t k = 0; k < n; ++k) s.vx[k] -= p[0] / n, s.vy[k] -= p[1] / n, s.vz[k] -= p[2] / n;
    const double scale = std::sqrt(cfg.kT * (3.0 * n - 3.0) / s.kinetic_twice());
    for (std::size_t k = 0; k < n; ++k) s.vx[k] *= scale, s.vy[k] *= scale, s.vz[k] *= scale;
  }
  return st;
}

}  // namespace dpdrng::dpd
