#pragma once
// Saru (S. Worley 2008; Afshar, Schmid, Pishevar & Worley, Comput. Phys. Commun. 184 (2013) 1119), the generator
// HOOMD-blue up to v2 used for its DPD pair noise (hoomd/Saru.h, EvaluatorPairDPDThermo.h). Written here from
// the published definition, not copied: a 64-bit state (x, y) seeded by hashing one to three 32-bit words, then
// advanced by a 32-bit LCG on x and an offset Weyl sequence of prime period 3666320093 on y; each step outputs
// a 32-bit mix of both. It has no round parameter.
//
// Our blocks: one 64-bit word = (u2 << 32) | u1, u1 and u2 the first two 32-bit outputs after seeding, so that
// to_unit() sees 53 bits of output (HOOMD's d() took 32 output bits plus 20 low LCG bits, which its own
// comment calls less random) and Box–Muller's two 32-bit halves are two whole outputs.
#include <array>
#include <bit>
#include <cstdint>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

namespace saru_detail {
inline constexpr std::uint32_t kLcgA = 0x4beb5d59u, kLcgC = 0x2600e1f7u;        // full-period LCG mod 2^32
inline constexpr std::uint32_t kWeylPeriod = 0xda879addu;                      // the prime 3666320093
inline constexpr std::uint32_t kWeylOffset = 0x8009d14bu;

// C++20 defines >> of a negative int as arithmetic; Saru's mixing relies on that sign fill.
constexpr std::uint32_t sar(std::uint32_t v, int n) { return static_cast<std::uint32_t>(static_cast<std::int32_t>(v) >> n); }

struct State {
  std::uint32_t x, y;
};

// The common tail of the two- and three-word seedings: two mixed words become the LCG state x and the Weyl
// state y (31 bits of the mix, offset by Saru's constant).
constexpr State finish_seed(std::uint32_t s1, std::uint32_t s2) {
  std::uint32_t x = 0x79dedea3u * (s1 ^ sar(s1, 14));
  std::uint32_t y = (x + s2) ^ sar(x, 8);
  x = x + y * (y ^ 0xdddf97f5u);
  return {x, 0xABCB96F7u + (y >> 1)};
}

constexpr State seed2(std::uint32_t s1, std::uint32_t s2) {
  s2 += s1 << 16;
  s1 += s2 << 11;
  s2 += sar(s1, 7);
  s1 ^= sar(s2, 3);
  s2 *= 0xA5366B4Du;
  s2 ^= s2 >> 10;
  s2 ^= sar(s2, 19);
  s1 += s2 ^ 0x6d2d4e11u;
  return finish_seed(s1, s2);
}

constexpr State seed3(std::uint32_t s1, std::uint32_t s2, std::uint32_t s3) {
  s3 ^= (s1 << 7) ^ (s2 >> 6);
  s2 += (s1 >> 4) ^ (s3 >> 15);
  s1 ^= (s2 << 9) + (s3 << 8);
  s3 ^= 0xA5366B4Du * ((s2 >> 11) ^ (s1 << 1));
  s2 += 0x72BE1579u * ((s1 << 4) ^ (s3 >> 16));
  s1 ^= 0x3F38A6EDu * ((s3 >> 5) ^ sar(s2, 22));
  s2 += s1 * s3;
  s1 += s3 ^ (s2 >> 2);
  s2 ^= sar(s2, 17);
  return finish_seed(s1, s2);
}

// One step: LCG, then Weyl (adding the offset, and the period back when y's top bit says it would leave the
// range: a branch-free modular add), then the output mix.
constexpr std::uint32_t next(State& s) {
  s.x = kLcgA * s.x + kLcgC;
  s.y = s.y + kWeylOffset + (sar(s.y, 31) & kWeylPeriod);
  const std::uint32_t v = (s.x ^ (s.x >> 26)) + s.y;
  return (v ^ (v >> 20)) * 0x6957f5a7u;
}

constexpr std::uint64_t two_outputs(State s) {
  const std::uint32_t u1 = next(s);
  const std::uint32_t u2 = next(s);
  return join32(u2, u1);
}
}  // namespace saru_detail

struct Saru {
  static constexpr const char* kName = "saru";
  static constexpr int kWords = 1;
  using Block = std::array<std::uint64_t, kWords>;

  TeaKey key = kPaperTeaKey;

  // Counter mode, as HOOMD seeded per-thread microstreams: call i seeds with the two 32-bit halves of the
  // 64-bit counter start + i (low word first) and returns that microstream's first two outputs. The key is unused.
  constexpr Block stream(std::uint64_t start, std::uint64_t i) const {
    const std::uint64_t c = start + i;
    return {saru_detail::two_outputs(saru_detail::seed2(lo32(c), hi32(c)))};
  }
  // The paper's distance seeding: the halves of dx's bits, with key[0] in the third seed (HOOMD's user-seed slot).
  Block distance(double dx, double, double) const {
    const std::uint64_t b = std::bit_cast<std::uint64_t>(dx);
    return {saru_detail::two_outputs(saru_detail::seed3(lo32(b), hi32(b), key[0]))};
  }
  // HOOMD-blue v2's DPD seeding: Saru(min(tag_i, tag_j), max(tag_i, tag_j), seed + timestep) in 32-bit words.
  constexpr Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    const std::uint32_t lo = i < j ? i : j, hi = i < j ? j : i;
    return {saru_detail::two_outputs(saru_detail::seed3(lo, hi, lo32(seed + step)))};
  }
};

template <>
struct FamilyTraits<Family::saru> {
  template <int>
  using Gen = Saru;
  using CompiledRounds = Rounds<>;
  static constexpr GeneratorInfo kInfo{
      .name = "saru",
      .family = Family::saru,
      .safe_rounds = "fixed, no round parameter; its author reports the stream passes BigCrush (Afshar et al. 2013)",
      .description = "Saru (Worley 2008), HOOMD-blue v2's DPD noise: 1-3 seed words hashed to (LCG, Weyl) state, "
                     "2 outputs per word",
      .takes_key = false};
};

}  // namespace dpdrng::rng
