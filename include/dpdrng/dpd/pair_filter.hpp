#pragma once
// The candidate filters of the pair loop. Cells mode: a cell's candidates, gathered from its runs of cells
// into one list, pass a SIMD vector at a time (separations, r²) and the pairs inside r_c are appended,
// compacted in order, to the output arrays: no per-candidate stores, no branch per candidate, one compress
// (AVX-512) or table permute (AVX2) per vector; cells whose stencil cannot wrap skip min_image. All pairs: a
// prefilter (on a 16-bit grid, in single precision where the grid cannot serve) passes every candidate inside r_c
// and a few beyond, which the exact filter then tests; without SIMD, a bit mask per 64 candidates, the few
// kept recomputed. Every lane does the scalar code's IEEE operations in the scalar order (min_image, then
// (a·a + b·b) + c·c; contraction is off), so the kept pairs and their separations are the scalar loop's bits
// on any of the paths, and the native and portable builds agree.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <algorithm>

#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
#include <immintrin.h>
#endif

#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd::pair_filter {

// Where the kept pairs go: the arrays must have room for kSlack entries past the last pair kept, since a
// vector's stores are whole-width.
struct Out {
  double *dx, *dy, *dz, *r2;
  std::uint32_t* j;
};

struct Centre {
  double x, y, z;
  double Lx, Ly, Lz, hx, hy, hz;  // box edges and their halves (min_image's arguments)
  double rc2;
};

inline Centre centre(const Box& box, double x, double y, double z, double rc2) {
  return {x, y, z, box.L[0], box.L[1], box.L[2], box.L[0] / 2, box.L[1] / 2, box.L[2] / 2, rc2};
}

#if defined(__AVX512F__) && defined(__AVX512VL__)

inline constexpr std::size_t kSlack = 8;

namespace isa {
using V = __m512d;
inline constexpr int kW = 8;
inline V set1(double v) { return _mm512_set1_pd(v); }
inline V load(const double* p) { return _mm512_loadu_pd(p); }
inline V load_part(const double* p, int n) { return _mm512_maskz_loadu_pd(__mmask8((1u << n) - 1), p); }
inline void store(double* p, V v) { _mm512_storeu_pd(p, v); }
// base, base + 1, … in kW 32-bit lanes.
inline void put_iota(std::uint32_t* out, std::uint32_t base) {
  const __m256i j = _mm256_add_epi32(_mm256_set1_epi32(int(base)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), j);
}
// d − (d < −h ? −L : d > h ? L : 0), as min_image.
inline V min_image(V d, V L, V h, V neg_L, V neg_h) {
  const V up = _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(d, h, _CMP_GT_OQ), L);
  const V shift = _mm512_mask_mov_pd(up, _mm512_cmp_pd_mask(d, neg_h, _CMP_LT_OQ), neg_L);
  return _mm512_sub_pd(d, shift);
}
inline unsigned inside(V r2, V rc2) { return _mm512_cmp_pd_mask(r2, rc2, _CMP_LT_OQ); }
inline void put(double* out, V v, unsigned m) { _mm512_storeu_pd(out, _mm512_maskz_compress_pd(__mmask8(m), v)); }
// The partners id[0, kW) whose bits are set in m, to the front, in order.
inline void put_ids(std::uint32_t* out, const std::uint32_t* id, unsigned m) {
  const __m256i j = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(id));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_maskz_compress_epi32(__mmask8(m), j));
}
}  // namespace isa

#elif defined(__AVX2__)

inline constexpr std::size_t kSlack = 4;

