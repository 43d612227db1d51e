// Frequency, BlockFrequency, CumulativeSums, Runs and LongestRun: the tests that only count ones and runs.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

TestResult frequency(const BitSequence& s) {
  TestResult r = make(Test::Frequency, s.size());
  const double n = static_cast<double>(s.size());
  if (s.empty()) return too_short(r, 1);
  const double sum = 2.0 * static_cast<double>(s.count_ones()) - n;
  r.values.push_back({"-", sum, erfc(std::fabs(sum) / std::sqrt(n) / std::sqrt(2.0))});
  return r;
}

std::optional<ParameterProblem> check_block_frequency(int M) {
  if (M < 2)
    return ParameterProblem{"block_frequency_M", M,
                            "must be at least 2 (with M = 1 every sequence gives chi^2 = N: the test cannot fail)"};
  return std::nullopt;
}

TestResult block_frequency(const BitSequence& s, int M) {
  require_valid(check_block_frequency(M));
  TestResult r = make(Test::BlockFrequency, s.size());
  r.parameters = {{"M", M}};
  const std::size_t N = s.size() / static_cast<std::size_t>(M);
  r.parameters.push_back({"N", static_cast<double>(N)});
  if (N == 0) return too_short(r, static_cast<std::size_t>(M), "one block of M bits");
  double sum = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const double pi = static_cast<double>(s.count_ones(i * M, M)) / M;
    sum += (pi - 0.5) * (pi - 0.5);
  }
  const double chi2 = 4.0 * M * sum;
  r.values.push_back({"-", chi2, igamc(N / 2.0, chi2 / 2.0)});
  return r;
}

namespace {

// Walk extremes inside one byte (first bit = most significant): net step, highest and lowest partial sum.
struct ByteWalk {
  std::array<std::int8_t, 256> delta{}, hi{}, lo{};
  ByteWalk() {
    for (int b = 0; b < 256; ++b) {
      int S = 0, h = -9, l = 9;
      for (int k = 7; k >= 0; --k) {
        S += ((b >> k) & 1) ? 1 : -1;
        h = std::max(h, S);
        l = std::min(l, S);
      }
      delta[b] = static_cast<std::int8_t>(S);
      hi[b] = static_cast<std::int8_t>(h);
      lo[b] = static_cast<std::int8_t>(l);
    }
  }
};
const ByteWalk kByteWalk;

// sts-2.1.2's cusum p-value, kept with its C integer divisions (truncation toward zero), see the header.
// Every non-empty walk reaches |S| = 1, so z = 1 has P = 1 exactly; the reference's truncated sums give up to
// 1.10 there (n <= 52), which is no probability. For z >= 2 they leave [0, 1] only by round-off (at most 1e-12,
// checked for every n <= 3000), which the clamp at the end removes.
double cusum_p(long n, long z) {
  if (z <= 1) return 1.0;
  const double sn = std::sqrt(static_cast<double>(n));
  double sum1 = 0, sum2 = 0;
  for (long k = (-n / z + 1) / 4; k <= (n / z - 1) / 4; ++k)
    sum1 += normal_cdf(((4 * k + 1) * z) / sn) - normal_cdf(((4 * k - 1) * z) / sn);
  for (long k = (-n / z - 3) / 4; k <= (n / z - 1) / 4; ++k)
    sum2 += normal_cdf(((4 * k + 3) * z) / sn) - normal_cdf(((4 * k + 1) * z) / sn);
  return std::clamp(1.0 - sum1 + sum2, 0.0, 1.0);
}

}  // namespace

TestResult cumulative_sums(const BitSequence& s) {
  TestResult r = make(Test::CumulativeSums, s.size());
  r.values = {{"forward", NAN, NAN}, {"reverse", NAN, NAN}};
  const std::size_t n = s.size();
  if (n == 0) return too_short(r, 1);
  long S = 0, sup = 0, inf = 0;
  const std::size_t full_bytes = n / 8;
  const auto words = s.words();
  for (std::size_t b = 0; b < full_bytes; ++b) {
    const unsigned byte = static_cast<unsigned>(words[b >> 3] >> (56 - 8 * (b & 7))) & 0xffu;
    sup = std::max(sup, S + kByteWalk.hi[byte]);
    inf = std::min(inf, S + kByteWalk.lo[byte]);
    S += kByteWalk.delta[byte];
  }
  for (std::size_t i = full_bytes * 8; i < n; ++i) {
    S += s[i] ? 1 : -1;
    sup = std::max(sup, S);
    inf = std::min(inf, S);
  }
  // The reverse walk's largest excursion is the largest distance of the final sum from any partial sum.
  const long z = std::max(sup, -inf);
  const long zrev = std::max(sup - S, S - inf);
  const long ln = static_cast<long>(n);
  r.values[0] = {"forward", static_cast<double>(z), cusum_p(ln, z)};
  r.values[1] = {"reverse", static_cast<double>(zrev), cusum_p(ln, zrev)};
  return r;
}

