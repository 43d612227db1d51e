#pragma once
// Two repairs of the paper's distance seeding for spatially decomposed runs, where the two domains that share a
// boundary pair compute its separation from different floating-point expressions ((x_j − L) − x_i on one side,
// x_j − (x_i + L) on the other) that may differ in the last bits (see dpd/decomposition.hpp).
//
//  grid:      the separation rounded to the grid 2^-k before its IEEE-754 bits are hashed. Two separations that
//             differ by a few ulps round to the same grid point unless a grid midpoint lies between them, so the
//             repair is probabilistic: a pair mismatches with probability ≈ |Δd| · 2^k per component. The price
//             is a coarser seed: pairs whose separations share a grid point share their ζ, and the seed's low
//             mantissa bits are zero (which a one-round hash may not hide).
//  canonical: the separation recomputed from the two beads' wrapped coordinates, min_image(x_j − x_i) with
//             i < j, as an undecomposed run computes it. A ghost must then carry its owner's unshifted
//             coordinate besides the shifted one (the shifted one follows from it and the image count, not the
//             other way round: fl(fl(x + L) − L) ≠ x in general). Both sides evaluate one expression on the
//             same operands, so they agree bit for bit, and the numbers are those of the undecomposed run: no
//             cost in randomness, 24 bytes more per ghost.
#include <cmath>

#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::rng {

// Grids finer than 2^-40 would leave ulp-sized differences (≈ 2^-50 for |x| < 8) about a 2^-10 chance of
// straddling a midpoint; grids coarser than 2^-8 would make whole neighbourhoods of pairs share one number.
inline constexpr int kMinGridBits = 8, kMaxGridBits = 40;

// d rounded to the nearest multiple of 2^-k (ties to even). ldexp is exact, so the only rounding is rint's,
// and rint(−x) = −rint(x): the repair is antisymmetric. Adding +0.0 turns −0.0 into +0.0, because the two
// sides of a pair straddling zero would otherwise hash 0x8000… and 0x0000….
inline double round_to_grid(double d, int k) { return std::ldexp(std::rint(std::ldexp(d, k)), -k) + 0.0; }

// True when d lies within `eps` (in grid units) of a rounding midpoint of the 2^-k grid: the pairs whose two
// views could round to different grid points.
inline bool near_grid_midpoint(double d, int k, double eps) {
  const double u = std::ldexp(d, k);
  return std::fabs(std::fabs(u - std::floor(u)) - 0.5) < eps;
}

template <class G>
inline auto grid_block(const G& gen, const PairInput& p, int k) {
  return gen.distance(round_to_grid(p.dx, k), round_to_grid(p.dy, k), round_to_grid(p.dz, k));
}

}  // namespace dpdrng::rng