namespace isa {
using V = __m256d;
inline constexpr int kW = 4;
inline V set1(double v) { return _mm256_set1_pd(v); }
inline V load(const double* p) { return _mm256_loadu_pd(p); }
inline V load_part(const double* p, int n) {
  alignas(32) static constexpr std::int64_t kLanes[8] = {-1, -1, -1, -1, 0, 0, 0, 0};
  return _mm256_maskload_pd(p, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kLanes + 4 - n)));
}
inline void store(double* p, V v) { _mm256_storeu_pd(p, v); }
inline void put_iota(std::uint32_t* out, std::uint32_t base) {
  const __m128i j = _mm_add_epi32(_mm_set1_epi32(int(base)), _mm_setr_epi32(0, 1, 2, 3));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), j);
}
// d − (d > h ? L : 0) + (−d > h ? L : 0): min_image's shift, exactly (the two tests exclude each other), from
// L and h alone: with 16 registers, the negated constants would be spilled and reloaded every vector.
inline V min_image(V d, V L, V h, V, V) {
  const V neg_d = _mm256_xor_pd(d, _mm256_set1_pd(-0.0));
  const V up = _mm256_and_pd(_mm256_cmp_pd(d, h, _CMP_GT_OQ), L);
  const V down = _mm256_and_pd(_mm256_cmp_pd(neg_d, h, _CMP_GT_OQ), L);
  return _mm256_sub_pd(d, _mm256_sub_pd(up, down));
}
inline unsigned inside(V r2, V rc2) { return unsigned(_mm256_movemask_pd(_mm256_cmp_pd(r2, rc2, _CMP_LT_OQ))); }
// For each 4-bit mask, the 32-bit lanes that move its set doubles to the front, in order.
struct Table {
  alignas(32) std::int32_t lanes[16][8];
  constexpr Table() : lanes{} {
    for (int m = 0; m < 16; ++m) {
      int k = 0;
      for (int t = 0; t < 4; ++t)
        if (m >> t & 1) lanes[m][2 * k] = 2 * t, lanes[m][2 * k + 1] = 2 * t + 1, ++k;
    }
  }
};
inline constexpr Table kTable{};
inline __m256i lanes(unsigned m) { return _mm256_load_si256(reinterpret_cast<const __m256i*>(kTable.lanes[m])); }
inline void put(double* out, V v, unsigned m) {
  _mm256_storeu_pd(out, _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(v), lanes(m))));
}
inline void put_ids(std::uint32_t* out, const std::uint32_t* id, unsigned m) {
  // The table's halved lanes pick the kept ids into the even 32-bit lanes (the table's unused lanes are 0, so
  // only the four loaded ids are ever read), which the second permute packs.
  const __m256i ids = _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(id)));
  const __m256i picked = _mm256_permutevar8x32_epi32(ids, _mm256_srli_epi32(lanes(m), 1));
  const __m256i even = _mm256_permutevar8x32_epi32(picked, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm256_castsi256_si128(even));
}
}  // namespace isa

#else

inline constexpr std::size_t kSlack = 0;

#endif

#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
// The centre and the box in every lane, and the minimum-image separations of a vector of candidates from it.
struct Lanes {
  isa::V xi, yi, zi, rc2, Lx, Ly, Lz, hx, hy, hz, nLx, nLy, nLz, nhx, nhy, nhz;
  explicit Lanes(const Centre& c)
      : xi(isa::set1(c.x)), yi(isa::set1(c.y)), zi(isa::set1(c.z)), rc2(isa::set1(c.rc2)), Lx(isa::set1(c.Lx)),
        Ly(isa::set1(c.Ly)), Lz(isa::set1(c.Lz)), hx(isa::set1(c.hx)), hy(isa::set1(c.hy)), hz(isa::set1(c.hz)),
        nLx(isa::set1(-c.Lx)), nLy(isa::set1(-c.Ly)), nLz(isa::set1(-c.Lz)), nhx(isa::set1(-c.hx)),
        nhy(isa::set1(-c.hy)), nhz(isa::set1(-c.hz)) {}
  struct Separation {
    isa::V a, b, d, r2;
  };
  template <bool Wrap = true>
  Separation separation(isa::V px, isa::V py, isa::V pz) const {
    if constexpr (!Wrap) {
      const isa::V a = px - xi, b = py - yi, d = pz - zi;
      return {a, b, d, a * a + b * b + d * d};
    }
    const isa::V a = isa::min_image(px - xi, Lx, hx, nLx, nhx), b = isa::min_image(py - yi, Ly, hy, nLy, nhy),
                 d = isa::min_image(pz - zi, Lz, hz, nLz, nhz);
    return {a, b, d, a * a + b * b + d * d};
  }
};
#endif

