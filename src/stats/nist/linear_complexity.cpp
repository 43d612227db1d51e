// Linear complexity test (SP800-22 2.10) with a word-parallel Berlekamp-Massey.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// Berlekamp-Massey on W-word bitsets (W*64 > len). C, B (connection polynomials) and the window T hold bit i at
// word i/64, bit i%64; T holds s_N, s_{N-1}, ..., so the discrepancy is the parity of C & T. Fixed-size
// loops over all W words let the compiler vectorise them; the block's bits are fetched 64 at a time.
template <std::size_t W>
int bm_fixed(const BitSequence& s, std::size_t start, std::size_t len) {
  std::array<std::uint64_t, W> C{}, B{}, T{}, Tmp{};
  C[0] = B[0] = 1;
  long L = 0, m = -1;
  std::uint64_t chunk = 0;
  for (std::size_t N = 0; N < len; ++N) {
    if ((N & 63) == 0) chunk = s.word_at(start + N);
    const std::uint64_t bit = chunk >> 63;
    chunk <<= 1;
    // Only the words that can hold set bits: T has bits 0..N, C degree <= L <= N.
    const std::size_t tw = N / 64 + 1;
    for (std::size_t k = tw - 1; k > 0; --k) T[k] = (T[k] << 1) | (T[k - 1] >> 63);
    T[0] = (T[0] << 1) | bit;
    std::uint64_t acc = 0;
    const std::size_t cw = static_cast<std::size_t>(L) / 64 + 1;
    for (std::size_t k = 0; k < cw; ++k) acc ^= C[k] & T[k];
    if (!(std::popcount(acc) & 1)) continue;
    const bool grow = L <= static_cast<long>(N) / 2;
    if (grow) Tmp = C;
    // C += x^(N-m) B; the result has degree <= N + 1.
    const std::size_t shift = static_cast<std::size_t>(static_cast<long>(N) - m);
    const std::size_t ws = shift / 64, bs = shift % 64;
    const std::size_t top = std::min(W, (N + 1) / 64 + 1);
    if (bs == 0) {
      for (std::size_t k = ws; k < top; ++k) C[k] ^= B[k - ws];
    } else {
      C[ws] ^= B[0] << bs;
      for (std::size_t k = ws + 1; k < top; ++k) C[k] ^= (B[k - ws] << bs) | (B[k - ws - 1] >> (64 - bs));
    }
    if (grow) {
      L = static_cast<long>(N) + 1 - L;
      m = static_cast<long>(N);
      B = Tmp;
    }
  }
  return static_cast<int>(L);
}

// Any length: the same algorithm on heap bitsets.
int bm_generic(const BitSequence& s, std::size_t start, std::size_t len) {
  const std::size_t W = len / 64 + 2;
  std::vector<std::uint64_t> C(W, 0), B(W, 0), T(W, 0), Tmp(W, 0);
  C[0] = B[0] = 1;
  long L = 0, m = -1;
  for (std::size_t N = 0; N < len; ++N) {
    for (std::size_t k = N / 64 + 1; k-- > 1;) T[k] = (T[k] << 1) | (T[k - 1] >> 63);
    T[0] = (T[0] << 1) | static_cast<std::uint64_t>(s[start + N]);
    std::uint64_t acc = 0;
    for (std::size_t k = 0; k <= static_cast<std::size_t>(L) / 64; ++k) acc ^= C[k] & T[k];
    if (!(std::popcount(acc) & 1)) continue;
    const bool grow = L <= static_cast<long>(N) / 2;
    if (grow) Tmp = C;
    const std::size_t shift = static_cast<std::size_t>(static_cast<long>(N) - m);
    const std::size_t ws = shift / 64, bs = shift % 64;
    for (std::size_t k = 0; k + ws < W; ++k) {
      C[k + ws] ^= B[k] << bs;
      if (bs && k + ws + 1 < W) C[k + ws + 1] ^= B[k] >> (64 - bs);
    }
    if (grow) {
      L = static_cast<long>(N) + 1 - L;
      m = static_cast<long>(N);
      std::swap(B, Tmp);
    }
  }
  return static_cast<int>(L);
}

