#pragma once
// Fixed-width lane types for the batched paths, and a SIMD sqrt.
//
// Why GNU vector extensions (GCC, Clang): they keep a TEA state in registers across all rounds, which the
// auto-vectoriser does not guarantee, and they compile on any target (split into narrower registers where a
// 512-bit one is missing). Box–Muller's log and cos need no such help: they are plain scalar functions
// (unit_math.hpp) that GCC vectorises in fill_noise()'s loops.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__) || defined(__AVX__)
#include <immintrin.h>
#endif

namespace dpdrng::rng::simd {

using u32x16 = std::uint32_t __attribute__((vector_size(64)));
using u64x8 = std::uint64_t __attribute__((vector_size(64)));
using i64x8 = std::int64_t __attribute__((vector_size(64)));
using f64x8 = double __attribute__((vector_size(64)));
using f32x16 = float __attribute__((vector_size(64)));

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

// Sixteen 64-bit words from p as their low and their high 32-bit halves, one register each, and back: the state
// words of a 32-bit hash whose seed or output is one 64-bit word (little-endian lanes).
inline void split_words(const void* p, u32x16& lo, u32x16& hi) {
  static_assert(std::endian::native == std::endian::little, "split_words assumes little-endian words");
  u32x16 a, b;
  std::memcpy(&a, p, sizeof a);
  std::memcpy(&b, static_cast<const char*>(p) + sizeof a, sizeof b);
  lo = __builtin_shufflevector(a, b, 0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  hi = __builtin_shufflevector(a, b, 1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
}
inline void join_words(void* p, const u32x16& lo, const u32x16& hi) {
  const u32x16 a = __builtin_shufflevector(lo, hi, 0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
  const u32x16 b = __builtin_shufflevector(lo, hi, 8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31);
  std::memcpy(p, &a, sizeof a);
  std::memcpy(static_cast<char*>(p) + sizeof a, &b, sizeof b);
}
// Eight two-word outputs (a[l], b[l]) stored pair after pair.
inline void store_pairs(void* p, const u64x8& a, const u64x8& b) {
  const u64x8 x = __builtin_shufflevector(a, b, 0, 8, 1, 9, 2, 10, 3, 11);
  const u64x8 y = __builtin_shufflevector(a, b, 4, 12, 5, 13, 6, 14, 7, 15);
  std::memcpy(p, &x, sizeof x);
  std::memcpy(static_cast<char*>(p) + sizeof x, &y, sizeof y);
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

inline f32x16 sqrt(f32x16 x) {
#if defined(__AVX512F__)
  const auto v = reinterpret_cast<__m512>(x);
  return reinterpret_cast<f32x16>(_mm512_mask_sqrt_ps(v, static_cast<__mmask16>(0xffff), v));
#else
  for (int i = 0; i < 16; ++i) x[i] = std::sqrt(x[i]);
  return x;
#endif
}

}  // namespace dpdrng::rng::simd