// Candidates gathered from several ranges into one list (a cell's own beads and its forward neighbours'):
// positions and partner ids, contiguous, readable kSlack entries past the last (vector loads are whole-width;
// the lanes past the end are masked out, and should hold finite values so that they cost no slow path).
struct Listed {
  const double *x, *y, *z;
  const std::uint32_t* id;
};

// Appends the candidates k in [lo, hi) of (x, y, z) to a list being gathered (positions, and ids k) at
// index `t`; returns the new length. Whole vectors: x, y and z must be readable kSlack entries past hi and the
// list writable as far past its new end (the next range's copy overwrites the excess).
inline std::size_t list_range(const double* x, const double* y, const double* z, std::uint32_t lo, std::uint32_t hi,
                              double* lx, double* ly, double* lz, std::uint32_t* id, std::size_t t) {
#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
  using namespace isa;
  for (std::uint32_t k = lo; k < hi; k += kW) {
    const std::size_t at = t + (k - lo);
    store(lx + at, load(x + k)), store(ly + at, load(y + k)), store(lz + at, load(z + k));
    put_iota(id + at, k);
  }
  return t + (hi - lo);
#else
  for (std::uint32_t k = lo; k < hi; ++k, ++t) lx[t] = x[k], ly[t] = y[k], lz[t] = z[k], id[t] = k;
  return t;
#endif
}

// Appends the listed candidates t in [lo, hi) with r² < rc2 (NaN fails), in order, as pairs with partner
// id[t] to out from index `kept` on; returns the new count. One run of whole vectors however many ranges the
// list was gathered from. Wrap = false skips min_image: only for a list whose every separation from the
// centre lies within half a box edge in each dimension, where min_image returns its argument, so the kept
// pairs and their bits are the same.
template <bool Wrap>
inline std::size_t append_listed(const Listed& l, std::uint32_t lo, std::uint32_t hi, const Centre& c,
                                 const Out& out, std::size_t kept) {
#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
  using namespace isa;
  const Lanes at(c);
  for (std::uint32_t k = lo; k < hi; k += kW) {
    const unsigned lanes = hi - k >= std::uint32_t(kW) ? (1u << kW) - 1 : (1u << (hi - k)) - 1;
    const Lanes::Separation s = at.separation<Wrap>(load(l.x + k), load(l.y + k), load(l.z + k));
    const unsigned m = inside(s.r2, at.rc2) & lanes;
    put(out.dx + kept, s.a, m), put(out.dy + kept, s.b, m), put(out.dz + kept, s.d, m), put(out.r2 + kept, s.r2, m);
    put_ids(out.j + kept, l.id + k, m);
    kept += std::size_t(std::popcount(m));
  }
  return kept;
#else
  for (std::uint32_t k = lo; k < hi; ++k) {
    double a = l.x[k] - c.x, b = l.y[k] - c.y, d = l.z[k] - c.z;
    if constexpr (Wrap) a = min_image(a, c.Lx, c.hx), b = min_image(b, c.Ly, c.hy), d = min_image(d, c.Lz, c.hz);
    const double r2 = a * a + b * b + d * d;
    if (!(r2 < c.rc2)) continue;
    out.dx[kept] = a, out.dy[kept] = b, out.dz[kept] = d, out.r2[kept] = r2, out.j[kept] = l.id[k];
    ++kept;
  }
  return kept;
#endif
}

// The candidates k in [lo, hi) (at most 64) with r² < rc2 (NaN fails), as a bit mask (bit k − lo). Nothing is
// stored per candidate: where few are kept (~1 in 20 along an all-pairs row), the caller recomputes the kept
// ones' separations (kept_pair), which are the bits the vector lanes had.
inline std::uint64_t inside_mask(const double* x, const double* y, const double* z, std::uint32_t lo,
                                 std::uint32_t hi, const Centre& c) {
#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
  using namespace isa;
  const Lanes at(c);
  auto one = [&](V px, V py, V pz) { return std::uint64_t(inside(at.separation(px, py, pz).r2, at.rc2)); };
  std::uint64_t mask = 0;
  std::uint32_t k = lo;
  for (; k + kW <= hi; k += kW) mask |= one(load(x + k), load(y + k), load(z + k)) << (k - lo);
  if (k < hi) {
    const int n = int(hi - k);
    mask |= (one(load_part(x + k, n), load_part(y + k, n), load_part(z + k, n)) & ((1u << n) - 1)) << (k - lo);
  }
  return mask;
#else
  std::uint64_t mask = 0;
  for (std::uint32_t k = lo; k < hi; ++k) {
    const double a = min_image(x[k] - c.x, c.Lx, c.hx), b = min_image(y[k] - c.y, c.Ly, c.hy),
                 d = min_image(z[k] - c.z, c.Lz, c.hz);
    mask |= std::uint64_t(a * a + b * b + d * d < c.rc2) << (k - lo);
  }
  return mask;
#endif
}

