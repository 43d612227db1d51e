#pragma once
// From hash output words to the numbers the tests and the DPD random force use.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "dpdrng/rng/simd.hpp"
#include "dpdrng/rng/unit_math.hpp"
#include "dpdrng/rng/unit_math_f32.hpp"

namespace dpdrng::rng {

// [0,1) with the top 53 bits: every double is exact and 1.0 can never come out.
constexpr double to_unit(std::uint64_t w) { return static_cast<double>(w >> 11) * 0x1p-53; }
// (0,1]: the same 53 bits shifted by one ulp, so that log(u) is finite.
constexpr double to_unit_open0(std::uint64_t w) { return static_cast<double>((w >> 11) + 1) * 0x1p-53; }

enum class Distribution { gauss, uniform };

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

// The defect generator's ζ (defect.hpp), declared here so that every qualified rng::draw<D> finds it.
struct DefectBlock;
template <Distribution D>
double draw(const DefectBlock& b);

Distribution parse_distribution(std::string_view name);  // throws InputError
std::string_view to_string(Distribution d);

}  // namespace dpdrng::rng
