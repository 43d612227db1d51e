// Random Excursions and Random Excursions Variant (SP800-22 2.14, 2.15): visits of the +-1 walk to small states.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <string>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// Everything both tests need from one walk: cycles J, per-cycle visit classes for |x| <= 4, total visits.
struct Walk {
  long J = 0;
  std::array<std::array<double, 6>, 8> nu{};  // [state -4..-1, 1..4][visits 0..4, >=5]
  std::array<long, 19> visits{};              // state -9..9
};

int excursion_index(int x) { return x < 0 ? x + 4 : x + 3; }

Walk walk(const BitSequence& s) {
  Walk w;
  std::array<int, 8> cycle{};
  auto close_cycle = [&] {
    ++w.J;
    for (int i = 0; i < 8; ++i) w.nu[i][std::min(cycle[i], 5)] += 1;
    cycle.fill(0);
  };
  const std::size_t n = s.size();
  const auto words = s.words();
  long S = 0;
  std::size_t i = 0;
  while (i < n) {
    // Far from the origin a whole byte can neither reach 0 nor a counted state: take it in one step.
    if ((i & 7) == 0 && i + 8 <= n && std::labs(S) > 17) {
      const unsigned byte = static_cast<unsigned>(words[i >> 6] >> (56 - (i & 63))) & 0xffu;
      S += 2 * std::popcount(byte) - 8;
      i += 8;
      continue;
    }
    S += s[i] ? 1 : -1;
    ++i;
    if (S == 0) {
      close_cycle();
    } else if (S >= -9 && S <= 9) {
      ++w.visits[S + 9];
      if (S >= -4 && S <= 4) ++cycle[excursion_index(static_cast<int>(S))];
    }
  }
  if (S != 0) close_cycle();  // the reference counts the unfinished last excursion as a cycle
  return w;
}

// The reference's rule: at least max(0.005 sqrt(n), 500) cycles.
double cycles_needed(std::size_t n) { return std::max(0.005 * std::sqrt(static_cast<double>(n)), 500.0); }

TestResult& too_few_cycles(TestResult& r, long J, double needed) {
  // A random walk of n steps returns to 0 about sqrt(2n/pi) times, so 500 cycles take ~392 700 bits on average.
  return not_applicable(r,
                        "only " + std::to_string(J) + " cycles (returns to zero), needs " +
                            std::to_string(static_cast<long>(needed)) +
                            "; a random sequence has that many on average from about 392700 bits",
                        392700);
}

}  // namespace

TestResult random_excursions(const BitSequence& s) {
  TestResult r = make(Test::RandomExcursions, s.size());
  constexpr int kStates[8] = {-4, -3, -2, -1, 1, 2, 3, 4};
  for (int x : kStates) r.values.push_back({"x=" + std::to_string(x), NAN, NAN});
  const Walk w = walk(s);
  const double needed = cycles_needed(s.size());
  r.parameters = {{"J", static_cast<double>(w.J)}, {"J_min", needed}};
  if (w.J < needed) return too_few_cycles(r, w.J, needed);
  // The reference's table of pi_k(x), k = 0..5, for |x| = 1..4.
  static constexpr double kPi[5][6] = {
      {0, 0, 0, 0, 0, 0},
      {0.5000000000, 0.25000000000, 0.12500000000, 0.06250000000, 0.03125000000, 0.0312500000},
      {0.7500000000, 0.06250000000, 0.04687500000, 0.03515625000, 0.02636718750, 0.0791015625},
      {0.8333333333, 0.02777777778, 0.02314814815, 0.01929012346, 0.01607510288, 0.0803755143},
      {0.8750000000, 0.01562500000, 0.01367187500, 0.01196289063, 0.01046752930, 0.0732727051}};
  for (int i = 0; i < 8; ++i) {
    const int ax = std::abs(kStates[i]);
    double chi2 = 0;
    for (int k = 0; k < 6; ++k) chi2 += std::pow(w.nu[i][k] - w.J * kPi[ax][k], 2) / (w.J * kPi[ax][k]);
    r.values[i].statistic = chi2;
    r.values[i].p = igamc(2.5, chi2 / 2.0);
  }
  return r;
}

TestResult random_excursions_variant(const BitSequence& s) {
  TestResult r = make(Test::RandomExcursionsVariant, s.size());
  for (int x = -9; x <= 9; ++x)
    if (x != 0) r.values.push_back({"x=" + std::to_string(x), NAN, NAN});
  const Walk w = walk(s);
  // The reference truncates this constraint to an integer here (not in RandomExcursions); same for n < 10^10.
  const double needed = static_cast<int>(cycles_needed(s.size()));
  r.parameters = {{"J", static_cast<double>(w.J)}, {"J_min", needed}};
  if (w.J < needed) return too_few_cycles(r, w.J, needed);
  std::size_t k = 0;
  for (int x = -9; x <= 9; ++x) {
    if (x == 0) continue;
    const double count = static_cast<double>(w.visits[x + 9]);
    r.values[k].statistic = count;
    r.values[k].p = erfc(std::fabs(count - w.J) / std::sqrt(2.0 * w.J * (4.0 * std::abs(x) - 2)));
    ++k;
  }
  return r;
}

}  // namespace dpdrng::stats::nist
