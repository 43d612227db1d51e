// Binary matrix rank test (SP800-22 2.5): 32x32 matrices over GF(2), one 32-bit word per row.
#include <array>
#include <bit>
#include <cmath>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// The reference's probability of full rank r for a 32x32 random matrix (product formula of 2.5.4).
double rank_probability(int r) {
  double product = 1;
  for (int i = 0; i <= r - 1; ++i)
    product *= ((1.0 - std::pow(2, i - 32)) * (1.0 - std::pow(2, i - 32))) / (1.0 - std::pow(2, i - r));
  return std::pow(2, r * (32 + 32 - r) - 32 * 32) * product;
}

}  // namespace

// Gaussian elimination without row swaps: each column picks as pivot the first unused row holding it and clears
// it from the others. The rows holding a column form a 32-bit mask, so both inner loops are branch-free and
// vectorise; the rank is the number of pivots.
int binary_rank32(std::array<std::uint32_t, 32> rows) {
  std::uint32_t used = 0;
  for (int col = 31; col >= 0; --col) {
    std::uint32_t holding = 0;
    for (int i = 0; i < 32; ++i) holding |= ((rows[i] >> col) & 1u) << i;
    const std::uint32_t candidates = holding & ~used;
    if (!candidates) continue;
    const int p = std::countr_zero(candidates);
    used |= std::uint32_t{1} << p;
    const std::uint32_t pivot = rows[p], others = holding & ~(std::uint32_t{1} << p);
    for (int i = 0; i < 32; ++i) rows[i] ^= ((others >> i) & 1u) ? pivot : 0;
  }
  return std::popcount(used);
}

TestResult rank(const BitSequence& s) {
  TestResult r = make(Test::Rank, s.size());
  const std::size_t N = s.size() / 1024;
  r.parameters = {{"N", static_cast<double>(N)}};
  if (N == 0) return too_short(r, 1024, "one 32x32 matrix; SP800-22 recommends 38 matrices, 38912 bits");
  const double p32 = rank_probability(32), p31 = rank_probability(31), p30 = 1 - (p32 + p31);
  double F32 = 0, F31 = 0;
  std::array<std::uint32_t, 32> rows;
  for (std::size_t k = 0; k < N; ++k) {
    for (int i = 0; i < 32; ++i) rows[i] = s.bits_at(k * 1024 + 32 * i, 32);
    const int R = binary_rank32(rows);
    F32 += R == 32;
    F31 += R == 31;
  }
  const double F30 = static_cast<double>(N) - (F32 + F31);
  const double chi2 = std::pow(F32 - N * p32, 2) / (N * p32) + std::pow(F31 - N * p31, 2) / (N * p31) +
                      std::pow(F30 - N * p30, 2) / (N * p30);
  // Two degrees of freedom: Q(1, x/2) = exp(-x/2), written as the reference does.
  r.values.push_back({"-", chi2, std::exp(-chi2 / 2.0)});
  return r;
}

}  // namespace dpdrng::stats::nist