// Candidate k's separation and r², as every path of the filter computes them, to out at index `at`.
inline void kept_pair(const double* x, const double* y, const double* z, std::uint32_t k, const Centre& c,
                      const Out& out, std::size_t at) {
  const double a = min_image(x[k] - c.x, c.Lx, c.hx), b = min_image(y[k] - c.y, c.Ly, c.hy),
               d = min_image(z[k] - c.z, c.Lz, c.hz);
  out.dx[at] = a, out.dy[at] = b, out.dz[at] = d, out.r2[at] = a * a + b * b + d * d, out.j[at] = k;
}

// Appends the candidates k in [lo, hi) with r² < rc2, in order, to out from index `kept` on, 64 candidates
// to a mask; returns the new count. Needs no slack.
inline std::size_t append_sparse(const double* x, const double* y, const double* z, std::uint32_t lo,
                                 std::uint32_t hi, const Centre& c, const Out& out, std::size_t kept) {
  for (std::uint32_t base = lo; base < hi; base += 64) {
    for (std::uint64_t m = inside_mask(x, y, z, base, std::min(hi, base + 64), c); m != 0; m &= m - 1)
      kept_pair(x, y, z, base + std::uint32_t(std::countr_zero(m)), c, out, kept++);
  }
  return kept;
}

// The all-pairs prefilter: positions rounded to float, r² in single precision (twice the lanes of a double
// vector) against r_c² raised by a bound on every rounding involved, so that it passes every candidate inside
// r_c and a few just outside; those it passes are recomputed in double precision (kept_pair) and kept on the
// exact test, so the kept pairs and their bits are the exact filter's.
struct Rounded {
  const float *x, *y, *z;  // positions rounded to float, readable kSlackF entries past the last
  float cx, cy, cz;        // the centre, rounded
  float Lx, Ly, Lz;        // the box edges, rounded
  float threshold;         // rounded_threshold
};

inline constexpr std::size_t kSlackF = 16;

// A float threshold above the single-precision r² of every pair with exact r² < rc2, for positions and box
// edges of magnitude at most `extent`. Rounding a coordinate to float moves it by at most u·extent (u = 2⁻²⁴);
// with the float difference, the float image shift and its subtraction, a component of the separation is off
// by less than e = 16 u·max(extent, r_c), its magnitude included where the two precisions pick opposite
// images (then both are within e of half the edge). So r_float < r + √3·e, and r² in float adds a relative
// 5u: (r_c + 2e)²(1 + 8u), rounded up to a float, bounds it.
inline float rounded_threshold(double rc2, double extent) {
  const double u = 0x1p-24, rc = std::sqrt(rc2);
  const double e = 16.0 * u * std::max(extent, rc);
  const double t = (rc + 2.0 * e) * (rc + 2.0 * e) * (1.0 + 8.0 * u);
  return std::nextafter(static_cast<float>(t), INFINITY);
}