TestResult runs(const BitSequence& s) {
  TestResult r = make(Test::Runs, s.size());
  const std::size_t n = s.size();
  if (n < 2) return too_short(r, 2);
  const double pi = static_cast<double>(s.count_ones()) / n;
  r.parameters = {{"pi", pi}};
  if (std::fabs(pi - 0.5) > 2.0 / std::sqrt(static_cast<double>(n))) {
    r.values.push_back({"-", NAN, 0.0});  // the reference's verdict: frequency prerequisite failed
    return r;
  }
  // Runs = 1 + number of positions where a bit differs from its successor.
  std::size_t changes = 0, pos = 0;
  for (; pos + 64 <= n - 1; pos += 64) changes += std::popcount(s.word_at(pos) ^ s.word_at(pos + 1));
  if (const std::size_t rest = n - 1 - pos; rest > 0)
    changes += std::popcount((s.word_at(pos) ^ s.word_at(pos + 1)) >> (64 - rest));
  const double V = 1.0 + static_cast<double>(changes);
  const double arg = std::fabs(V - 2.0 * n * pi * (1 - pi)) / (2.0 * pi * (1 - pi) * std::sqrt(2.0 * n));
  r.values.push_back({"-", V, erfc(arg)});
  return r;
}

namespace {

int longest_ones(const BitSequence& s, std::size_t start, std::size_t len) {
  int best = 0, cur = 0;
  for (std::size_t off = 0; off < len; off += 64) {
    std::uint64_t x = s.word_at(start + off);
    if (len - off < 64) x &= ~std::uint64_t{0} << (64 - (len - off));
    if (x == ~std::uint64_t{0}) {
      cur += 64;
      best = std::max(best, cur);
      continue;
    }
    best = std::max(best, cur + std::countl_one(x));
    int inner = 0;
    for (std::uint64_t y = x; y; y &= y << 1) ++inner;
    best = std::max(best, inner);
    cur = std::countr_one(x);
  }
  return best;
}

}  // namespace

TestResult longest_run(const BitSequence& s) {
  TestResult r = make(Test::LongestRun, s.size());
  const std::size_t n = s.size();
  if (n < 128) return too_short(r, 128);
  // sts-2.1.2's classes and probabilities (for M = 10^4 its 4-digit table, not the more precise values).
  int K, M;
  std::array<int, 7> V{};
  std::array<double, 7> pi{};
  if (n < 6272) {
    K = 3, M = 8, V = {1, 2, 3, 4};
    pi = {0.21484375, 0.3671875, 0.23046875, 0.1875};
  } else if (n < 750000) {
    K = 5, M = 128, V = {4, 5, 6, 7, 8, 9};
    pi = {0.1174035788, 0.242955959, 0.249363483, 0.17517706, 0.102701071, 0.112398847};
  } else {
    K = 6, M = 10000, V = {10, 11, 12, 13, 14, 15, 16};
    pi = {0.0882, 0.2092, 0.2483, 0.1933, 0.1208, 0.0675, 0.0727};
  }
  const std::size_t N = n / M;
  r.parameters = {{"M", M}, {"K", K}, {"N", static_cast<double>(N)}};
  std::array<double, 7> nu{};
  for (std::size_t i = 0; i < N; ++i) {
    const int v = longest_ones(s, i * M, M);
    nu[std::clamp(v, V[0], V[K]) - V[0]] += 1;
  }
  double chi2 = 0;
  for (int i = 0; i <= K; ++i) chi2 += (nu[i] - N * pi[i]) * (nu[i] - N * pi[i]) / (N * pi[i]);
  r.values.push_back({"-", chi2, igamc(K / 2.0, chi2 / 2.0)});
  return r;
}

}  // namespace dpdrng::stats::nist
