// g(r) against two outside facts: an ideal gas (independent uniform positions) has g(r) = 1 at every r, and
// the cell-list sampler must count exactly the pairs a brute-force double loop counts, for any team size. The
// mean squared displacement against its definition (Allen & Tildesley, Computer Simulation of Liquids, §8.2:
// the average over time origins and particles of |r(t0 + τ) − r(t0)|²), summed one lag at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>

#include "dpdrng/dpd/observables.hpp"
#include "dpdrng/dpd/result.hpp"

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

// 500 beads (the all-pairs path: 2 000 beads or fewer) in a box of 5.5, 25 bins to 2.5: most pairs lie beyond
// r_max, as in the paper's small box, and each bead's row of partners has its own length.
TEST(Rdf, AllPairsCountsEqualBruteForce) {
  const double L = 5.5;
  expect_counts_equal_brute_force(make_fluid(500, Box{{L, L, L}}, 1.0, 13), 25, 2.5, {1, 2});
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

// A random walk of 200 beads sampled 1 101 times: the recorder's curve and its leave-one-group-out curves equal,
// bit for bit, the definition summed one origin and one lag at a time, coordinate after coordinate, with the
// recorder's origins (every ⌊1 100/400⌋ = 2nd frame), lags (up to half the frames) and groups of beads
// (kStatBlocks contiguous ones). The lags are not a multiple of any register block, and a group's 30 coordinates
// span two transposed chunks (of ⌊2¹⁵/1 101⌋ = 29).
TEST(Msd, CurvesEqualTheDefinitionSummedOneLagAtATime) {
  const std::size_t n = 200, nf = 1101;
  System s = make_fluid(n, Box{{6.0, 6.0, 6.0}}, 1.0, 5);
  std::mt19937_64 eng(9);
  std::uniform_real_distribution<double> step(-0.3, 0.3);
  MsdRecorder rec(n, 0.5, nf);
  std::vector<std::vector<double>> frames;
  for (std::size_t f = 0; f < nf; ++f) {
    rec.sample(s);
    std::vector<double> u(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      u[3 * i] = s.x[i] + s.ix[i] * s.box.L[0];
      u[3 * i + 1] = s.y[i] + s.iy[i] * s.box.L[1];
      u[3 * i + 2] = s.z[i] + s.iz[i] * s.box.L[2];
    }
    frames.push_back(std::move(u));
    for (std::size_t i = 0; i < n; ++i) s.x[i] += step(eng), s.y[i] += step(eng), s.z[i] += step(eng);
    s.wrap();
  }
  const Msd m = rec.finish();
  const std::size_t lmax = nf / 2, stride = (nf - 1) / 400, groups = kStatBlocks;
  ASSERT_EQ(stride, 2u);
  ASSERT_EQ(m.msd.size(), lmax + 1);
  ASSERT_EQ(m.jackknife.size(), groups);
  std::vector<double> sum(lmax + 1, 0), raw(lmax + 1, 0);
  std::vector<std::vector<double>> gsum(groups, std::vector<double>(lmax + 1, 0));
  std::vector<std::size_t> cnt(lmax + 1, 0);
  for (std::size_t o = 0; o < nf; o += stride)
    for (std::size_t l = 1; l <= std::min(lmax, nf - 1 - o); ++l) {
      double total = 0;
      for (std::size_t g = 0; g < groups; ++g) {
        double part = 0;
        for (std::size_t k = 3 * (g * n / groups); k < 3 * ((g + 1) * n / groups); ++k) {
          const double d = frames[o + l][k] - frames[o][k];
          total += d * d, part += d * d;
        }
        gsum[g][l] += part;
      }
      raw[l] += total, sum[l] += total / double(n), ++cnt[l];
    }
  for (std::size_t l = 1; l <= lmax; ++l) {
    EXPECT_EQ(m.msd[l], sum[l] / double(cnt[l])) << "lag " << l;
    for (std::size_t g = 0; g < groups; ++g) {
      const double beads = double(n - ((g + 1) * n / groups - g * n / groups));
      EXPECT_EQ(m.jackknife[g][l], (raw[l] - gsum[g][l]) / (beads * double(cnt[l]))) << "lag " << l << " group " << g;
    }
  }
}

}  // namespace dpdrng_test::dpd_test_observables
