#pragma once
// Bonded interactions of the membrane scene as small value types: a harmonic bond and a cosine bending term
// on the angle between successive bond vectors (Grafmüller, Shillcock & Lipowsky, Biophys. J. 96, 2658 (2009)).
// Both act on minimum-image separations, so a lipid may straddle the periodic boundary.
//
// Virial convention (the engine's, pair_forces.hpp): W_α = Σ_i r_iα F_iα written with relative vectors, which
// for a translation-invariant term equals −L_α ∂U/∂L_α under an affine stretch of the box along α. The
// pressure is then P_αα = (Σ m v_α² + W_α^pair + W_α^bond + W_α^bend) / V.
#include <array>
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

// U = ½ k (r − r0)². With d = r_j − r_i the force on j is s·d, on i −s·d.
struct HarmonicBond {
  double k = 128.0;
  double r0 = 0.5;

  double energy(double r) const { return 0.5 * k * (r - r0) * (r - r0); }
  // s such that F_j = s·d; r = |d| > 0.
  double scale(double r) const { return -k * (r - r0) / r; }
};

// U = k (1 − cos φ), φ the angle between b1 = r_2 − r_1 and b2 = r_3 − r_2 (zero for a straight chain).
struct CosineBend {
  double k = 15.0;

  struct Forces {
    std::array<double, 3> f1, f3;  // the force on bead 2 is −(f1 + f3)
    double energy;
  };
  double energy(const double b1[3], const double b2[3]) const;
  // Zero forces if either bond has zero length (the angle is undefined and the term has no gradient there).
  Forces forces(const double b1[3], const double b2[3]) const;
};

// Bead indices of the bonded terms; every index refers to System arrays.
struct Topology {
  std::vector<std::array<std::uint32_t, 2>> bonds;
  std::vector<std::array<std::uint32_t, 3>> angles;
};

struct BondedSums {
  double energy_bond = 0, energy_bend = 0;
  std::array<double, 3> virial_bond{}, virial_bend{};  // W_α as in the header comment
  double max_bond = 0;                                  // longest bond (stability guard)
};

struct BondedForces {
  HarmonicBond bond{};
  CosineBend bend{};

  // Adds the bonded forces to s.f (does not clear it) and returns energies and virials. Serial, in topology
  // order, so the sums are deterministic; a few thousand terms cost little beside the pair loop.
  BondedSums add(System& s, const Topology& t) const;
  // Energies and virials only (the tests' reference and the energy of a configuration).
  BondedSums measure(const System& s, const Topology& t) const;
};

}  // namespace dpdrng::dpd
