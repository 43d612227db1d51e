// The bilayer scene's model and builder: topology as Grafmüller, Shillcock & Lipowsky (2009) give it, a
// deterministic pre-assembled configuration, and the engine's typed pair forces plus the bonded terms checked against the total energy
// (finite differences of the forces, box-stretch derivative of the virial).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/bilayer_observables.hpp"
#include "dpdrng/dpd/pair_forces.hpp"

namespace dpdrng::dpd::test_bilayer_model {
namespace {

TEST(BilayerModel, TopologyOfOneLipid) {
  const Topology t = lipid_topology(2);
  ASSERT_EQ(t.bonds.size(), 28u);
  ASSERT_EQ(t.angles.size(), 20u);
  // Lipid 1 (beads 15..29): H1 H2 H3 Ta1..Ta6 Tb1..Tb6.
  std::set<std::pair<int, int>> bonds;
  for (std::size_t k = 14; k < 28; ++k) bonds.insert({int(t.bonds[k][0]) - 15, int(t.bonds[k][1]) - 15});
  const std::set<std::pair<int, int>> expect{{0, 1}, {1, 2}, {2, 3}, {3, 4},   {4, 5},   {5, 6},   {6, 7},
                                             {7, 8}, {1, 9}, {9, 10}, {10, 11}, {11, 12}, {12, 13}, {13, 14}};
  EXPECT_EQ(bonds, expect);
  std::set<std::array<int, 3>> angles;
  for (std::size_t k = 10; k < 20; ++k)
    angles.insert({int(t.angles[k][0]) - 15, int(t.angles[k][1]) - 15, int(t.angles[k][2]) - 15});
  const std::set<std::array<int, 3>> expect_angles{{2, 3, 4},   {3, 4, 5},    {4, 5, 6},    {5, 6, 7},
                                                   {6, 7, 8},   {1, 9, 10},   {9, 10, 11},  {10, 11, 12},
                                                   {11, 12, 13}, {12, 13, 14}};
  EXPECT_EQ(angles, expect_angles);
}

TEST(BilayerModel, BuilderMatchesIssue7) {
  const BilayerConfig cfg;
  const BilayerState st = build_bilayer(cfg);
  const System& s = st.system;
  ASSERT_EQ(s.size(), 5400u);
  EXPECT_EQ(st.lipids, 146u);
  EXPECT_EQ(std::count(s.type.begin(), s.type.end(), kHead), 146 * 3);
  EXPECT_EQ(std::count(s.type.begin(), s.type.end(), kTail), 146 * 12);
  EXPECT_EQ(std::count(s.type.begin(), s.type.end(), kWater), 5400 - 146 * 15);
  const double zc = 9.0;
  for (std::size_t i = 146 * 15; i < s.size(); ++i) EXPECT_GT(std::abs(s.z[i] - zc), 4.8);
  // Every bond starts at its rest length and every T–T–T angle straight.
  const BondedSums b = BondedForces{}.measure(s, st.topology);
  EXPECT_NEAR(b.energy_bond, 0.0, 1e-20);
  EXPECT_NEAR(b.max_bond, 0.5, 1e-12);
  // Only H2–Tb1–Tb2 is bent (Tb1 hangs off H2 sideways): cos φ = 0.6, U = 15·0.4 per lipid.
  EXPECT_NEAR(b.energy_bend, 146 * 15 * 0.4, 1e-9);
  // Heads outward: H1 above the tails in the upper leaflet (first 73 lipids), below in the lower.
  EXPECT_NEAR(s.z[0] - zc, 4.25, 1e-12);
  EXPECT_NEAR(s.z[73 * 15] - zc, -4.25, 1e-12);
  EXPECT_NEAR(bilayer_midplane(s, st.lipids), zc, 1e-9);
  EXPECT_EQ(lipids_out(s, st.lipids, zc, cfg.escape_distance), 0);
  EXPECT_NEAR(tail_order(s, st.lipids).mean, 1.0, 1e-12);  // straight tails along z
  // Lateral sites: 73 per leaflet with no two closer than 1.1 (hexagonal packing at 1.37 per lipid: 1.26).
  double dmin = 1e9;
  for (int p = 0; p < 73; ++p)
    for (int q = p + 1; q < 73; ++q) {
      const double dx = min_image(s.x[15 * q] - s.x[15 * p], 10, 5), dy = min_image(s.y[15 * q] - s.y[15 * p], 10, 5);
      dmin = std::min(dmin, std::hypot(dx, dy));
    }
  EXPECT_GT(dmin, 1.1);
  const auto p = s.momentum();
  for (double v : p) EXPECT_NEAR(v, 0.0, 1e-9);
  EXPECT_NEAR(s.kinetic_twice() / (3.0 * 5400 - 3.0), 1.0, 1e-12);
}

TEST(BilayerModel, BuilderIsDeterministic) {
  BilayerConfig cfg;
  const System a = build_bilayer(cfg).system, b = build_bilayer(cfg).system;
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.vz, b.vz);
  cfg.init_seed += 1;
  const System c = build_bilayer(cfg).system;
  EXPECT_NE(a.x, c.x);
}

TEST(BilayerModel, RejectsBadConfig) {
  BilayerConfig cfg;
  cfg.particles = 100;
  EXPECT_THROW(cfg.validate(), InputError);
  cfg = BilayerConfig{};
  cfg.equilibrate = 10;  // before the end of the warm-up
  EXPECT_THROW(cfg.validate(), InputError);
  cfg = BilayerConfig{};
  cfg.a[1] = 36;  // HT ≠ TH
  EXPECT_THROW(cfg.validate(), InputError);
  cfg = BilayerConfig{};
  cfg.box[2] = 8;  // the pre-assembled lipids (±4.25) do not fit
  EXPECT_THROW(cfg.validate(), InputError);
}

// A small bilayer patch (2 lipids per leaflet, some water) shaken out of its straight start, so that every
// term (each a_ij, bonds, bends) contributes.
struct Patch {
  BilayerConfig cfg;
  BilayerState st;
  Patch() {
    cfg.box = {3.2, 3.4, 9.0};
    cfg.lipids_per_leaflet = 2;
    cfg.particles = 60 + 40;
    cfg.water_gap = 3.0;
    cfg.max_bond = 1.5;
    st = build_bilayer(cfg);
    std::mt19937_64 eng(5);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    System& s = st.system;
    for (std::size_t i = 0; i < s.size(); ++i) s.x[i] += u(eng), s.y[i] += u(eng), s.z[i] += u(eng);
    s.wrap();
    for (auto* v : {&s.vx, &s.vy, &s.vz}) v->assign(s.size(), 0.0);  // no dissipative force
  }
};

// Soft DPD energy U = Σ_pairs ½ a_ij r_c (1 − r/r_c)² (Groot & Warren 1997), written here independently of
// the engine's pair loop, plus the bonded energies.
double patch_energy(const Patch& p, const System& s) {
  const auto& L = s.box.L;
  double u = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double dx = min_image(s.x[j] - s.x[i], L[0], L[0] / 2), dy = min_image(s.y[j] - s.y[i], L[1], L[1] / 2),
                   dz = min_image(s.z[j] - s.z[i], L[2], L[2] / 2);
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      if (r < p.cfg.rc) u += 0.5 * p.cfg.a[3 * s.type[i] + s.type[j]] * p.cfg.rc * (1 - r / p.cfg.rc) * (1 - r / p.cfg.rc);
    }
  const BondedSums b = BondedForces{p.cfg.bond, p.cfg.bend}.measure(s, p.st.topology);
  return u + b.energy_bond + b.energy_bend;
}