#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
namespace isa_f {
#if defined(__AVX512F__) && defined(__AVX512VL__)
using V = __m512;
inline constexpr int kW = 16;
inline V set1(float v) { return _mm512_set1_ps(v); }
inline V load(const float* p) { return _mm512_loadu_ps(p); }
// |min_image(d)| as min(|d|, L − |d|): L − |d| rounds as d ∓ L does (the same magnitudes), and the smaller of
// the two is the image min_image picks (h = L/2 exactly), so r² is min_image's to the bit in four operations
// and no mask; the prefilter needs the lengths only.
inline V image_length(V d, V L) {
  const V a = _mm512_abs_ps(d);
  // The masked minimum over all lanes: GCC 12's unmasked one reads an undefined source (and warns).
  return _mm512_mask_min_ps(a, __mmask16(0xffff), a, _mm512_sub_ps(L, a));
}
inline unsigned inside(V r2, V t) { return _mm512_cmp_ps_mask(r2, t, _CMP_LT_OQ); }
// base + t for each lane t set in m, to the front, in order.
inline void put_ids(std::uint32_t* out, std::uint32_t base, unsigned m) {
  const __m512i j = _mm512_add_epi32(_mm512_set1_epi32(int(base)),
                                     _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  _mm512_storeu_si512(out, _mm512_maskz_compress_epi32(__mmask16(m), j));
}
#else
using V = __m256;
inline constexpr int kW = 8;
inline V set1(float v) { return _mm256_set1_ps(v); }
inline V load(const float* p) { return _mm256_loadu_ps(p); }
// |min_image(d)|, as the AVX-512 path has it.
inline V image_length(V d, V L) {
  const V a = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), d);
  return _mm256_min_ps(a, _mm256_sub_ps(L, a));
}
inline unsigned inside(V r2, V t) { return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(r2, t, _CMP_LT_OQ))); }
// For each 8-bit mask, the lanes whose bits are set, to the front, in order.
struct Table {
  alignas(32) std::int32_t lanes[256][8];
  constexpr Table() : lanes{} {
    for (int m = 0; m < 256; ++m) {
      int k = 0;
      for (int t = 0; t < 8; ++t)
        if (m >> t & 1) lanes[m][k++] = t;
    }
  }
};
inline constexpr Table kTable{};
inline void put_ids(std::uint32_t* out, std::uint32_t base, unsigned m) {
  const __m256i lanes = _mm256_load_si256(reinterpret_cast<const __m256i*>(kTable.lanes[m]));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_add_epi32(_mm256_set1_epi32(int(base)), lanes));
}
#endif
}  // namespace isa_f

// The candidates k in [lo, hi) the single-precision test passes, in order, to id; returns their number. id
// must have room for hi − lo entries and kSlackF more.
inline std::uint32_t maybe_ids(const Rounded& f, std::uint32_t lo, std::uint32_t hi, std::uint32_t* id) {
  using namespace isa_f;
  const V xi = set1(f.cx), yi = set1(f.cy), zi = set1(f.cz), t = set1(f.threshold);
  const V Lx = set1(f.Lx), Ly = set1(f.Ly), Lz = set1(f.Lz);
  std::uint32_t n = 0;
  for (std::uint32_t k = lo; k < hi; k += kW) {
    const V a = image_length(load(f.x + k) - xi, Lx), b = image_length(load(f.y + k) - yi, Ly),
            d = image_length(load(f.z + k) - zi, Lz);
    const unsigned lanes = hi - k >= std::uint32_t(kW) ? (1u << kW) - 1 : (1u << (hi - k)) - 1;
    const unsigned m = inside(a * a + b * b + d * d, t) & lanes;
    put_ids(id + n, k, m);
    n += std::uint32_t(std::popcount(m));
  }
  return n;
}
#endif

// Room for a list being gathered: positions and ids (Listed), writable kSlackF entries past the candidates.
struct ListRoom {
  double *x, *y, *z;
  std::uint32_t* id;
};

// The candidates a prefilter passed (t of them, ids in room.id, each below the row's end): their positions
// gathered into `room` and filtered exactly a vector at a time (append_listed with min_image).
inline std::size_t append_passed(const double* x, const double* y, const double* z, std::uint32_t t,
                                 const Centre& c, const ListRoom& room, const Out& out, std::size_t kept) {
  for (std::uint32_t q = 0; q < t; ++q) {
    const std::uint32_t k = room.id[q];
    room.x[q] = x[k], room.y[q] = y[k], room.z[q] = z[k];
  }
  for (std::uint32_t e = t; e < t + kSlack; ++e) room.x[e] = room.y[e] = room.z[e] = 0.0;
  return append_listed<true>(Listed{room.x, room.y, room.z, room.id}, 0, t, c, out, kept);
}

