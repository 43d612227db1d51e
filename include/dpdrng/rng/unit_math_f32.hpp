#pragma once
// Box–Muller's log and cos in single precision, straight from 32-bit words, for the generators whose block is one
// 64-bit word (32TEA, SplitMix64, Saru, MT19937): u1 and u2 are its two 32-bit halves, so they carry 32 bits.
//
// Why single precision: a Gaussian made of two 32-bit uniforms needs no 53-bit arithmetic, and on the batched
// path float lanes are twice as many per register and float sqrt costs far less than double; the double kernels
// (unit_math.hpp) made the batched Gaussian 5.6× the uniform at 32TEA(1), these about 3× (`dpdrng bench rng`).
// Why from the integer word and not from a float u: a float cannot hold a 32-bit u, and rounding u near 1 would
// quantise small radii (−2·log u ≈ 2(1 − u)) and cos's zeros. Both reductions below are exact integer operations.
//
// Each kernel is one template written once for a scalar lane (std::uint32_t → float, the DPD pair loop) and for
// 16 lanes (simd::u32x16 → simd::f32x16, the batched loop in stream.cpp): the log reads a 16-entry table, which
// GCC's auto-vectoriser would turn into scalar loads, while a 16-lane register table is one permute. Same source,
// IEEE basic operations and fma only, -ffp-contract=off: the two instantiations give the same bits.
// Accuracy: tests/rng/test_unit_math.cpp.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>

#include "dpdrng/rng/simd.hpp"

