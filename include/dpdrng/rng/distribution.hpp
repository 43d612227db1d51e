#pragma once
// From hash output words to the numbers the tests and the DPD random force use.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "dpdrng/rng/unit_math.hpp"

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

// Box–Muller, cosine branch. The two uniforms: a block of two 64-bit words gives one each at 53-bit resolution
// (64TEA's a and b, Philox's halves); a single 64-bit word (32TEA, SplitMix64, Saru) gives its two 32-bit halves,
// which for 32TEA are the two TEA output words x0' and x1'.
// Split in two so that the batched path (fill_noise) can run the same parts in vectorised loops: radius² =
// −2·log u1 and cos(2π·u2) through math::log_unit and math::cos_2pi, then the correctly rounded sqrt (std::sqrt
// here, the SIMD instruction there), so that a block gives the same ζ, bit for bit, on either path.
struct BoxMullerParts {
  double radius2, cosine;
};
template <std::size_t N>
inline BoxMullerParts box_muller_parts(const std::array<std::uint64_t, N>& b) {
  double u1, u2;
  if constexpr (N >= 2) {
    u1 = to_unit_open0(b[0]);
    u2 = to_unit(b[1]);
  } else {
    u1 = (static_cast<double>(b[0] & 0xffffffffu) + 1.0) * 0x1p-32;
    u2 = static_cast<double>(b[0] >> 32) * 0x1p-32;
  }
  return {-2.0 * math::log_unit(u1), math::cos_2pi(u2)};
}

template <std::size_t N>
inline double box_muller(const std::array<std::uint64_t, N>& b) {
  const BoxMullerParts p = box_muller_parts(b);
  return std::sqrt(p.radius2) * p.cosine;
}

template <Distribution D, std::size_t N>
inline double draw(const std::array<std::uint64_t, N>& b) {
  if constexpr (D == Distribution::gauss)
    return box_muller(b);
  else
    return uniform_unit_variance(b);
}

Distribution parse_distribution(std::string_view name);  // throws InputError
std::string_view to_string(Distribution d);

}  // namespace dpdrng::rng