// a[r] bit c <-> a[c] bit r (bits counted from the least significant): swap the off-diagonal halves of every
// block, halving the block size each round.
void transpose64(std::array<std::uint64_t, 64>& a) {
  std::uint64_t mask = 0x00000000FFFFFFFFull;
  for (unsigned j = 32; j != 0; j >>= 1, mask ^= mask << j) {
    for (unsigned k = 0; k < 64; k = ((k | j) + 1) & ~j) {
      const std::uint64_t t = ((a[k] >> j) ^ a[k | j]) & mask;
      a[k] ^= t << j;
      a[k | j] ^= t;
    }
  }
}

// S[M-N] = bit N of every block (block l in bit l), S[0] = 0: reversed, so that the discrepancy reads S and C
// forwards. 64 bits of 64 blocks at a time, as one bit-matrix transpose.
void load_sliced(const BitSequence& s, std::size_t first, std::size_t M, int lanes, std::vector<std::uint64_t>& S) {
  S.assign(M + 1, 0);
  std::array<std::uint64_t, 64> a;
  for (std::size_t N0 = 0; N0 < M; N0 += 64) {
    for (int l = 0; l < 64; ++l)
      a[l] = l < lanes ? s.word_at(first + static_cast<std::size_t>(l) * M + N0) : 0;
    // Word l holds bit N0+b of block l at bit 63-b; after the transpose, word 63-b holds it at bit l.
    transpose64(a);
    const std::size_t cnt = std::min<std::size_t>(64, M - N0);
    for (std::size_t b = 0; b < cnt; ++b) S[M - (N0 + b)] = a[63 - b];
  }
}

// The lanes' register lengths L, and which lanes may lengthen theirs at step N: those with L <= N/2 (unused lanes
// hold L = M, out of the way of the minimum, and never grow). With AVX-512 the 64 lengths are four vectors (AVX2:
// eight): a step's test, update, minimum and maximum are a few instructions each, where a loop over the growing
// lanes (about a quarter of them a step) mispredicts its exit every step.
struct GrowState {
  alignas(64) std::array<std::int32_t, 64> L{};
  int min_L = 0, max_L = 0;

