#pragma once
// Fixed-width lane types for the batched paths, and the two transcendental functions Box–Muller needs, written
// so that one call works on a whole register of lanes.
//
// Why GNU vector extensions (GCC, Clang): they keep a TEA state in registers across all rounds, which the
// auto-vectoriser does not guarantee, and they compile on any target (split into narrower registers where a
// 512-bit one is missing). Why our own log and cos: libm's are scalar, and glibc's libmvec is reachable only
// under -ffast-math. Both functions below stay within a few ulp of a correctly rounded result (tests/rng/
// test_simd_math.cpp measures it), so the batched Gaussians differ from the scalar box_muller() by a few ulp.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#if defined(__AVX512F__) || defined(__AVX__)
#include <immintrin.h>
#endif

namespace dpdrng::rng::simd {

using u32x16 = std::uint32_t __attribute__((vector_size(64)));
using u64x8 = std::uint64_t __attribute__((vector_size(64)));
using i64x8 = std::int64_t __attribute__((vector_size(64)));
using f64x8 = double __attribute__((vector_size(64)));

template <class V, class T>
inline V load(const T* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V, class T>
inline void store(T* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}

// libm's sqrt may set errno, which stops GCC from vectorising it unless -fno-math-errno; the intrinsic cannot.
// Both are correctly rounded, so the lanes equal std::sqrt bit for bit.
inline f64x8 sqrt(f64x8 x) {
#if defined(__AVX512F__)
  // The masked form with every lane selected: the unmasked one trips GCC 12's -Wmaybe-uninitialized.
  const auto v = reinterpret_cast<__m512d>(x);
  return reinterpret_cast<f64x8>(_mm512_mask_sqrt_pd(v, static_cast<__mmask8>(0xff), v));
#elif defined(__AVX__)
  __m256d lo, hi;
  std::memcpy(&lo, &x, 32);
  std::memcpy(&hi, reinterpret_cast<const char*>(&x) + 32, 32);
  lo = _mm256_sqrt_pd(lo);
  hi = _mm256_sqrt_pd(hi);
  std::memcpy(&x, &lo, 32);
  std::memcpy(reinterpret_cast<char*>(&x) + 32, &hi, 32);
  return x;
#else
  for (int i = 0; i < 8; ++i) x[i] = std::sqrt(x[i]);
  return x;
#endif
}

// a·b + c rounded once. Hardware FMA where the target has it, std::fma lane by lane otherwise: both are
// correctly rounded, so results do not depend on the build's SIMD level (ISO mode forbids implicit contraction).
inline f64x8 fma(f64x8 a, f64x8 b, f64x8 c) {
#if defined(__AVX512F__)
  return reinterpret_cast<f64x8>(_mm512_fmadd_pd(reinterpret_cast<__m512d>(a), reinterpret_cast<__m512d>(b),
                                                 reinterpret_cast<__m512d>(c)));
#else
  for (int i = 0; i < 8; ++i) a[i] = std::fma(a[i], b[i], c[i]);
  return a;
#endif
}

namespace detail {
// Taylor coefficients c_k = (-1)^k a^(2k+p) / (2k+p)!, computed in long double and rounded once.
constexpr double taylor_coeff(long double a, int k, int p) {
  long double c = 1.0L;
  for (int n = 1; n <= 2 * k + p; ++n) c *= a / n;
  return static_cast<double>(k % 2 ? -c : c);
}
inline constexpr long double kTwoPi = 2.0L * std::numbers::pi_v<long double>;
template <int P>
struct TaylorTable {
  double c[9];
  constexpr TaylorTable() : c{} {
    for (int k = 0; k < 9; ++k) c[k] = taylor_coeff(kTwoPi, k, P);
  }
};
inline constexpr TaylorTable<0> kCos2Pi{};
inline constexpr double kTwoPiHi = static_cast<double>(kTwoPi);
inline constexpr double kTwoPiLo = static_cast<double>(kTwoPi - kTwoPiHi);
inline constexpr TaylorTable<1> kSin2Pi{};
}  // namespace detail

// log(u) for normal u in (0, 1] (Box–Muller's u1 is at least 2^-53). The fdlibm reduction: u = 2^e·m with
// m in [√½, √2), f = m−1, s = f/(2+f), log(1+f) = 2·atanh(s) = f − (f²/2 − s·(f²/2 + R(s²))), R the odd
// atanh series beyond its first term; |s| ≤ 0.1716, so ten terms leave a truncation below 1e-17 relative.
// ln 2 is split into a high part with trailing zero bits (e·ln2_hi is exact) and the remainder.
inline f64x8 log_unit(f64x8 u) {
  constexpr double ln2_hi = 0x1.62e42feep-1, ln2_lo = 0x1.a39ef35793c76p-33;
  const u64x8 bits = reinterpret_cast<u64x8>(u);
  i64x8 e = reinterpret_cast<i64x8>(bits >> 52) - 1023;
  f64x8 m = reinterpret_cast<f64x8>((bits & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
  const i64x8 big = m > std::numbers::sqrt2;
  m = big ? m * 0.5 : m;
  e = big ? e + 1 : e;
  const f64x8 f = m - 1.0;  // exact: m and 1 are within a factor 2 (Sterbenz)
  const f64x8 s = f / (2.0 + f);
  const f64x8 z = s * s;
  f64x8 r = 2.0 / 21 + f64x8{};
  for (int k = 9; k >= 1; --k) r = simd::fma(r, z, 2.0 / (2 * k + 1) + f64x8{});
  r = r * z;
  const f64x8 hfsq = 0.5 * f * f;
  const f64x8 dk = __builtin_convertvector(e, f64x8);
  return dk * ln2_hi - ((hfsq - (s * (hfsq + r) + dk * ln2_lo)) - f);
}

// cos(2π·u) for u in [0, 1]. The reduction is exact because it works on u, not on 2πu: q = nearest quarter,
// r = u − q/4 in [−1/8, 1/8] (exact: u lies on a 2^-53 grid), then cos(2πu) = ±cos(2πr) or ±sin(2πr) by q's
// quadrant. Taylor series in r to the 16th (cos) and 17th (sin) power of 2πr: the next terms are below 1e-17.
inline f64x8 cos_2pi(f64x8 u) {
  const i64x8 q = __builtin_convertvector(u * 4.0 + 0.5, i64x8);
  const f64x8 r = u - __builtin_convertvector(q, f64x8) * 0.25;
  const f64x8 r2 = r * r;
  f64x8 c = detail::kCos2Pi.c[8] + f64x8{};
  f64x8 s = detail::kSin2Pi.c[8] + f64x8{};
  for (int k = 7; k >= 1; --k) {
    c = simd::fma(c, r2, detail::kCos2Pi.c[k] + f64x8{});
    s = simd::fma(s, r2, detail::kSin2Pi.c[k] + f64x8{});
  }
  c = simd::fma(c, r2, 1.0 + f64x8{});
  // sin's leading term 2π·r carries the result: 2π as a double-double and fused products round it only once.
  s = simd::fma(r, detail::kTwoPiHi + f64x8{}, simd::fma(r, detail::kTwoPiLo + f64x8{}, (r * r2) * s));
  const f64x8 v = (q & 1) != 0 ? s : c;
  return ((q + 1) & 2) != 0 ? -v : v;  // quadrants 1 and 2 are negative: −sin, −cos
}

}  // namespace dpdrng::rng::simd