namespace dpdrng::rng::math {

namespace detail_f32 {

using i32x16 = std::int32_t __attribute__((vector_size(64)));

template <class U>
struct Lanes;
template <>
struct Lanes<std::uint32_t> {
  using F = float;
  using I = std::int32_t;
};
template <>
struct Lanes<simd::u32x16> {
  using F = simd::f32x16;
  using I = i32x16;
};

inline float to_f32(std::uint32_t x) { return static_cast<float>(x); }
inline float to_f32(std::int32_t x) { return static_cast<float>(x); }
inline simd::f32x16 to_f32(simd::u32x16 x) { return __builtin_convertvector(x, simd::f32x16); }
inline simd::f32x16 to_f32(i32x16 x) { return __builtin_convertvector(x, simd::f32x16); }

inline simd::f32x16 broadcast(simd::f32x16 v) { return v; }
inline simd::f32x16 broadcast(float s) {
  simd::f32x16 v;
  for (int i = 0; i < 16; ++i) v[i] = s;
  return v;
}
// GNU vectors have no fma operator; the lane loop compiles to one vfmadd (checked in the assembly).
template <class A, class B, class C>
inline auto fma(A a, B b, C c) {
  if constexpr (std::is_same_v<A, float> && std::is_same_v<B, float> && std::is_same_v<C, float>) {
    return std::fma(a, b, c);
  } else {
    const simd::f32x16 x = broadcast(a), y = broadcast(b), z = broadcast(c);
    simd::f32x16 r;
    for (int i = 0; i < 16; ++i) r[i] = std::fma(x[i], y[i], z[i]);
    return r;
  }
}

using Table = std::array<float, 16>;
inline float lookup(const Table& t, std::uint32_t i) { return t[i & 15u]; }
// __builtin_shuffle takes the index modulo 16, as the scalar lookup does. Clang (the fuzz build) has no
// run-time shuffle builtin: there the same lookup runs lane by lane.
inline simd::f32x16 lookup(const Table& t, simd::u32x16 i) {
#if defined(__clang__)
  simd::f32x16 r;
  for (int k = 0; k < 16; ++k) r[k] = t[i[k] & 15u];
  return r;
#else
  return __builtin_shuffle(simd::load<simd::f32x16>(t.data()), i);
#endif
}

// Long double helpers for the constexpr tables below (std::log is not constexpr).
constexpr long double log_ld(long double y) {  // 2·atanh((y − 1)/(y + 1)); |s| < 0.2 here, 40 terms is plenty
  const long double s = (y - 1) / (y + 1), s2 = s * s;
  long double sum = 0, p = s;
  for (int k = 0; k < 40; ++k, p *= s2) sum += p / (2 * k + 1);
  return 2 * sum;
}
constexpr long double round_ld(long double x) {
  return x < 0 ? -static_cast<long double>(static_cast<long long>(-x + 0.5L))
               : static_cast<long double>(static_cast<long long>(x + 0.5L));
}

// log u1 = (j − 32)·ln 2 + log m with u1 = v·2^-32, v = x + 1 = 2^j·m. j and the table index k come from the
// bits of float(v) minus those of 45/64: m in [45/64, 90/64), cut in 16 pieces by the top 4 mantissa bits, 1/32
// wide below 1 and 1/16 wide above. Piece k has invc_k ≈ 1/(its centre) with 8 significant bits, exactly 1 for
// the piece holding 1; with c_k = 1/invc_k exactly, log m = log c_k + log1p(r), r = m·invc_k − 1, |r| ≤ 0.0313,
// evaluated with a single rounding:
//  - v = x_hi + (x_lo + 1), the top and bottom 16 bits of x, both exact floats (v = 2^32 included), so
//    r = (x_hi·invc_k·2^-j − 1) + (x_lo + 1)·invc_k·2^-j. The first fma is exact (16 × 8 bits, the difference
//    on a grid no finer than 2^-24 and below 1.5; x_hi = 0 gives −1), the second adds the rest and rounds once.
//    Converting v − 2^j to float instead, as a table-free reduction does, rounds at 2^-24 relative to m − 1 (up
//    to 0.41) and costs up to half an ulp of log u1. float(v) itself is rounded but only picks j and k: a piece's
//    neighbour works as well.
//  - log c_k is split hi + lo with hi a multiple of 2^-17 like ln2_hi, so (j − 32)·ln2_hi + hi is exact; the
//    −32·ln 2 is folded into the table, so j needs no subtraction. At x = 2^32 − 1: j = 32, the piece of 1,
//    r = 0 and both sums cancel exactly, so log 1 = 0; next to it log u1 ≈ r keeps its relative accuracy.
//  - log1p(r) = r + r²·P(r), P of degree 3: weighted minimax (Remez) for the relative error of log1p on
//    r in [−0.0292, 0.0313], coefficients rounded to float; its error is below 2^-31.
inline constexpr float kLn2Hi = 0x1.62e3p-1f, kLn2Lo = 0x1.2fefa2p-17f;  // ln2_hi: 17 significant bits
inline constexpr std::uint32_t kLogPieces = 0x3f340000u;                 // the bits of 45/64 as a float
//  - Box–Muller wants −2·log u1: every constant below is scaled by s = −2 instead (the polynomial's by powers of
//    s so that each intermediate is a power-of-two multiple of the unscaled one), which gives −2·log u1 bit for bit
//    without the multiplication (but +0, not −0, at u1 = 1).
struct LogTable {
  Table invc, logc_hi, logc_lo;
};
template <int kScale>
constexpr LogTable make_log_table() {
  LogTable t{};
  for (std::uint32_t k = 0; k < 16; ++k) {
    const long double lo = std::bit_cast<float>(kLogPieces + (k << 19));
    const long double hi = std::bit_cast<float>(kLogPieces + ((k + 1) << 19));
    const long double centre = (lo + hi) / 2;
    const long double scale = centre > 1 ? 256 : 128;  // 8 significant bits of 1/centre
    const long double invc = lo <= 1 && 1 < hi ? 1.0L : round_ld(scale / centre) / scale;
    const long double logc = -log_ld(invc);
    const long double logc_hi = round_ld(logc * 131072) / 131072;
    t.invc[k] = static_cast<float>(kScale * invc);
    t.logc_hi[k] = static_cast<float>(kScale * (logc_hi - 32 * static_cast<long double>(kLn2Hi)));
    t.logc_lo[k] = static_cast<float>(kScale * (logc - logc_hi - 32 * static_cast<long double>(kLn2Lo)));
  }
  return t;
}
template <int kScale>
inline constexpr LogTable kLogTable = make_log_table<kScale>();

// kScale·log u1, kScale = 1 or −2.
template <int kScale, class U>
[[gnu::always_inline]] inline typename Lanes<U>::F scaled_log_u32(U x) {
  using F = typename Lanes<U>::F;
  constexpr float s = kScale;
  constexpr float p2 = -0x1.fffffep-2f / s, p3 = 0x1.55557p-2f / (s * s), p4 = -0x1.0030aep-2f / (s * s * s),
                  p5 = 0x1.985d4ep-3f / (s * s * s * s);
  const auto& t = kLogTable<kScale>;
  const F x_hi = to_f32(x & 0xffff0000u);
  const F x_lo1 = to_f32(x & 0xffffu) + 1.0f;
  const U bits = std::bit_cast<U>(x_hi + x_lo1) - kLogPieces;
  const U j = bits >> 23;
  const U k = bits >> 19;
  const F invc_scaled = std::bit_cast<F>(std::bit_cast<U>(lookup(t.invc, k)) - (bits & 0xff800000u));  // ·2^-j
  const F r = fma(x_lo1, invc_scaled, fma(x_hi, invc_scaled, -s));
  const F poly = fma(fma(fma(p5, r, p4), r, p3), r, p2);
  const F fj = to_f32(j);
  const F lo = fma(r * r, poly, fma(fj, s * kLn2Lo, lookup(t.logc_lo, k)));
  return fma(fj, s * kLn2Hi, lookup(t.logc_hi, k)) + (r + lo);
}

// cos(2π·x·2^-32) = sin(2π·v·2^-32) with v = 2^30 − x, reduced in uint32 arithmetic (sin has period 2^32 in v,
// so wrap-around is harmless): t = v + 2^30 = 2^31 − x, q = t's top bit, s = (t mod 2^31) − 2^30 in
// [−2^30, 2^30), and sin(2πv·2^-32) = (−1)^q·sin(π/2·r) with r = s·2^-30 in [−1, 1). s → float is exact below
// 2^24, so the result stays relative-accurate next to cos's zeros. The odd polynomial of degree 9 is a weighted
// minimax (Remez) fit of sin(π/2·r)/r in r² for the relative error on [−1, 1] (below 2^-27, where Taylor would need
// degree 13); its leading coefficient is hi + lo with fused products. The sign flip is an XOR.
template <class U>
[[gnu::always_inline]] inline typename Lanes<U>::F cos_2pi_u32(U x) {
  using F = typename Lanes<U>::F;
  using I = typename Lanes<U>::I;
  constexpr float s1_hi = 0x1.921fb6p+0f, s1_lo = -0x1.bf2e0ap-25f, s3 = -0x1.4abbc2p-1f, s5 = 0x1.4668b0p-4f,
                  s7 = -0x1.324ccap-8f, s9 = 0x1.3daff6p-13f;
  const U t = 0x80000000u - x;
  const U q = t >> 31;
  const F r = to_f32(std::bit_cast<I>(t & 0x7fffffffu) - 0x40000000) * 0x1p-30f;
  const F r2 = r * r;
  const F p = fma(fma(fma(s9, r2, s7), r2, s5), r2, s3);
  const F y = fma(r, s1_hi, fma(r * r2, p, r * s1_lo));
  return std::bit_cast<F>(std::bit_cast<U>(y) ^ (q << 31));
}

}  // namespace detail_f32

// log(u1) for u1 = (x + 1)·2^-32 in [2^-32, 1], −2·log(u1) (the bits of −2.0f * log_u32(x), but +0 at u1 = 1),
// and cos(2π·u2) for u2 = x·2^-32: one lane or sixteen.
inline float log_u32(std::uint32_t x) { return detail_f32::scaled_log_u32<1>(x); }
inline simd::f32x16 log_u32(simd::u32x16 x) { return detail_f32::scaled_log_u32<1>(x); }
inline float minus_two_log_u32(std::uint32_t x) { return detail_f32::scaled_log_u32<-2>(x); }
inline simd::f32x16 minus_two_log_u32(simd::u32x16 x) { return detail_f32::scaled_log_u32<-2>(x); }
inline float cos_2pi_u32(std::uint32_t x) { return detail_f32::cos_2pi_u32(x); }
inline simd::f32x16 cos_2pi_u32(simd::u32x16 x) { return detail_f32::cos_2pi_u32(x); }

}  // namespace dpdrng::rng::math