// Engine pair forces (no noise, zero velocities: conservative only) plus bonded forces.
ForceSums patch_forces(const Patch& p, System& s) {
  WaterConfig w;
  w.pairs = PairMode::all;
  w.threads = 1;
  w.noise_override = NoiseOverride::none;
  auto pair = make_pair_forces(w, bilayer_kernel(p.cfg, p.cfg.dt), s.size());
  Taps taps;
  ForceSums f = pair->compute(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()}, 1, false, false, false, taps);
  const BondedSums b = BondedForces{p.cfg.bond, p.cfg.bend}.add(s, p.st.topology);
  for (int a = 0; a < 3; ++a) f.virial_cons[a] += b.virial_bond[a] + b.virial_bend[a];
  return f;
}

TEST(BilayerModel, TotalForceIsMinusEnergyGradient) {
  Patch p;
  System s = p.st.system;
  patch_forces(p, s);
  const double h = 1e-6;
  System q = p.st.system;
  for (std::size_t i = 0; i < q.size(); i += 3)
    for (int a = 0; a < 3; ++a) {
      auto& c = a == 0 ? q.x : a == 1 ? q.y : q.z;
      const double keep = c[i];
      c[i] = keep + h;
      const double up = patch_energy(p, q);
      c[i] = keep - h;
      const double down = patch_energy(p, q);
      c[i] = keep;
      const double fd = -(up - down) / (2 * h);
      EXPECT_NEAR((a == 0 ? s.fx : a == 1 ? s.fy : s.fz)[i], fd, 1e-5 * std::max(1.0, std::abs(fd)))
          << "bead " << i << " axis " << a;
    }
}

// The virial the pressure uses, W_α = Σ r_iα F_iα over pair and bonded forces, against −dU/dε under
// r_α → (1+ε) r_α, L_α → (1+ε) L_α: what P_αα = (K_α + W_α)/V needs to be the mechanical pressure.
TEST(BilayerModel, TotalVirialIsMinusEnergyDerivativeUnderBoxStretch) {
  Patch p;
  System s = p.st.system;
  const ForceSums f = patch_forces(p, s);
  for (int a = 0; a < 3; ++a) {
    auto stretched = [&](double eps) {
      System q = p.st.system;
      q.box.L[a] *= 1 + eps;
      auto& c = a == 0 ? q.x : a == 1 ? q.y : q.z;
      for (auto& v : c) v *= 1 + eps;
      return q;
    };
    const double h = 1e-6;
    const double fd = -(patch_energy(p, stretched(h)) - patch_energy(p, stretched(-h))) / (2 * h);
    EXPECT_NEAR(f.virial_cons[a], fd, 1e-5 * std::max(1.0, std::abs(fd))) << "axis " << a;
  }
}

}  // namespace
}  // namespace dpdrng::dpd::test_bilayer_model
