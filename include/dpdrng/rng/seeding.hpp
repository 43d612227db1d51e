#pragma once
// Seeding strategies: how a pair (and a step) becomes a generator input, and the per-pair noise policy
// the DPD pair loop inlines.
#include <cstdint>
#include <string_view>
#include <utility>

#include "dpdrng/rng/distribution.hpp"

namespace dpdrng::rng {

enum class Seeding {
  distance,   // IEEE-754 bits of r_ij = r_j - r_i (i < j): the paper's choice
  pair_step,  // (min(i,j), max(i,j), step, user seed): HOOMD's choice
  counter,    // a 64-bit counter: standalone streams only
};

Seeding parse_seeding(std::string_view name);  // throws InputError
std::string_view to_string(Seeding s);

// What a pair loop knows about a pair at a step. d is r_j - r_i (minimum image).
struct PairInput {
  std::uint32_t i, j;
  double dx, dy, dz;
  std::uint64_t step;
};

// Canonical order (i < j, d = r_j - r_i) makes every seeding symmetric: ζ_ij = ζ_ji by construction.
constexpr PairInput canonical(PairInput p) {
  if (p.i > p.j) {
    std::swap(p.i, p.j);
    p.dx = -p.dx;
    p.dy = -p.dy;
    p.dz = -p.dz;
  }
  return p;
}

template <Seeding S, class G>
inline auto pair_block(const G& gen, const PairInput& p, std::uint64_t seed) {
  static_assert(S != Seeding::counter, "counter seeding makes streams, not pair noise");
  if constexpr (S == Seeding::distance)
    return gen.distance(p.dx, p.dy, p.dz);
  else
    return gen.pair_step(p.i, p.j, p.step, seed);
}

// The input of a pair's second block (the blocks feed): the separation's components rotated, (dy, dz, dx), which
// distance seeding hashes (32TEA, SplitMix64 and Saru hash the first component: dy; 64TEA, Philox and Threefry
// the first two: (dy, dz)), and the step complemented, a stream that pair-step seeding never reaches from the
// first block (steps stay below 2^63). The map commutes with canonical() (it rotates and negates alike and keeps
// i, j), so ζ_ij = ζ_ji still holds; it reads only the separation both owners of a boundary pair already agree
// on (or round to one grid alike), so the decomposition repairs carry over unchanged.
constexpr PairInput second_input(PairInput p) { return {p.i, p.j, p.dy, p.dz, p.dx, ~p.step}; }

// ζ for one pair and step: generator ∘ seeding ∘ distribution resolved at compile time, the feed at run time.
template <class G, Seeding S, Distribution D>
struct PairNoise {
  using Generator = G;
  static constexpr Seeding kSeeding = S;
  static constexpr Distribution kDistribution = D;

  G gen;
  std::uint64_t seed = 0;
  Feed feed = Feed::halves;

  // p must already be canonical (the pair loop visits i < j); call canonical() otherwise.
  double operator()(const PairInput& p) const {
    const auto a = pair_block<S>(gen, p, seed);
    if (feed != Feed::blocks) return draw<D>(feed, a, a);
    return draw<D>(feed, a, pair_block<S>(gen, second_input(p), seed));
  }
};

}  // namespace dpdrng::rng
