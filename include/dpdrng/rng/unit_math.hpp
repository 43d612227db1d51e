#pragma once
// log and cos for Box–Muller, written as plain branch-free scalar code so that one definition serves both the
// scalar draw (the DPD pair loop) and the batched fill_noise(), where GCC auto-vectorises the same function at
// -O3 -march=native. Why not libm: glibc's log and cos are scalar calls a loop cannot vectorise, and they
// would make a pair's ζ depend on which path computed it. Here every operation is an IEEE-754 basic
// operation or a fused multiply-add (std::fma: correctly rounded in software or hardware), and the build has
// -ffp-contract=off, so a value is bit for bit the same in a scalar register or in any SIMD lane.
//
// Branch-free matters twice: selects instead of branches let the vectoriser if-convert, and every product
// is computed unconditionally (with -ftrapping-math GCC will not speculate a conditional one).
// Accuracy against MPFR: tests/rng/test_unit_math.cpp.
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace dpdrng::rng::math {

namespace detail {
// Taylor coefficient (−1)^k a^(2k+p) / (2k+p)!, accumulated in long double and rounded once.
constexpr double taylor_coeff(long double a, int k, int p) {
  long double c = 1.0L;
  for (int n = 1; n <= 2 * k + p; ++n) c *= a / n;
  return static_cast<double>(k % 2 ? -c : c);
}
inline constexpr long double kTwoPi = 2.0L * std::numbers::pi_v<long double>;
struct SinTwoPiTaylor {  // sin(2πr) = Σ c_k r^(2k+1)
  double c[12];
  constexpr SinTwoPiTaylor() : c{} {
    for (int k = 0; k < 12; ++k) c[k] = taylor_coeff(kTwoPi, k, 1);
  }
};
inline constexpr SinTwoPiTaylor kSin{};
inline constexpr double kTwoPiHi = static_cast<double>(kTwoPi);
inline constexpr double kTwoPiLo = static_cast<double>(kTwoPi - kTwoPiHi);

// The atanh series 2·Σ s^(2k+1)/(2k+1) beyond its first term, as R(z) = Σ_{k≥1} 2/(2k+1) z^k with z = s².
inline double atanh_tail(double z) {
  double r = 2.0 / 21;
#pragma GCC unroll 16
  for (int k = 9; k >= 1; --k) r = std::fma(r, z, 2.0 / (2 * k + 1));
  return r * z;
}
}  // namespace detail

// log(u) for normal u in (0, 1] (Box–Muller's u1 ≥ 2^-53). The fdlibm reduction: u = 2^k·m with m in [√½, √2)
// (subtracting √½'s bits from u's moves the exponent boundary to √½: integer operations only), f = m − 1 (exact,
// Sterbenz), s = f/(2+f), log(1+f) = 2·atanh(s) = f − (f²/2 − s·(f²/2 + R(s²))); |s| ≤ 0.1716, so ten series
// terms leave a truncation below 1e-17 relative. ln 2 = ln2_hi + ln2_lo with ln2_hi's low bits zero, so k·ln2_hi
// is exact. k becomes a double through the 1.5·2^52 trick (an integer add and one exact subtraction), which
// vectorises on any SIMD level, unlike a 64-bit integer conversion.
inline double log_unit(double u) {
  constexpr double ln2_hi = 0x1.62e42feep-1, ln2_lo = 0x1.a39ef35793c76p-33;
  constexpr std::uint64_t kSqrtHalf = 0x3fe6a09e667f3bcdull;  // the bits of √½
  const std::uint64_t ix = std::bit_cast<std::uint64_t>(u) - kSqrtHalf;
  const std::int64_t k = static_cast<std::int64_t>(ix) >> 52;  // arithmetic shift: k ≤ 0 for u < √½
  const double m = std::bit_cast<double>((ix & 0x000fffffffffffffull) + kSqrtHalf);
  const double e = std::bit_cast<double>(static_cast<std::uint64_t>(k) + 0x4338000000000000ull) - 0x1.8p52;
  const double f = m - 1.0;
  const double s = f / (2.0 + f);
  const double r = detail::atanh_tail(s * s);
  const double hfsq = 0.5 * f * f;
  return e * ln2_hi - ((hfsq - std::fma(s, hfsq + r, e * ln2_lo)) - f);
}

// cos(2π·u) for u in [0, 1]. cos(2πu) = sin(2πv) with v = 1/4 − u, and the reduction works on v, not on 2πv, so
// it is exact: q = 2v rounded to the nearest integer (adding 1.5·2^52 leaves q in the low mantissa bits),
// r = v − q/2 in [−1/4, 1/4] (exact: u, v and r lie on u's grid), sin(2πv) = (−1)^q·sin(2πr). One odd Taylor
// polynomial, sin(2πr) = 2πr + r³·P(r²) to the 23rd power (the next term is below 2e-18 at |2πr| = π/2),
// costs fewer operations than a sine and a cosine on an octant, and stays relative-accurate next to cos's zeros
// (r → 0). Its leading term uses 2π as a double-double with fused products. The sign flip is an XOR.
inline double cos_2pi(double u) {
  const double v = 0.25 - u;
  const double shifted = std::fma(v, 2.0, 0x1.8p52);
  const std::uint64_t q = std::bit_cast<std::uint64_t>(shifted);
  const double r = std::fma(shifted - 0x1.8p52, -0.5, v);
  const double r2 = r * r;
  double p = detail::kSin.c[11];
#pragma GCC unroll 16
  for (int k = 10; k >= 1; --k) p = std::fma(p, r2, detail::kSin.c[k]);
  const double y = std::fma(r, detail::kTwoPiHi, std::fma(r * r2, p, r * detail::kTwoPiLo));
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(y) ^ (q << 63));
}

}  // namespace dpdrng::rng::math
