#pragma once
// Box–Muller's log and cos in single precision, straight from 32-bit words, for the generators whose block is one
// 64-bit word (32TEA, SplitMix64, Saru, MT19937): u1 and u2 are its two 32-bit halves, so they carry 32 bits.
//
// Why single precision: a Gaussian made of two 32-bit uniforms needs no 53-bit arithmetic, and on the batched
// path float lanes are twice as many per register and float division and sqrt cost far less than double ones;
// the double kernels (unit_math.hpp) made the batched Gaussian 5.6× the uniform at 32TEA(1), these bring it under
// 3× (`dpdrng bench rng`). Why from the integer word and not from a float u: a float cannot hold a 32-bit u,
// and rounding u near 1 would quantise small radii (−2·log u ≈ 2(1 − u)) and cos's zeros. Both reductions below
// are exact integer operations; the only rounding before the polynomials is the int32 → float conversion of
// the reduced argument, a relative error ≤ 2^-24 that the result keeps as a relative error.
//
// Like unit_math.hpp: branch-free, IEEE basic operations and std::fma only, -ffp-contract=off, so the scalar
// pair loop and GCC's vectorised fill_noise() loops give the same bits. Accuracy: tests/rng/test_unit_math.cpp.
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace dpdrng::rng::math {

namespace detail_f32 {
inline constexpr long double kTwoPi = 2.0L * std::numbers::pi_v<long double>;
// Taylor coefficient (−1)^k (2π)^(2k+1) / (2k+1)!, rounded once to float.
constexpr float sin_coeff(int k) {
  long double c = 1.0L;
  for (int n = 1; n <= 2 * k + 1; ++n) c *= kTwoPi / n;
  return static_cast<float>(k % 2 ? -c : c);
}
inline constexpr float kTwoPiHi = static_cast<float>(kTwoPi);
inline constexpr float kTwoPiLo = static_cast<float>(kTwoPi - kTwoPiHi);
}  // namespace detail_f32

// log(u1) for u1 = (x + 1)·2^-32 in [2^-32, 1]. fdlibm's reduction done on the integer v = x + 1: j with
// v = 2^j·m, m ≈ in [√½, √2), taken from the exponent of float(v) minus √½'s bits (float rounding may put m a
// hair outside; the series has margin). f = m − 1 = (v − 2^j)·2^-j, where v − 2^j is exact in int32 arithmetic
// modulo 2^32: it lies in (−0.3·2^j, 0.42·2^j), and v = 2^32 wraps to 0 with 2^32 to 0, so x = 2^32 − 1 gives
// f = 0 and log 1 = 0 exactly. Then log(1 + f) = 2·atanh(s), s = f/(2 + f), |s| ≤ 0.172: four series terms leave
// a truncation below 1e-9 relative, and log u1 = (j − 32)·ln 2 + log(1 + f) with ln 2 split so that
// (j − 32)·ln2_hi is exact.
inline float log_u32(std::uint32_t x) {
  constexpr float ln2_hi = 0x1.62e3p-1f, ln2_lo = 0x1.2fefa2p-17f;  // ln2_hi: 17 significant bits
  constexpr std::uint32_t kSqrtHalf = 0x3f3504f3u;                   // the bits of √½ as a float
  const std::uint32_t v = x + 1u;
  const float fv = static_cast<float>(x) + 1.0f;
  const std::int32_t j = static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(fv) - kSqrtHalf) >> 23;
  const std::uint32_t pow2 = j < 32 ? 1u << (j & 31) : 0u;
  const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(127 - j) << 23);  // 2^-j, exact
  const float f = static_cast<float>(static_cast<std::int32_t>(v - pow2)) * scale;
  const float s = f / (2.0f + f);
  const float z = s * s;
  const float r = z * std::fma(std::fma(std::fma(2.0f / 9, z, 2.0f / 7), z, 2.0f / 5), z, 2.0f / 3);
  const float hfsq = 0.5f * f * f;
  const float k = static_cast<float>(j - 32);
  return k * ln2_hi - ((hfsq - std::fma(s, hfsq + r, k * ln2_lo)) - f);
}

// cos(2π·x·2^-32) = sin(2π·v·2^-32) with v = 2^30 − x, reduced in uint32 arithmetic (sin has period 2^32 in v,
// so wrap-around is harmless): t = v + 2^30 = 2^31 − x, q = t's top bit, r = (t mod 2^31) − 2^30 in
// [−2^30, 2^30), and sin(2πv·2^-32) = (−1)^q·sin(2πr·2^-32). r → float is exact below 2^24, so the result stays
// relative-accurate next to cos's zeros. The odd Taylor polynomial to the 13th power covers |2πr·2^-32| ≤ π/2
// (next term below 4e-9); its leading term uses 2π as hi + lo with fused products. The sign flip is an XOR.
inline float cos_2pi_u32(std::uint32_t x) {
  const std::uint32_t t = 0x80000000u - x;
  const std::uint32_t q = t >> 31;
  const float r = static_cast<float>(static_cast<std::int32_t>(t & 0x7fffffffu) - 0x40000000) * 0x1p-32f;
  const float r2 = r * r;
  float p = detail_f32::sin_coeff(6);
#pragma GCC unroll 8
  for (int k = 5; k >= 1; --k) p = std::fma(p, r2, detail_f32::sin_coeff(k));
  const float y = std::fma(r, detail_f32::kTwoPiHi, std::fma(r * r2, p, r * detail_f32::kTwoPiLo));
  return std::bit_cast<float>(std::bit_cast<std::uint32_t>(y) ^ (q << 31));
}

}  // namespace dpdrng::rng::math