  void reset(std::size_t M, int lanes) {
    for (int l = 0; l < 64; ++l) L[l] = l < lanes ? 0 : static_cast<std::int32_t>(M);
    min_L = max_L = 0;
  }
  // The lanes among `d` that grow at step N; updates L (to N + 1 - L) and the extremes for them.
  std::uint64_t grow(std::uint64_t d, std::size_t N) {
    const auto n = static_cast<std::int32_t>(N);
#if defined(__AVX512F__)
    const __m512i twice_max = _mm512_set1_epi32(n), next = _mm512_set1_epi32(n + 1);
    std::uint64_t g = 0;
    for (int q = 0; q < 4; ++q) {
      const __m512i v = _mm512_load_si512(L.data() + 16 * q);
      g |= std::uint64_t(_mm512_cmple_epi32_mask(_mm512_add_epi32(v, v), twice_max)) << (16 * q);
    }
    g &= d;
    if (!g) return 0;
    __m512i lo = _mm512_set1_epi32(std::numeric_limits<std::int32_t>::max()), hi = _mm512_set1_epi32(max_L);
    for (int q = 0; q < 4; ++q) {
      const auto k = static_cast<__mmask16>(g >> (16 * q));
      __m512i v = _mm512_load_si512(L.data() + 16 * q);
      v = _mm512_mask_sub_epi32(v, k, next, v);
      _mm512_store_si512(L.data() + 16 * q, v);
      // The masked minimum over all lanes: GCC 12's unmasked one reads an undefined source (and warns).
      lo = _mm512_mask_min_epi32(lo, __mmask16(0xffff), lo, v), hi = _mm512_mask_max_epi32(hi, k, hi, v);
    }
    alignas(64) std::array<std::int32_t, 16> a, b;
    _mm512_store_si512(a.data(), lo), _mm512_store_si512(b.data(), hi);
    min_L = *std::min_element(a.begin(), a.end()), max_L = *std::max_element(b.begin(), b.end());
    return g;
#elif defined(__AVX2__)
    // Eight vectors of eight; a lane of the grown set g is picked by its own bit of g.
    const __m256i twice_max = _mm256_set1_epi32(n), next = _mm256_set1_epi32(n + 1);
    std::uint64_t g = 0;
    for (int q = 0; q < 8; ++q) {
      const __m256i v = _mm256_load_si256(reinterpret_cast<const __m256i*>(L.data() + 8 * q));
      const __m256i over = _mm256_cmpgt_epi32(_mm256_add_epi32(v, v), twice_max);
      g |= std::uint64_t(~_mm256_movemask_ps(_mm256_castsi256_ps(over)) & 0xff) << (8 * q);
    }
    g &= d;
    if (!g) return 0;
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    __m256i lo = _mm256_set1_epi32(std::numeric_limits<std::int32_t>::max()), hi = _mm256_set1_epi32(max_L);
    for (int q = 0; q < 8; ++q) {
      const __m256i k = _mm256_set1_epi32(static_cast<int>(g >> (8 * q) & 0xff));
      const __m256i pick = _mm256_cmpeq_epi32(_mm256_and_si256(k, bit), bit);
      auto* at = reinterpret_cast<__m256i*>(L.data() + 8 * q);
      const __m256i v = _mm256_load_si256(at);
      const __m256i w = _mm256_blendv_epi8(v, _mm256_sub_epi32(next, v), pick);
      _mm256_store_si256(at, w);
      // Lengths are never negative, so the lanes not picked may enter the maximum as 0.
      lo = _mm256_min_epi32(lo, w), hi = _mm256_max_epi32(hi, _mm256_and_si256(pick, w));
    }
    alignas(32) std::array<std::int32_t, 8> a, b;
    _mm256_store_si256(reinterpret_cast<__m256i*>(a.data()), lo);
    _mm256_store_si256(reinterpret_cast<__m256i*>(b.data()), hi);
    min_L = *std::min_element(a.begin(), a.end()), max_L = *std::max_element(b.begin(), b.end());
    return g;
#else
    std::uint64_t g = 0;
    for (int l = 0; l < 64; ++l) g |= std::uint64_t(2 * L[l] <= n) << l;
    g &= d;
    if (!g) return 0;
    for (int l = 0; l < 64; ++l)
      if (g >> l & 1) L[l] = n + 1 - L[l], max_L = std::max(max_L, int(L[l]));
    min_L = *std::min_element(L.begin(), L.end());
    return g;
#endif
  }
};

// Berlekamp-Massey on up to 64 blocks at once, bit-sliced: word j of C holds coefficient c_j of every block
// (block l in bit l), so one AND/XOR serves 64 blocks. The shift x^(N-m) that differs between blocks is avoided
// by keeping B already shifted (Bx = x^(N-m) B), which every step multiplies by x: a uniform index shift.
// At step N each lane has deg C <= L and deg Bx <= N+1-L, so words past max(L, N+1-L) over the lanes are zero
// and the loops stop there. Unused lanes hold C = B = 0 and never change.
// The blocks are bits [first + l*M, first + (l+1)*M), l < lanes; their complexities go to L_out[l].
void bm_sliced(const BitSequence& s, std::size_t first, std::size_t M, int lanes, int* L_out) {
  thread_local std::vector<std::uint64_t> S, C, Bbuf;
  thread_local GrowState st;
  load_sliced(s, first, M, lanes, S);
  st.reset(M, lanes);
  const std::uint64_t active = lanes == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << lanes) - 1;
  C.assign(M + 3, 0);
  // Bx[j] lives at Bbuf[off + j]; multiplying by x is --off, so every loop below runs forwards (and vectorises).
  Bbuf.assign(2 * M + 6, 0);
  std::size_t off = M + 2;
  C[0] = active;
  Bbuf[off + 1] = active;  // m = -1: Bx = x^(0 - (-1)) * 1
  // The discrepancy d = sum_i c_i s_{N-i} (c_0 = 1), s_{N-i} being S[M-N+i]; step 0 has C = 1.
  std::uint64_t d = S[M];
  for (std::size_t N = 0; N < M; ++N) {
    const std::size_t top = static_cast<std::size_t>(std::max(st.max_L, static_cast<int>(N) + 1 - st.min_L));
    const std::uint64_t grow = st.grow(d, N);
    // C += Bx where d; next Bx = x * (grow ? old C : Bx); and the next step's discrepancy from the new C, which
    // is zero past `top` as well.
    std::uint64_t* __restrict c_ = C.data();
    std::uint64_t* __restrict b_ = Bbuf.data() + off;
    const std::uint64_t* __restrict next = S.data() + (M - N - 1);
    std::uint64_t d_next = 0;
    for (std::size_t j = 0; j <= top; ++j) {
      const std::uint64_t c = c_[j], b = b_[j], c_new = c ^ (d & b);
      c_[j] = c_new;
      b_[j] = (grow & c) | (~grow & b);
      d_next ^= c_new & next[j];
    }
    d = d_next;
    --off;
    Bbuf[off] = 0;
  }
  for (int l = 0; l < lanes; ++l) L_out[l] = static_cast<int>(st.L[l]);
}

}  // namespace

