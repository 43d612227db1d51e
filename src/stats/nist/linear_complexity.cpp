// Linear complexity test (SP800-22 2.10) with a word-parallel Berlekamp-Massey.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <vector>

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

// Berlekamp-Massey on up to 64 blocks at once, bit-sliced: word j of C holds coefficient c_j of every block
// (block l in bit l), so one AND/XOR serves 64 blocks. The shift x^(N-m) that differs between blocks is avoided
// by keeping B already shifted (Bx = x^(N-m) B), which every step multiplies by x: a uniform index shift.
// The blocks are bits [first + l*M, first + (l+1)*M), l < lanes; their complexities go to L_out[l].
void bm_sliced(const BitSequence& s, std::size_t first, std::size_t M, int lanes, int* L_out) {
  thread_local std::vector<std::uint64_t> S, C, Bbuf;
  S.assign(M, 0);
  C.assign(M + 3, 0);
  // Bx[j] lives at Bbuf[off + j]; multiplying by x is --off, so every loop below runs forwards (and vectorises).
  Bbuf.assign(2 * M + 6, 0);
  std::size_t off = M + 2;
  for (int l = 0; l < lanes; ++l) {
    const std::uint64_t lane = std::uint64_t{1} << l;
    for (std::size_t N0 = 0; N0 < M; N0 += 64) {
      const std::uint64_t w = s.word_at(first + static_cast<std::size_t>(l) * M + N0);
      const std::size_t cnt = std::min<std::size_t>(64, M - N0);
      // Stored reversed (S[M-1-N] = bit N) so that the discrepancy below reads both arrays forwards.
      for (std::size_t b = 0; b < cnt; ++b) S[M - 1 - (N0 + b)] |= ((w >> (63 - b)) & 1) ? lane : 0;
    }
  }
  std::array<long, 64> L{};
  C[0] = ~std::uint64_t{0};
  Bbuf[off + 1] = ~std::uint64_t{0};  // m = -1: Bx = x^(0 - (-1)) * 1
  for (std::size_t N = 0; N < M; ++N) {
    // d = s_N + sum_i c_i s_{N-i}, s_{N-i} being S[M-1-N+i]
    const std::uint64_t* window = S.data() + (M - 1 - N);
    std::uint64_t d = window[0];
    for (std::size_t i = 1; i <= N; ++i) d ^= C[i] & window[i];
    std::uint64_t grow = 0;
    if (d) {
      for (int l = 0; l < 64; ++l)
        if (((d >> l) & 1) && L[l] <= static_cast<long>(N) / 2) {
          grow |= std::uint64_t{1} << l;
          L[l] = static_cast<long>(N) + 1 - L[l];
        }
    }
    // C += Bx where d; next Bx = x * (grow ? old C : Bx).
    const std::size_t top = std::min(N + 1, M + 1);
    std::uint64_t* B = Bbuf.data() + off;
    for (std::size_t j = 0; j <= top; ++j) {
      const std::uint64_t c = C[j], b = B[j];
      C[j] = c ^ (d & b);
      B[j] = (grow & c) | (~grow & b);
    }
    --off;
    Bbuf[off] = 0;
  }
  for (int l = 0; l < lanes; ++l) L_out[l] = static_cast<int>(L[l]);
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
