// Non-overlapping and overlapping template matching (SP800-22 2.7, 2.8).
#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// Some proper prefix equals the suffix of the same length: two matches could overlap.
bool bordered(std::uint32_t v, int m) {
  for (int k = 1; k < m; ++k) {
    const std::uint32_t mask = (std::uint32_t{1} << k) - 1;
    if ((v >> (m - k)) == (v & mask)) return true;
  }
  return false;
}

}  // namespace

std::vector<std::uint32_t> aperiodic_templates(int m) {
  std::vector<std::uint32_t> out;
  if (m < 1 || m > 24) return out;
  for (std::uint32_t v = 0; v < (std::uint32_t{1} << m); ++v)
    if (!bordered(v, m)) out.push_back(v);
  return out;
}

namespace {

std::string bits_string(std::uint32_t v, int m) {
  std::string s(static_cast<std::size_t>(m), '0');
  for (int k = 0; k < m; ++k)
    if ((v >> (m - 1 - k)) & 1) s[k] = '1';
  return s;
}

// Counts[t * N + i]: matches of template t in block i, the scan restarting m bits after each counted match as in
// the reference. Three ways to the same counts, from the fastest to the most general.

// Distinct unbordered templates: two matches of one template can never overlap, so the restart never skips a
// match and a template's count is the number of windows equal to it. One histogram of the block's m-bit window
// values gives every template's count.
std::vector<std::uint32_t> counts_unbordered(const BitSequence& s, int m, std::span<const std::uint32_t> templates,
                                             std::size_t N, std::size_t M) {
  const std::size_t T = templates.size(), per_word = 64 - static_cast<std::size_t>(m) + 1;
  const unsigned shift = 64 - static_cast<unsigned>(m);
  std::vector<std::uint32_t> W(T * N), hist(std::size_t{1} << m);
  for (std::size_t i = 0; i < N; ++i) {
    std::fill(hist.begin(), hist.end(), 0);
    const std::size_t base = i * M, windows = M - m + 1;
    for (std::size_t j0 = 0; j0 < windows; j0 += per_word) {
      const std::uint64_t x = s.word_at(base + j0);
      const std::size_t cnt = std::min(per_word, windows - j0);
      for (std::size_t k = 0; k < cnt; ++k) ++hist[(x << k) >> shift];
    }
    for (std::size_t t = 0; t < T; ++t) W[t * N + i] = hist[templates[t]];
  }
  return W;
}

// Distinct templates, some bordered: each remembers where its last counted match ends. Branch-free: windows that
// match no template land in a dummy slot T.
std::vector<std::uint32_t> counts_distinct(const BitSequence& s, int m, std::span<const std::uint32_t> templates,
                                           std::size_t N, std::size_t M) {
  const std::size_t T = templates.size();
  std::vector<std::uint32_t> W(T * N, 0);
  std::vector<std::uint32_t> slot(std::size_t{1} << m, static_cast<std::uint32_t>(T));
  for (std::size_t t = 0; t < T; ++t) slot[templates[t]] = static_cast<std::uint32_t>(t);
  std::vector<std::size_t> free_from(T + 1);
  std::vector<std::uint32_t> count(T + 1);
  const unsigned shift = 64 - static_cast<unsigned>(m);
  for (std::size_t i = 0; i < N; ++i) {
    std::fill(free_from.begin(), free_from.end(), 0);
    std::fill(count.begin(), count.end(), 0);
    const std::size_t base = i * M, last = M - m;  // windows j = 0..last
    for (std::size_t j0 = 0; j0 <= last; j0 += 64 - m + 1) {
      const std::uint64_t x = s.word_at(base + j0);
      const std::size_t cnt = std::min<std::size_t>(64 - m + 1, last - j0 + 1);
      for (std::size_t k = 0; k < cnt; ++k) {
        const std::size_t j = j0 + k;
        const std::uint32_t t = slot[(x << k) >> shift];
        const bool hit = j >= free_from[t];
        count[t] += hit;
        free_from[t] = hit ? j + m : free_from[t];
      }
    }
    for (std::size_t t = 0; t < T; ++t) W[t * N + i] = count[t];
  }
  return W;
}

// Any list, repeats included: the window value points at the template(s) equal to it.
std::vector<std::uint32_t> counts_general(const BitSequence& s, int m, std::span<const std::uint32_t> templates,
                                          std::size_t N, std::size_t M) {
  const std::size_t T = templates.size();
  std::vector<int> first(std::size_t{1} << m, -1), next_same(T, -1);
  for (std::size_t t = T; t-- > 0;) {
    next_same[t] = first[templates[t]];
    first[templates[t]] = static_cast<int>(t);
  }
  std::vector<std::uint32_t> W(T * N, 0);
  std::vector<std::size_t> free_from(T);
  for (std::size_t i = 0; i < N; ++i) {
    std::fill(free_from.begin(), free_from.end(), 0);
    const std::size_t base = i * M;
    for (std::size_t j = 0; j + m <= M; ++j) {
      for (int t = first[s.bits_at(base + j, m)]; t >= 0; t = next_same[t]) {
        if (j < free_from[t]) continue;
        ++W[t * N + i];
        free_from[t] = j + m;
      }
    }
  }
  return W;
}

std::vector<std::uint32_t> match_counts(const BitSequence& s, int m, std::span<const std::uint32_t> templates,
                                        std::size_t N, std::size_t M) {
  std::vector<bool> seen(std::size_t{1} << m, false);
  bool distinct = true, unbordered = true;
  for (const std::uint32_t t : templates) {
    distinct = distinct && !seen[t];
    seen[t] = true;
    unbordered = unbordered && !bordered(t, m);
  }
  if (!distinct) return counts_general(s, m, templates, N, M);
  if (!unbordered) return counts_distinct(s, m, templates, N, M);
  return counts_unbordered(s, m, templates, N, M);
}

}  // namespace