int berlekamp_massey(const BitSequence& s, std::size_t start, std::size_t len) {
  if (len < 64 * 2) return bm_fixed<2>(s, start, len);
  if (len < 64 * 4) return bm_fixed<4>(s, start, len);
  if (len < 64 * 8) return bm_fixed<8>(s, start, len);
  if (len < 64 * 16) return bm_fixed<16>(s, start, len);
  return bm_generic(s, start, len);
}

std::vector<int> block_linear_complexities(const BitSequence& s, int M) {
  const std::size_t N = M > 0 ? s.size() / static_cast<std::size_t>(M) : 0;
  std::vector<int> out(N);
  for (std::size_t g = 0; g < N; g += 64)
    bm_sliced(s, g * M, static_cast<std::size_t>(M), static_cast<int>(std::min<std::size_t>(64, N - g)), &out[g]);
  return out;
}

std::optional<ParameterProblem> check_linear_complexity(int M) {
  // The class probabilities below are the limit M -> infinity. For M >= 12 a block's exact ones (from Rueppel's
  // count of sequences by linear complexity) are within 1 % of them; at M = 11 the first class is 2 % off, and
  // from M = 5 down whole classes are empty, so chi^2 would fail every sequence.
  if (M < 12)
    return ParameterProblem{"linear_complexity_M", M,
                            "must be at least 12 (shorter blocks do not follow the test's class probabilities)"};
  return std::nullopt;
}

TestResult linear_complexity(const BitSequence& s, int M) {
  require_valid(check_linear_complexity(M));
  TestResult r = make(Test::LinearComplexity, s.size());
  r.parameters = {{"M", M}};
  const std::size_t N = s.size() / static_cast<std::size_t>(M);
  r.parameters.push_back({"N", static_cast<double>(N)});
  if (N == 0) return too_short(r, static_cast<std::size_t>(M), "one block of M bits");
  // The reference's rounded class probabilities (the first is 0.01047, not 1/96 = 0.010417).
  constexpr double pi[7] = {0.01047, 0.03125, 0.12500, 0.50000, 0.25000, 0.06250, 0.020833};
  // The reference's mean uses (-1)^M where the printed formula has (-1)^(M+1) (sign1 below); kept, because
  // the reference's P-values are the published ones (docs/nist-conventions.md).
  const double sign1 = (M + 1) % 2 == 0 ? -1.0 : 1.0;
  const double mean = M / 2.0 + (9.0 + sign1) / 36.0 - 1.0 / std::pow(2, M) * (M / 3.0 + 2.0 / 9.0);
  const double sign2 = M % 2 == 0 ? 1.0 : -1.0;
  double nu[7] = {};
  for (const int L : block_linear_complexities(s, M)) {
    const double T = sign2 * (L - mean) + 2.0 / 9.0;
    int k;
    if (T <= -2.5) k = 0;
    else if (T <= -1.5) k = 1;
    else if (T <= -0.5) k = 2;
    else if (T <= 0.5) k = 3;
    else if (T <= 1.5) k = 4;
    else if (T <= 2.5) k = 5;
    else k = 6;
    nu[k] += 1;
  }
  double chi2 = 0;
  for (int k = 0; k < 7; ++k) chi2 += std::pow(nu[k] - N * pi[k], 2) / (N * pi[k]);
  r.parameters.push_back({"mean", mean});
  r.values.push_back({"-", chi2, igamc(3.0, chi2 / 2.0)});
  return r;
}

}  // namespace dpdrng::stats::nist
