// Bonded terms against exact mathematics: forces are minus the gradient of the energies the same types report
// (central finite differences), the virial is minus the derivative of the energy under an affine stretch of
// the box along each axis, and internal forces sum to zero.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dpdrng/dpd/bonded.hpp"

namespace dpdrng::dpd::test_bonded {
namespace {

double total_energy(const BondedForces& bf, const System& s, const Topology& t) {
  const BondedSums b = bf.measure(s, t);
  return b.energy_bond + b.energy_bend;
}

// A short chain with two bonds and one angle per triple, scattered across the periodic boundary so the
// minimum image is exercised.
System chain(std::mt19937_64& eng, int beads, const Box& box) {
  std::uniform_real_distribution<double> u(-0.45, 0.45);
  System s;
  s.box = box;
  s.resize(beads);
  double x = box.L[0] - 0.2, y = 0.1, z = box.L[2] - 0.1;  // starts at a corner: bonds wrap in x and z
  for (int i = 0; i < beads; ++i) {
    s.x[i] = x, s.y[i] = y, s.z[i] = z;
    x += 0.3 + u(eng), y += u(eng), z += 0.2 + u(eng);
  }
  s.wrap();
  return s;
}

Topology chain_topology(int beads) {
  Topology t;
  for (std::uint32_t i = 0; i + 1 < std::uint32_t(beads); ++i) t.bonds.push_back({i, i + 1});
  for (std::uint32_t i = 0; i + 2 < std::uint32_t(beads); ++i) t.angles.push_back({i, i + 1, i + 2});
  return t;
}

void expect_forces_match_gradient(const BondedForces& bf, System s, const Topology& t) {
  System f = s;
  for (auto* v : {&f.fx, &f.fy, &f.fz}) v->assign(s.size(), 0.0);
  bf.add(f, t);
  const double h = 1e-6;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      auto& coord = a == 0 ? s.x : a == 1 ? s.y : s.z;
      const double keep = coord[i];
      coord[i] = keep + h;
      const double up = total_energy(bf, s, t);
      coord[i] = keep - h;
      const double down = total_energy(bf, s, t);
      coord[i] = keep;
      const double fd = -(up - down) / (2 * h);
      const double got = (a == 0 ? f.fx : a == 1 ? f.fy : f.fz)[i];
      EXPECT_NEAR(got, fd, 1e-6 * std::max(1.0, std::abs(fd))) << "bead " << i << " axis " << a;
    }
}

TEST(Bonded, HarmonicBondForceIsMinusGradient) {
  std::mt19937_64 eng(1);
  BondedForces bf;
  bf.bend.k = 0;
  for (int rep = 0; rep < 20; ++rep) expect_forces_match_gradient(bf, chain(eng, 2, Box{{4, 5, 6}}), chain_topology(2));
}

TEST(Bonded, CosineBendForceIsMinusGradient) {
  std::mt19937_64 eng(2);
  BondedForces bf;
  bf.bond.k = 0;
  for (int rep = 0; rep < 20; ++rep) {
    System s = chain(eng, 3, Box{{4, 5, 6}});
    Topology t = chain_topology(3);
    t.bonds.clear();
    expect_forces_match_gradient(bf, s, t);
  }
}

TEST(Bonded, ChainForcesAreMinusGradientAndSumToZero) {
  std::mt19937_64 eng(3);
  const BondedForces bf;  // the H3(T6)2 model's constants: k_bond 128, r0 0.5, k_bend 15
  for (int rep = 0; rep < 10; ++rep) {
    System s = chain(eng, 7, Box{{3, 4, 3.5}});
    const Topology t = chain_topology(7);
    expect_forces_match_gradient(bf, s, t);
    for (auto* v : {&s.fx, &s.fy, &s.fz}) v->assign(s.size(), 0.0);
    bf.add(s, t);
    double sum[3] = {0, 0, 0};
    for (std::size_t i = 0; i < s.size(); ++i) sum[0] += s.fx[i], sum[1] += s.fy[i], sum[2] += s.fz[i];
    for (double v : sum) EXPECT_NEAR(v, 0.0, 1e-11);
  }
}

TEST(Bonded, KnownValues) {
  // A bond stretched to 0.7: U = ½·128·0.2² = 2.56, |F| = 128·0.2 = 25.6 pulling the beads together.
  System s;
  s.box = Box{{5, 5, 5}};
  s.resize(3);
  s.x = {1.0, 1.7, 1.7};
  s.y = {1.0, 1.0, 2.2};  // then a right angle: bending U = 15·(1 − cos 90°) = 15
  s.z = {1.0, 1.0, 1.0};
  Topology t{{{0, 1}}, {{0, 1, 2}}};
  const BondedSums b = BondedForces{}.add(s, t);
  EXPECT_NEAR(b.energy_bond, 2.56, 1e-12);
  EXPECT_NEAR(b.energy_bend, 15.0, 1e-12);
  // Bond: F_1 = −25.6 x̂; bend on bead 2 at a right angle: |F| = k/|b2| along −b1 direction → −15/1.2 x̂.
  EXPECT_NEAR(s.fx[1], -25.6 - 15.0 / 1.2, 1e-12);
  EXPECT_NEAR(b.virial_bond[0], -25.6 * 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(b.max_bond, 0.7);
}

// W_α = −dU/dε for r_α → (1+ε) r_α, L_α → (1+ε) L_α (the engine's virial convention, pair_forces.hpp).
TEST(Bonded, VirialIsMinusEnergyDerivativeUnderBoxStretch) {
  std::mt19937_64 eng(4);
  const BondedForces bf;
  for (int rep = 0; rep < 5; ++rep) {
    const System s = chain(eng, 9, Box{{3, 4, 3.5}});
    const Topology t = chain_topology(9);
    const BondedSums b = bf.measure(s, t);
    for (int a = 0; a < 3; ++a) {
      auto stretched = [&](double eps) {
        System q = s;
        q.box.L[a] *= 1 + eps;
        auto& c = a == 0 ? q.x : a == 1 ? q.y : q.z;
        for (auto& v : c) v *= 1 + eps;
        return q;
      };
      const double h = 1e-6;
      auto fd = [&](auto part) {
        const BondedSums up = bf.measure(stretched(h), t), down = bf.measure(stretched(-h), t);
        return -(part(up) - part(down)) / (2 * h);
      };
      const double wb = fd([](const BondedSums& x) { return x.energy_bond; });
      const double we = fd([](const BondedSums& x) { return x.energy_bend; });
      EXPECT_NEAR(b.virial_bond[a], wb, 1e-5 * std::max(1.0, std::abs(wb))) << "axis " << a;
      EXPECT_NEAR(b.virial_bend[a], we, 1e-5 * std::max(1.0, std::abs(we))) << "axis " << a;
    }
  }
}

}  // namespace
}  // namespace dpdrng::dpd::test_bonded