// append_sparse with the single-precision prefilter (Rounded): the candidates it passes are gathered into
// `room` and filtered exactly a vector at a time (append_listed with min_image): the same pairs, separations
// and order.
inline std::size_t append_rounded(const double* x, const double* y, const double* z, const Rounded& f,
                                  std::uint32_t lo, std::uint32_t hi, const Centre& c, const ListRoom& room,
                                  const Out& out, std::size_t kept) {
#if defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
  return append_passed(x, y, z, maybe_ids(f, lo, hi, room.id), c, room, out, kept);
#else
  (void)f, (void)room;
  return append_sparse(x, y, z, lo, hi, c, out, kept);
#endif
}

// The all-pairs prefilter on a 16-bit grid: each coordinate as round(x·S) mod 2¹⁶ with S = 2¹⁶/L along its
// axis, so that a difference taken in 16 bits wraps to the minimum image by itself, and 32 candidates go per
// vector (16 with AVX2). Along an axis the grid difference u (the wrap picks the smallest of the images) is
// within 1 of d·S, d the minimum-image separation: two roundings of at most ½ each, and of S·x and of L·S =
// 2¹⁶ far less while |x·S| < 2⁴⁰. So a pair inside r_c has Σ u² < (r_c·S_max + 2)², S_max the largest scale;
// ⌊u²/2¹⁶⌋ (the high half of the 32-bit square) is at most u²/2¹⁶, and the three of them, each at most 2¹⁴,
// sum in an unsigned 16-bit lane. A candidate whose sum reaches grid_threshold cannot be inside r_c; those
// below it (inside, and a few just outside) are recomputed exactly, so the kept pairs and their bits are the
// exact filter's.
struct Grid16 {
  const std::uint16_t *x, *y, *z;  // grid coordinates, readable kSlackG entries past the last
  std::uint16_t cx, cy, cz;        // the centre's
  std::uint16_t threshold;         // grid_threshold
};

inline constexpr std::size_t kSlackG = 32;

// Whether the grid serves the box and cutoff rc with coordinates of magnitude at most `extent`: it
// must resolve r_c into at least 2¹² steps (a box at most 16 r_c across) for the prefilter to pass few
// candidates beyond r_c, and keep |x·S| below 2⁴⁰ for the bound above; and the build must have AVX2.
inline bool grid_serves(const Box& box, double rc, double extent) {
#if defined(__AVX512BW__) && defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
  const double smax = 65536.0 / std::min({box.L[0], box.L[1], box.L[2]});
  return rc * smax >= 4096.0 && rc * smax <= 32768.0 && extent * smax < 0x1p40;
#else
  (void)box, (void)rc, (void)extent;
  return false;
#endif
}

// round(x·scale) mod 2¹⁶ (scale = 2¹⁶/L); 0 for a coordinate that is not finite, whose pairs the exact test
// rejects anyway. The reduction is exact: below 2⁴⁰ the product's multiples of 2¹⁶ are whole doubles.
inline std::uint16_t to_grid(double x, double scale) {
  const double v = x * scale, r = v - 65536.0 * std::floor(v / 65536.0);
  if (!(r >= 0.0 && r < 65536.0)) return 0;
  return static_cast<std::uint16_t>(static_cast<std::uint32_t>(std::floor(r + 0.5)) & 0xffffu);
}

// The grid prefilter's bound for cutoff rc with the largest scale smax: ⌊(rc·smax + 2)²/2¹⁶⌋ + 2, one above
// what Σ⌊u²/2¹⁶⌋ can reach inside r_c with room for the rounding of this computation.
inline std::uint16_t grid_threshold(double rc, double smax) {
  const double b = (rc * smax + 2.0) * (rc * smax + 2.0) / 65536.0;
  return static_cast<std::uint16_t>(std::min(65535.0, std::floor(b) + 2.0));
}

