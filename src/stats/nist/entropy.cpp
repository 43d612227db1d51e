// Serial and Approximate Entropy tests (SP800-22 2.11, 2.12): both count m-bit patterns around the circle.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// Occurrences of every m-bit pattern at the n start positions of the sequence read circularly.
std::vector<std::uint32_t> circular_counts(const BitSequence& s, int m) {
  std::vector<std::uint32_t> counts(std::size_t{1} << m, 0);
  if (m == 0) {
    counts[0] = static_cast<std::uint32_t>(s.size());
    return counts;
  }
  const BitSequence w = s.wrapped(static_cast<std::size_t>(m - 1));
  const std::size_t n = s.size();
  const unsigned shift = 64 - static_cast<unsigned>(m);
  // 64 - m + 1 windows per loaded word.
  const std::size_t step = 64 - static_cast<std::size_t>(m) + 1;
  for (std::size_t pos = 0; pos < n; pos += step) {
    const std::uint64_t x = w.word_at(pos);
    const std::size_t cnt = std::min(step, n - pos);
    for (std::size_t j = 0; j < cnt; ++j) ++counts[(x << j) >> shift];
  }
  return counts;
}

// Counts of the k-bit prefixes (k <= m): on a circle every k-bit window is the prefix of exactly one m-bit one.
std::vector<std::uint32_t> prefix_counts(const std::vector<std::uint32_t>& counts, int m, int k) {
  std::vector<std::uint32_t> out(std::size_t{1} << k, 0);
  for (std::size_t v = 0; v < counts.size(); ++v) out[v >> (m - k)] += counts[v];
  return out;
}

// The m-bit counts of s: from the given table of at least m bits, or counted.
std::vector<std::uint32_t> counts_of(const BitSequence& s, int m, const PatternCounts* given) {
  if (given == nullptr) return circular_counts(s, m);
  if (given->m < m || given->counts.size() != std::size_t{1} << given->m)
    throw std::invalid_argument("pattern counts of " + std::to_string(given->m) + " bits cannot give " +
                                std::to_string(m) + "-bit ones");
  return given->m == m ? given->counts : prefix_counts(given->counts, given->m, m);
}

double psi2(const std::vector<std::uint32_t>& counts, int m, std::size_t n) {
  if (m <= 0) return 0.0;
  std::uint64_t sum = 0;
  for (std::uint32_t c : counts) sum += std::uint64_t{c} * c;
  return static_cast<double>(sum) * std::pow(2, m) / static_cast<double>(n) - static_cast<double>(n);
}

double phi(const std::vector<std::uint32_t>& counts, std::size_t n) {
  const double nd = static_cast<double>(n);
  double sum = 0;
  for (std::uint32_t c : counts)
    if (c > 0) sum += c * std::log(c / nd);
  return sum / nd;
}

}  // namespace

PatternCounts pattern_counts(const BitSequence& s, int m) {
  if (m < 1 || m > 24) throw std::invalid_argument("pattern counts: m must be within 1..24");
  return {m, circular_counts(s, m)};
}

std::optional<ParameterProblem> check_serial(int m) {
  if (m < 2 || m > 24) return ParameterProblem{"serial_m", m, "must be within 2..24"};
  return std::nullopt;
}

std::optional<ParameterProblem> check_approximate_entropy(int m) {
  if (m < 0 || m > 23) return ParameterProblem{"approximate_entropy_m", m, "must be within 0..23"};
  return std::nullopt;
}

TestResult serial(const BitSequence& s, int m, const PatternCounts* counts) {
  require_valid(check_serial(m));
  TestResult r = make(Test::Serial, s.size());
  r.values = {{"p1", NAN, NAN}, {"p2", NAN, NAN}};
  r.parameters = {{"m", m}};
  const std::size_t n = s.size();
  if (n < static_cast<std::size_t>(m)) return too_short(r, static_cast<std::size_t>(m), "one block of m bits");
  const auto c0 = counts_of(s, m, counts);
  const double psim0 = psi2(c0, m, n);
  const double psim1 = psi2(prefix_counts(c0, m, m - 1), m - 1, n);
  const double psim2 = m >= 3 ? psi2(prefix_counts(c0, m, m - 2), m - 2, n) : 0.0;
  const double del1 = psim0 - psim1, del2 = psim0 - 2.0 * psim1 + psim2;
  r.parameters.push_back({"psi2_m", psim0});
  r.parameters.push_back({"psi2_m-1", psim1});
  r.parameters.push_back({"psi2_m-2", psim2});
  r.values[0] = {"p1", del1, igamc(std::pow(2, m - 1) / 2, del1 / 2.0)};
  r.values[1] = {"p2", del2, igamc(std::pow(2, m - 2) / 2, del2 / 2.0)};
  return r;
}

TestResult approximate_entropy(const BitSequence& s, int m, const PatternCounts* counts) {
  require_valid(check_approximate_entropy(m));
  TestResult r = make(Test::ApproximateEntropy, s.size());
  r.parameters = {{"m", m}};
  const std::size_t n = s.size();
  if (n < static_cast<std::size_t>(m) + 1) return too_short(r, static_cast<std::size_t>(m) + 1, "one block of m+1 bits");
  const auto c1 = counts_of(s, m + 1, counts);
  const double phi_m = m == 0 ? 0.0 : phi(prefix_counts(c1, m + 1, m), n);
  const double phi_m1 = phi(c1, n);
  const double apen = phi_m - phi_m1;
  const double chi2 = 2.0 * static_cast<double>(n) * (std::log(2) - apen);
  r.parameters.push_back({"ApEn", apen});
  r.values.push_back({"-", chi2, igamc(std::pow(2, m - 1), chi2 / 2.0)});
  return r;
}

}  // namespace dpdrng::stats::nist
