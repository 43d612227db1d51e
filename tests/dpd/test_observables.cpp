// g(r) against two outside facts: an ideal gas (independent uniform positions) has g(r) = 1 at every r, and
// the cell-list sampler must count exactly the pairs a brute-force double loop counts, for any team size.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>

#include "dpdrng/dpd/observables.hpp"

namespace dpdrng_test::dpd_test_observables {

using namespace dpdrng::dpd;

namespace {
// Pairs per bin by brute force, with the sampler's own binning (bin = floor(r · bins / rmax)).
std::vector<double> brute_counts(const System& s, int bins, double rmax) {
  std::vector<double> out(bins, 0.0);
  const double L = s.box.L[0];
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double dx = min_image(s.x[j] - s.x[i], L, L / 2), dy = min_image(s.y[j] - s.y[i], L, L / 2),
                   dz = min_image(s.z[j] - s.z[i], L, L / 2);
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < rmax * rmax) out[std::min<std::size_t>(bins - 1, std::size_t(std::sqrt(r2) * bins / rmax))] += 1;
    }
  return out;
}

double shell_volume(int bin, double dr) {
  const double r0 = bin * dr, r1 = r0 + dr;
  return 4.0 / 3.0 * std::numbers::pi * (r1 * r1 * r1 - r0 * r0 * r0);
}

// The sampler's g(r) of one configuration, turned back into pairs per bin, equals the brute-force count on every
// team size in `threads`.
void expect_counts_equal_brute_force(const System& s, int bins, double rmax, std::initializer_list<int> threads) {
  const auto brute = brute_counts(s, bins, rmax);
  const double L = s.box.L[0], n = double(s.size()), pair_density = n * (n - 1) / 2 / (L * L * L);
  for (int t : threads) {
    RdfHistogram h(bins, rmax, t);
    h.sample(s);
    const Rdf g = h.finish(s);
    ASSERT_EQ(g.g.size(), std::size_t(bins));
    for (int b = 0; b < bins; ++b)
      EXPECT_NEAR(g.g[b] * pair_density * shell_volume(b, rmax / bins), brute[b], 1e-9 * (1 + brute[b]))
          << "threads " << t << " bin " << b;
  }
}
}  // namespace

// 3 000 beads (the cell-list path: more than 2 000 beads) in a box of 7.6 (three cells along each axis, the
// fewest the grid takes: the forward half of the stencil and the backward half are then as far apart as they get).
TEST(Rdf, CellListCountsEqualBruteForceOnTheSmallestGrid) {
  const double L = 7.6;
  expect_counts_equal_brute_force(make_fluid(3000, Box{{L, L, L}}, 1.0, 12), 25, 2.5, {1, 2});
}

// 3 000 beads in a box of 10 (the cell-list path: more than 2 000 beads), 25 bins to 2.5, one configuration.
TEST(Rdf, CellListCountsEqualBruteForceForAnyTeamAndIdealGasIsFlat) {
  const int bins = 25;
  const double rmax = 2.5, L = 10.0;
  const System s = make_fluid(3000, Box{{L, L, L}}, 1.0, 11);
  expect_counts_equal_brute_force(s, bins, rmax, {1, 2, 3});
  // Ideal gas: each bin's count is Poisson-like around pair_density · shell; 5 σ per bin, bins beyond 0.5
  // (the inner ones hold a handful of pairs).
  const auto brute = brute_counts(s, bins, rmax);
  const double n = double(s.size()), pair_density = n * (n - 1) / 2 / (L * L * L);
  for (int b = 5; b < bins; ++b) {
    const double expected = pair_density * shell_volume(b, rmax / bins);
    EXPECT_NEAR(brute[b], expected, 5 * std::sqrt(expected)) << "bin " << b;
  }
}

}  // namespace dpdrng_test::dpd_test_observables