std::optional<ParameterProblem> check_non_overlapping(int m, std::span<const std::uint32_t> templates, int blocks) {
  if (m < 2 || m > 21) return ParameterProblem{"non_overlapping_m", m, "must be within 2..21"};
  if (blocks < 1) return ParameterProblem{"non_overlapping_blocks", blocks, "must be at least 1"};
  for (const std::uint32_t t : templates)
    if (t >> m != 0)
      return ParameterProblem{"non_overlapping_templates", t, "does not fit in m = " + std::to_string(m) + " bits"};
  return std::nullopt;
}

TestResult non_overlapping_template(const BitSequence& s, int m, std::span<const std::uint32_t> templates,
                                    int blocks) {
  require_valid(check_non_overlapping(m, templates, blocks));
  TestResult r = make(Test::NonOverlappingTemplate, s.size());
  std::vector<std::uint32_t> own;
  if (templates.empty()) {
    own = aperiodic_templates(m);
    templates = own;
  }
  for (std::uint32_t t : templates) r.values.push_back({bits_string(t, m), NAN, NAN});
  const std::size_t N = static_cast<std::size_t>(blocks);
  const std::size_t M = s.size() / N;
  r.parameters = {{"m", m}, {"N", blocks}, {"M", static_cast<double>(M)}};
  if (M < static_cast<std::size_t>(m))
    return too_short(r, N * m, "each of the " + std::to_string(N) + " blocks must hold one template");
  const double lambda = (M - m + 1) / std::pow(2, m);
  const double varW = M * (1.0 / std::pow(2.0, m) - (2.0 * m - 1.0) / std::pow(2.0, 2.0 * m));
  r.parameters.push_back({"lambda", lambda});

  const std::vector<std::uint32_t> W = match_counts(s, m, templates, N, M);
  const std::size_t T = templates.size();
  for (std::size_t t = 0; t < T; ++t) {
    double chi2 = 0;
    for (std::size_t i = 0; i < N; ++i) chi2 += std::pow((W[t * N + i] - lambda) / std::sqrt(varW), 2);
    r.values[t].statistic = chi2;
    r.values[t].p = igamc(N / 2.0, chi2 / 2.0);
  }
  return r;
}

