#pragma once
// The particle state: structure-of-arrays so the pair loop streams, a periodic orthorhombic box (cubic for
// water, but the bilayer scene will want Lz ≠ Lx), bead types for a_ij by type pair, and image counters so
// that unwrapped positions (for the MSD) survive wrapping. Mass is 1 throughout.
#include <array>
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/team.hpp"

namespace dpdrng::dpd {

struct Box {
  std::array<double, 3> L{1, 1, 1};
  double volume() const { return L[0] * L[1] * L[2]; }
};

// Minimum image of one component, for |d| < 1.5 L (both positions wrapped into [0, L) give |d| < L): d − L
// above half, d + L below −half, d itself otherwise. The shift is picked by selects and always subtracted, so
// the loops over it have no control flow and vectorise with AVX2 blends as well as AVX-512 masks; the result is
// bit for bit the branchy one's: d − (−L) rounds exactly as d + L, and d − 0 is d (−0 included).
// Not round(): that would touch d inside the box.
inline double min_image(double d, double L, double half) {
  const double up = d > half ? L : 0.0;
  const double shift = d < -half ? -L : up;
  return d - shift;
}

// Member t of a team of nt's contiguous share [lo, hi) of n beads. The integrator and the cell sort split the
// beads the same way, so a thread mostly reads back what it wrote itself.
struct Share {
  std::size_t lo, hi;
};
inline Share team_share(std::size_t n, std::size_t t, std::size_t nt) { return {n * t / nt, n * (t + 1) / nt}; }

struct System {
  Box box;
  std::vector<double> x, y, z;     // wrapped into [0, L)
  std::vector<double> vx, vy, vz;
  std::vector<double> fx, fy, fz;
  std::vector<std::int32_t> ix, iy, iz;  // periodic images crossed: unwrapped = x + ix·Lx
  std::vector<std::uint8_t> type;        // index into the a_ij matrix

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n);
  // Wraps every position (or beads [lo, hi): each independent of the others) into [0, L) and counts the
  // images crossed.
  void wrap();
  void wrap(std::size_t lo, std::size_t hi);
  std::array<double, 3> momentum() const;
  double kinetic_twice() const;  // Σ m v² (fixed summation order)
};

// Uniform random positions (soft DPD beads need no lattice) and Maxwell–Boltzmann velocities at kT with the
// total momentum removed, all from one std::mt19937_64 seeded with `seed`: the same start for every generator.
System make_fluid(std::size_t n, const Box& box, double kT, std::uint64_t seed);

}  // namespace dpdrng::dpd