#if defined(__AVX512BW__) && defined(__AVX512F__) && defined(__AVX512VL__)
// The candidates k in [lo, hi) the grid test passes, in order, to id; returns their number. id must have room
// for hi − lo entries and kSlackF more.
inline std::uint32_t grid_ids(const Grid16& g, std::uint32_t lo, std::uint32_t hi, std::uint32_t* id) {
  const __m512i xi = _mm512_set1_epi16(static_cast<short>(g.cx)), yi = _mm512_set1_epi16(static_cast<short>(g.cy)),
                zi = _mm512_set1_epi16(static_cast<short>(g.cz)),
                t = _mm512_set1_epi16(static_cast<short>(g.threshold));
  const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  auto term = [](const std::uint16_t* p, __m512i c) {
    const __m512i u = _mm512_abs_epi16(_mm512_sub_epi16(_mm512_loadu_si512(p), c));  // −2¹⁵ reads as 2¹⁵
    return _mm512_mulhi_epu16(u, u);
  };
  std::uint32_t n = 0;
  for (std::uint32_t k = lo; k < hi; k += 32) {
    const __m512i sum = _mm512_add_epi16(_mm512_add_epi16(term(g.x + k, xi), term(g.y + k, yi)), term(g.z + k, zi));
    std::uint32_t m = _mm512_cmplt_epu16_mask(sum, t);
    if (hi - k < 32) m &= (1u << (hi - k)) - 1;
    for (std::uint32_t half = 0; half < 2; ++half) {
      const auto h = static_cast<__mmask16>(m >> (16 * half));
      const __m512i j = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(k + 16 * half)), iota);
      _mm512_storeu_si512(id + n, _mm512_maskz_compress_epi32(h, j));
      n += std::uint32_t(std::popcount(unsigned(h)));
    }
  }
  return n;
}
#elif defined(__AVX2__)
// As above, 16 candidates a vector: sum < threshold as min(sum, threshold − 1) == sum (AVX2 compares 16-bit
// lanes as signed only, and a sum reaches 3·2¹⁴), the lanes' results packed to bytes for one mask.
inline std::uint32_t grid_ids(const Grid16& g, std::uint32_t lo, std::uint32_t hi, std::uint32_t* id) {
  const __m256i xi = _mm256_set1_epi16(static_cast<short>(g.cx)), yi = _mm256_set1_epi16(static_cast<short>(g.cy)),
                zi = _mm256_set1_epi16(static_cast<short>(g.cz)),
                below = _mm256_set1_epi16(static_cast<short>(g.threshold - 1));
  auto term = [](const std::uint16_t* p, __m256i c) {
    const __m256i d = _mm256_sub_epi16(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)), c);
    const __m256i u = _mm256_abs_epi16(d);  // −2¹⁵ reads as 2¹⁵
    return _mm256_mulhi_epu16(u, u);
  };
  std::uint32_t n = 0;
  for (std::uint32_t k = lo; k < hi; k += 16) {
    const __m256i sum = _mm256_add_epi16(_mm256_add_epi16(term(g.x + k, xi), term(g.y + k, yi)), term(g.z + k, zi));
    const __m256i in = _mm256_cmpeq_epi16(_mm256_min_epu16(sum, below), sum);
    const __m128i bytes = _mm_packs_epi16(_mm256_castsi256_si128(in), _mm256_extracti128_si256(in, 1));
    unsigned m = unsigned(_mm_movemask_epi8(bytes));
    if (hi - k < 16) m &= (1u << (hi - k)) - 1;
    isa_f::put_ids(id + n, k, m & 0xffu);
    n += std::uint32_t(std::popcount(m & 0xffu));
    isa_f::put_ids(id + n, k + 8, m >> 8);
    n += std::uint32_t(std::popcount(m >> 8));
  }
  return n;
}
#endif

// append_sparse with the grid prefilter (Grid16; only where grid_serves): the same pairs, separations and
// order.
inline std::size_t append_grid(const double* x, const double* y, const double* z, const Grid16& g,
                               std::uint32_t lo, std::uint32_t hi, const Centre& c, const ListRoom& room,
                               const Out& out, std::size_t kept) {
#if defined(__AVX512BW__) && defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
  return append_passed(x, y, z, grid_ids(g, lo, hi, room.id), c, room, out, kept);
#else
  (void)g, (void)room;
  return append_sparse(x, y, z, lo, hi, c, out, kept);
#endif
}

}  // namespace dpdrng::dpd::pair_filter