namespace {

// The reference's Pr(u, eta): probability that an m-bit template of ones occurs u times in a block (the
// corrected formula of SP800-22 rev1a 3.8).
double overlap_probability(int u, double eta) {
  if (u == 0) return std::exp(-eta);
  double sum = 0;
  for (int l = 1; l <= u; ++l)
    sum += std::exp(-eta - u * std::log(2) + l * std::log(eta) - std::lgamma(l + 1) + std::lgamma(u) -
                    std::lgamma(l) - std::lgamma(u - l + 1));
  return sum;
}

// eta = lambda / 2, lambda = (M - m + 1) / 2^m.
double overlap_eta(int m, int M) { return static_cast<double>(M - m + 1) / std::pow(2, m) / 2.0; }

// Classes 0..K-1 occurrences and "K or more".
std::vector<double> overlap_classes(int K, double eta) {
  std::vector<double> pi(static_cast<std::size_t>(K) + 1);
  double sum = 0;
  for (int i = 0; i < K; ++i) sum += pi[i] = overlap_probability(i, eta);
  pi[K] = 1 - sum;
  return pi;
}

// Windows of m ones starting at j = 0..M-m of bits [base, base+M), overlapping ones included. Per loaded word,
// bit 63-k of the AND of its shifts by 0..m-1 is set when bits k..k+m-1 are all ones (k <= 64-m).
std::size_t runs_of_ones(const BitSequence& s, std::size_t base, std::size_t M, int m) {
  const std::size_t windows = M - static_cast<std::size_t>(m) + 1, per_word = 64 - static_cast<std::size_t>(m) + 1;
  std::size_t count = 0;
  for (std::size_t j0 = 0; j0 < windows; j0 += per_word) {
    const std::uint64_t x = s.word_at(base + j0);
    std::uint64_t y = x;
    for (int t = 1; t < m; ++t) y &= x << t;
    const std::size_t cnt = std::min(per_word, windows - j0);
    count += static_cast<std::size_t>(std::popcount(y & (~std::uint64_t{0} << (64 - cnt))));
  }
  return count;
}

}  // namespace

double min_overlapping_class(int m, int M, int K) {
  const std::vector<double> pi = overlap_classes(K, overlap_eta(m, M));
  return *std::min_element(pi.begin(), pi.end());
}

std::optional<ParameterProblem> check_overlapping(int m, int M, int K) {
  if (m < 1 || m > 32) return ParameterProblem{"overlapping_m", m, "must be within 1..32"};
  if (M < m) return ParameterProblem{"overlapping_M", M, "must be at least m = " + std::to_string(m)};
  if (K < 1 || K > 64) return ParameterProblem{"overlapping_K", K, "must be within 1..64"};
  // chi^2 divides by every class probability: each must be positive (too many classes for a short block leave
  // the last one with 1 - sum <= 0 in floating point).
  for (const double p : overlap_classes(K, overlap_eta(m, M)))
    if (!(p > 0))
      return ParameterProblem{"overlapping_K", K,
                              "leaves a class with probability 0 for m = " + std::to_string(m) +
                                  " and M = " + std::to_string(M) + ": use fewer classes"};
  return std::nullopt;
}

TestResult overlapping_template(const BitSequence& s, int m, int M, int K) {
  require_valid(check_overlapping(m, M, K));
  TestResult r = make(Test::OverlappingTemplate, s.size());
  const std::size_t N = s.size() / static_cast<std::size_t>(M);
  const double eta = overlap_eta(m, M);
  const double lambda = 2 * eta;
  r.parameters = {{"m", m}, {"M", M}, {"K", K}, {"N", static_cast<double>(N)}, {"lambda", lambda}, {"eta", eta}};
  if (N == 0) return too_short(r, static_cast<std::size_t>(M), "one block of M bits");
  const std::vector<double> pi = overlap_classes(K, eta);
  std::vector<double> nu(K + 1, 0);
  for (std::size_t i = 0; i < N; ++i) {
    const int w = static_cast<int>(runs_of_ones(s, i * static_cast<std::size_t>(M), static_cast<std::size_t>(M), m));
    nu[std::min(w, K)] += 1;
  }
  double chi2 = 0;
  for (int i = 0; i <= K; ++i) chi2 += std::pow(nu[i] - N * pi[i], 2) / (N * pi[i]);
  r.values.push_back({"-", chi2, igamc(K / 2.0, chi2 / 2.0)});
  return r;
}

}  // namespace dpdrng::stats::nist
