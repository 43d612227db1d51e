// Maurer's "universal statistical" test (SP800-22 2.9).
#include <cmath>
#include <vector>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// Expected value and variance of f_n for L = 1..16: L >= 6 as in the reference's arrays, L <= 5 (which the
// reference never chooses) from SP800-22's table in 2.9.
constexpr double kExpected[17] = {0,         0.7326495, 1.5374383, 2.4016068, 3.3112247, 4.2534266,
                                  5.2177052, 6.1962507, 7.1836656, 8.1764248, 9.1723243, 10.170032,
                                  11.168765, 12.168070, 13.167693, 14.167488, 15.167379};
constexpr double kVariance[17] = {0,     0.690, 1.338, 1.901, 2.358, 2.705, 2.954, 3.125, 3.238,
                                  3.311, 3.356, 3.384, 3.401, 3.410, 3.416, 3.419, 3.421};

// The reference's choice of L from n (n >= 1010 * 2^L * L, its thresholds verbatim); 5 means "too short".
int reference_L(std::size_t n) {
  constexpr std::size_t kFrom[] = {387840,   904960,    2068480,   4654080,   10342400,  22753280,
                                   49643520, 107560960, 231669760, 496435200, 1059061760};
  int L = 5;
  for (int k = 0; k < 11; ++k)
    if (n >= kFrom[k]) L = 6 + k;
  return L;
}

// log2 of a distance between repeats, as log(d) / log(2). Distances are mostly short (mean 2^L), so the values
// for d < 2^16 are computed once per process; the same expression, so the same bits.
double log2_distance(long d) {
  static const std::vector<double> table = [] {
    std::vector<double> t(std::size_t{1} << 16);
    const double ln2 = std::log(2.0);
    for (std::size_t i = 1; i < t.size(); ++i) t[i] = std::log(static_cast<double>(i)) / ln2;
    return t;
  }();
  if (d < static_cast<long>(table.size())) return table[static_cast<std::size_t>(d)];
  return std::log(static_cast<double>(d)) / std::log(2.0);
}

}  // namespace

std::optional<ParameterProblem> check_universal(int L, int Q) {
  // Coron's c(L, K) = 0.7 - 0.8/L + ... is negative at L = 1 (for every K >= 3), which would make sigma negative
  // and P up to 2.
  if (L != 0 && (L < 2 || L > 16))
    return ParameterProblem{"universal_L", L,
                            "must be 0 (chosen from n) or within 2..16 (at L = 1 the variance factor c(L, K) is "
                            "negative)"};
  if (Q < 0) return ParameterProblem{"universal_Q", Q, "must be 0 (10 * 2^L) or positive"};
  return std::nullopt;
}

TestResult universal(const BitSequence& s, int L, int Q) {
  require_valid(check_universal(L, Q));
  TestResult r = make(Test::Universal, s.size());
  const std::size_t n = s.size();
  if (L == 0) {
    L = reference_L(n);
    if (L < 6) return too_short(r, 387840, "the reference's smallest block length L = 6");
  }
  if (Q == 0) Q = 10 * (1 << L);
  const long K = static_cast<long>(n / L) - Q;
  r.parameters = {{"L", L}, {"Q", Q}, {"K", static_cast<double>(K)}};
  if (K < 1)
    return too_short(r, (static_cast<std::size_t>(Q) + 1) * static_cast<std::size_t>(L),
                     "Q initialisation blocks plus one");
  const double c = 0.7 - 0.8 / L + (4 + 32.0 / L) * std::pow(static_cast<double>(K), -3.0 / L) / 15;
  const double sigma = c * std::sqrt(kVariance[L] / K);
  std::vector<long> last(std::size_t{1} << L, 0);
  for (long i = 1; i <= Q; ++i) last[s.bits_at((i - 1) * L, L)] = i;
  double sum = 0;
  for (long i = Q + 1; i <= Q + K; ++i) {
    long& t = last[s.bits_at((i - 1) * L, L)];
    sum += log2_distance(i - t);
    t = i;
  }
  const double phi = sum / K;
  r.parameters.push_back({"sigma", sigma});
  r.values.push_back({"-", phi, erfc(std::fabs(phi - kExpected[L]) / (std::sqrt(2.0) * sigma))});
  return r;
}

}  // namespace dpdrng::stats::nist
