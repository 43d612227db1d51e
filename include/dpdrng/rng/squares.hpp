#pragma once
// Squares (B. Widynski, "Squares: a fast counter-based RNG", arXiv:2004.06278, 2020): von Neumann's middle-square
// method made counter-based. The counter times a key gives x = y and z = y + key; each round squares x, adds y or z
// alternately and swaps x's 32-bit halves. Four rounds give a 32-bit output (squares32), five a 64-bit one
// (squares64: the fourth round's full 64 bits XOR the fifth's high half). Written here from the published
// definition.
//
// dpdrng's family is squares64: one 64-bit word a call, no round parameter. The key is fixed, not the user's:
// Squares needs a key of the form the author's key generator makes (the paper's section on keys), which an
// arbitrary 128-bit key would not respect. kSquaresKey is the first key of the list published with the author's
// reference code (keys.h); --key is refused.
#include <array>
#include <bit>
#include <cstdint>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

inline constexpr std::uint64_t kSquaresKey = 0xc58efd154ce32f6dull;

namespace squares_detail {
constexpr std::uint64_t swap_halves(std::uint64_t x) { return (x >> 32) | (x << 32); }

// The first three rounds, shared by both widths: the state x before round 4.
constexpr std::uint64_t three_rounds(std::uint64_t y, std::uint64_t z) {
  std::uint64_t x = swap_halves(y * y + y);
  x = swap_halves(x * x + z);
  return swap_halves(x * x + y);
}
}  // namespace squares_detail

constexpr std::uint32_t squares32(std::uint64_t ctr, std::uint64_t key) {
  const std::uint64_t y = ctr * key, z = y + key;
  const std::uint64_t x = squares_detail::three_rounds(y, z);
  return static_cast<std::uint32_t>((x * x + z) >> 32);
}

constexpr std::uint64_t squares64(std::uint64_t ctr, std::uint64_t key) {
  const std::uint64_t y = ctr * key, z = y + key;
  std::uint64_t x = squares_detail::three_rounds(y, z);
  const std::uint64_t t = x * x + z;
  x = squares_detail::swap_halves(t);
  return t ^ ((x * x + y) >> 32);
}

struct Squares64 {
  static constexpr const char* kName = "squares64";
  static constexpr int kWords = 1;
  using Block = std::array<std::uint64_t, kWords>;

  TeaKey key = kPaperTeaKey;  // not read: the key is kSquaresKey

  constexpr Block stream(std::uint64_t start, std::uint64_t i) const { return {squares64(start + i, kSquaresKey)}; }
  // As 32TEA: the IEEE-754 bits of the x component of r_ij = r_j − r_i are the counter.
  Block distance(double dx, double, double) const {
    return {squares64(std::bit_cast<std::uint64_t>(dx), kSquaresKey)};
  }
  // The pair (j:i) is the counter, offset by a Squares hash of the step and by the seed times an odd constant: for
  // one step and seed the pairs' counters are distinct (an XOR with a constant is a bijection), and steps and seeds
  // move the whole set pseudo-randomly.
  constexpr Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    const std::uint64_t offset = squares64(step, kSquaresKey) ^ (seed * 0x9e3779b97f4a7c15ull);
    return {squares64(join32(j, i) ^ offset, kSquaresKey)};
  }
};

template <>
struct FamilyTraits<Family::squares64> {
  template <int>
  using Gen = Squares64;
  using CompiledRounds = Rounds<>;
  static constexpr GeneratorInfo kInfo{
      .name = "squares64",
      .family = Family::squares64,
      .safe_rounds = "fixed at 5 rounds, no round parameter; its author reports that it passes BigCrush and "
                     "PractRand (Widynski 2020)",
      .description = "Squares64 (Widynski 2020): 5 middle-square rounds of counter x key, the author's first "
                     "published key 0xc58efd154ce32f6d; one 64-bit word a call",
      .takes_key = false};
};

}  // namespace dpdrng::rng
