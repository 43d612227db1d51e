#pragma once
// From hash output words to the numbers the tests and the DPD random force use.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "dpdrng/rng/inverse_normal.hpp"
#include "dpdrng/rng/simd.hpp"
#include "dpdrng/rng/unit_math.hpp"
#include "dpdrng/rng/unit_math_f32.hpp"

namespace dpdrng::rng {

// [0,1) with the top 53 bits: every double is exact and 1.0 can never come out.
constexpr double to_unit(std::uint64_t w) { return static_cast<double>(w >> 11) * 0x1p-53; }
// (0,1]: the same 53 bits shifted by one ulp, so that log(u) is finite.
constexpr double to_unit_open0(std::uint64_t w) { return static_cast<double>((w >> 11) + 1) * 0x1p-53; }

enum class Distribution { gauss, uniform };

// Which uniforms feed the Gaussian (the uniform distribution always takes one word: halves only).
//  halves:  Box–Muller on one block as below (for a one-word block its two 32-bit halves): the default, and the
//           only feed the paper's text admits for 32TEA, whose one-round halves are dependent (⟨ζ²⟩ ≈ 0.965).
//  blocks:  Box–Muller with u1 from the pair's block and u2 from a second block of the same pair (seeding.hpp,
//           second_input), each the 53 top bits of the block's first word.
//  inverse: one uniform from the block's first word (its top 52 bits, on the odd multiples of 2^-53) through the
//           inverse normal CDF: no pairing at all.
enum class Feed { halves, blocks, inverse };
inline constexpr Feed kFeeds[] = {Feed::halves, Feed::blocks, Feed::inverse};

// Groot & Warren (1997): a uniform variable of unit variance gives the same DPD physics as a Gaussian.
template <std::size_t N>
inline double uniform_unit_variance(const std::array<std::uint64_t, N>& b) {
  return std::numbers::sqrt3 * (2.0 * to_unit(b[0]) - 1.0);
}

// Box–Muller, cosine branch: z = √(−2·log u1)·cos(2π·u2). Which uniforms feed it:
//  - a block of one 64-bit word (32TEA, SplitMix64, Saru, MT19937): its two 32-bit halves, u1 = (low + 1)·2^-32
//    and u2 = high·2^-32 (for 32TEA the two TEA output words x0' and x1'), computed in single precision from the
//    integers (unit_math_f32.hpp): 32-bit uniforms need no more, and the batched path runs twice the lanes;
//  - a block of two or more words (64TEA's a and b, Philox's, Threefry's): one 53-bit uniform from each of the
//    first two words, u1 in (0, 1] and u2 in [0, 1), in double precision (unit_math.hpp).
// Split in parts so that the batched path (fill_noise) can run the same functions in vectorised loops, then the
// correctly rounded sqrt (std::sqrt here, the SIMD instruction there): a block gives the same ζ, bit for bit,
// on either path. The single-precision z is √(radius²) and cos as floats, multiplied in double (exactly).
struct BoxMullerParts {
  double radius2, cosine;
};
struct BoxMullerParts32 {
  float radius2, cosine;
};
inline BoxMullerParts32 box_muller_parts32(std::uint64_t w) {
  return {math::minus_two_log_u32(static_cast<std::uint32_t>(w)), math::cos_2pi_u32(static_cast<std::uint32_t>(w >> 32))};
}
// Sixteen words at once, given as their low and high halves: the same operations lane by lane.
struct BoxMullerParts32x16 {
  simd::f32x16 radius2, cosine;
};
inline BoxMullerParts32x16 box_muller_parts32(simd::u32x16 low, simd::u32x16 high) {
  return {math::minus_two_log_u32(low), math::cos_2pi_u32(high)};
}
template <std::size_t N>
inline BoxMullerParts box_muller_parts(const std::array<std::uint64_t, N>& b) {
  static_assert(N >= 2, "a one-word block goes through box_muller_parts32");
  return {-2.0 * math::log_unit(to_unit_open0(b[0])), math::cos_2pi(to_unit(b[1]))};
}

template <std::size_t N>
inline double box_muller(const std::array<std::uint64_t, N>& b) {
  if constexpr (N == 1) {
    const BoxMullerParts32 p = box_muller_parts32(b[0]);
    return static_cast<double>(std::sqrt(p.radius2)) * static_cast<double>(p.cosine);
  } else {
    const BoxMullerParts p = box_muller_parts(b);
    return std::sqrt(p.radius2) * p.cosine;
  }
}

template <Distribution D, std::size_t N>
inline double draw(const std::array<std::uint64_t, N>& b) {
  if constexpr (D == Distribution::gauss)
    return box_muller(b);
  else
    return uniform_unit_variance(b);
}

// Box–Muller fed by two blocks: u1 = the first word of a in (0, 1], u2 = the first word of b in [0, 1), both
// 53-bit, through the two-word path (double precision).
template <std::size_t N>
inline double box_muller_blocks(const std::array<std::uint64_t, N>& a, const std::array<std::uint64_t, N>& b) {
  return box_muller(std::array<std::uint64_t, 2>{a[0], b[0]});
}

// Φ⁻¹ of the first word's uniform on the odd multiples of 2^-53 (to_unit_mid): never 0 or 1, symmetric about ½.
template <std::size_t N>
inline double inverse_gauss(const std::array<std::uint64_t, N>& b) {
  return inverse_normal(to_unit_mid(b[0]));
}

// ζ from the pair's block a (and, for the blocks feed, its second block b) under a feed chosen at run time.
template <Distribution D, std::size_t N>
inline double draw(Feed f, const std::array<std::uint64_t, N>& a, const std::array<std::uint64_t, N>& b) {
  if constexpr (D == Distribution::uniform) return uniform_unit_variance(a);
  switch (f) {
    case Feed::blocks: return box_muller_blocks(a, b);
    case Feed::inverse: return inverse_gauss(a);
    case Feed::halves: break;
  }
  return box_muller(a);
}

// The defect generator's ζ (defect.hpp), declared here so that every qualified rng::draw<D> finds it.
struct DefectBlock;
template <Distribution D>
double draw(const DefectBlock& b);
template <Distribution D>
double draw(Feed f, const DefectBlock& a, const DefectBlock& b);

Distribution parse_distribution(std::string_view name);  // throws InputError
std::string_view to_string(Distribution d);
Feed parse_feed(std::string_view name);  // throws InputError
std::string_view to_string(Feed f);
// InputError unless the feed applies to the distribution (uniform noise takes halves only).
void check_feed(Distribution d, Feed f);

}  // namespace dpdrng::rng
