// The cells-mode pair search: every pair inside r_c owned by exactly one cell, same-colour cells writing
// disjoint beads, and the sorted, coloured loop giving the all-pairs forces and thread-independent bits.
#include <gtest/gtest.h>
#include <omp.h>

#include <bit>
#include <cmath>
#include <set>
#include <utility>

#include "dpdrng/dpd/neighbours.hpp"
#include "dpdrng/dpd/pair_forces.hpp"

namespace dpdrng_test::dpd_test_neighbours {

using namespace dpdrng;
using namespace dpdrng::dpd;

namespace {
System fluid(std::size_t n, double L, std::uint64_t seed = 2021) { return make_fluid(n, Box{{L, L, L}}, 1.0, seed); }

double r2_between(const System& s, std::uint32_t i, std::uint32_t j) {
  const double L = s.box.L[0];
  const double dx = min_image(s.x[j] - s.x[i], L, L / 2), dy = min_image(s.y[j] - s.y[i], L, L / 2),
               dz = min_image(s.z[j] - s.z[i], L, L / 2);
  return dx * dx + dy * dy + dz * dz;
}

// Pairs (i < j, the System's indices) inside r_c = 1 that the cells own: within a cell, and with its forward cells.
std::multiset<std::pair<std::uint32_t, std::uint32_t>> owned_pairs(const System& s, const SortedCells& g) {
  std::multiset<std::pair<std::uint32_t, std::uint32_t>> out;
  const auto& order = g.order();
  auto consider = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t i = order[a], j = order[b];
    if (r2_between(s, i, j) < 1.0) out.insert({std::min(i, j), std::max(i, j)});
  };
  for (int c = 0; c < g.cells(); ++c)
    for (std::uint32_t a = g.begin(c); a < g.end(c); ++a) {
      for (std::uint32_t b = a + 1; b < g.end(c); ++b) consider(a, b);
      for (int f = 0; f < g.forward_count(); ++f)
        for (std::uint32_t b = g.begin(g.forward(c)[f]); b < g.end(g.forward(c)[f]); ++b) consider(a, b);
    }
  return out;
}

std::multiset<std::pair<std::uint32_t, std::uint32_t>> brute_pairs(const System& s) {
  std::multiset<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    for (std::uint32_t j = i + 1; j < s.size(); ++j)
      if (r2_between(s, i, j) < 1.0) out.insert({i, j});
  return out;
}
}  // namespace

// 1 500 beads in a box of 8 (8 × 8 × 8 cells) and 256 in the paper's box of 4.40 (3 × 3 × 4): the cells find
// exactly the brute-force pair set, each pair once; a box of 3.5 (too small for the grid) falls back to one cell.
TEST(SortedCells, EveryPairInsideTheCutoffIsOwnedOnce) {
  for (auto [n, L] : {std::pair<std::size_t, double>{1500, 8.0}, {256, std::cbrt(256 / 3.0)}, {128, 3.5}}) {
    const System s = fluid(n, L);
    SortedCells g;
    g.build(s, 1.0);
    EXPECT_EQ(g.gridded(), L > 4.0) << "L = " << L;
    const auto owned = owned_pairs(s, g), brute = brute_pairs(s);
    ASSERT_GT(brute.size(), n);
    EXPECT_EQ(owned, brute) << "L = " << L;
    // The sort is a permutation, by cell.
    std::set<std::uint32_t> ids(g.order().begin(), g.order().end());
    EXPECT_EQ(ids.size(), n);
  }
}

// What lets the filter skip min_image: for a cell that does not wrap, every bead of the cell and every
// candidate (own cell, forward cells) lie within half an edge of each other along each axis, so the plain
// difference is the minimum image. An 8 × 8 × 8 grid (some cells wrap, some do not), and one of 4 × 4 × 4 and
// the paper's 3 × 3 × 4, where every cell counts as wrapping (fewer than 5 cells along an axis).
TEST(SortedCells, CellsThatDoNotWrapNeedNoMinimumImage) {
  for (auto [n, L] : {std::pair<std::size_t, double>{1500, 8.0}, {192, 4.0}, {256, std::cbrt(256 / 3.0)}}) {
    const System s = fluid(n, L);
    SortedCells g;
    g.build(s, 1.0);
    ASSERT_TRUE(g.gridded());
    int plain = 0;
    for (int c = 0; c < g.cells(); ++c) {
      if (g.wraps(c)) continue;
      ++plain;
      std::vector<int> cand{c};
      for (int f = 0; f < g.forward_count(); ++f) cand.push_back(g.forward(c)[f]);
      for (std::uint32_t a = g.begin(c); a < g.end(c); ++a)
        for (const int d : cand)
          for (std::uint32_t b = g.begin(d); b < g.end(d); ++b) {
            const std::uint32_t i = g.order()[a], j = g.order()[b];
            for (const auto& r : {&System::x, &System::y, &System::z})
              ASSERT_LE(std::abs((s.*r)[j] - (s.*r)[i]), L / 2) << "cell " << c;
          }
    }
    // Cells 1 … 6 along x and y and 0 … 6 along z of the 8-grid do not wrap.
    EXPECT_EQ(plain, L == 8.0 ? 6 * 6 * 7 : 0) << "L = " << L;
  }
}

// What lets the layers of a colour run in parallel: a cell writes to itself and its forward cells, and no two
// layers of one colour write to the same cell.
TEST(SortedCells, LayersOfOneColourWriteDisjointCells) {
  const System s = fluid(1500, 8.0);
  SortedCells g;
  g.build(s, 1.0);
  ASSERT_TRUE(g.gridded());
  ASSERT_EQ(g.colours(), 2);
  ASSERT_EQ(g.layers() * g.layer_cells(), g.cells());
  for (int k = 0; k < g.colours(); ++k) {
    std::set<int> written;
    std::size_t writes = 0;
    for (int z = k; z < g.layers(); z += g.colours()) {
      std::set<int> layer;
      for (int c = z * g.layer_cells(); c < (z + 1) * g.layer_cells(); ++c) {
        std::set<int> mine{c};
        for (int f = 0; f < g.forward_count(); ++f) mine.insert(g.forward(c)[f]);
        EXPECT_EQ(mine.size(), 1u + SortedCells::kForward);  // forward cells are distinct, and not c itself
        layer.insert(mine.begin(), mine.end());
      }
      writes += layer.size();
      written.insert(layer.begin(), layer.end());
    }
    EXPECT_EQ(written.size(), writes) << "colour " << k;
  }
}

// The sort runs on a team, each thread placing a contiguous range of beads: the serial sort's order (by cell,
// then by bead index) and cell bounds for any team, an odd one and one larger than the cores included.
TEST(SortedCells, SameSortForAnyThreadCount) {
  const System s = fluid(3000, 10.0);
  SortedCells one;
  one.build(s, 1.0);
  for (int c = 0; c < one.cells(); ++c)
    for (std::uint32_t k = one.begin(c) + 1; k < one.end(c); ++k) ASSERT_LT(one.order()[k - 1], one.order()[k]);
  for (int threads : {2, 3, 8}) {
    SortedCells many;
#pragma omp parallel num_threads(threads)
    many.build(s, 1.0);
    EXPECT_EQ(many.order(), one.order()) << "threads " << threads;
    for (int c = 0; c < one.cells(); ++c)
      ASSERT_TRUE(many.begin(c) == one.begin(c) && many.end(c) == one.end(c)) << "threads " << threads << " cell " << c;
  }
}

namespace {
struct Forces {
  std::vector<double> f;
  ForceSums sums;
};
Forces forces(const System& start, PairMode mode, const char* gen, int threads) {
  System s = start;
  WaterConfig cfg;
  cfg.pairs = mode;
  cfg.generator = rng::validated({gen, 0});
  cfg.threads = threads;
  cfg.team_beads = 0;
  auto pf = make_pair_forces(cfg, make_kernel(25, 1, 4.5, 1, 0.04), s.size());
  Taps taps;
  Forces out;
  out.sums = pf->compute(s, VelocityView{s.vx.data(), s.vy.data(), s.vz.data()}, 11, false, false, false, taps);
  out.f = s.fx;
  out.f.insert(out.f.end(), s.fy.begin(), s.fy.end());
  out.f.insert(out.f.end(), s.fz.begin(), s.fz.end());
  return out;
}
}  // namespace

// The sorted, coloured cells loop sees the same pairs with the same separations and ζ as the all-pairs loop
// (generator inputs use the System's indices in canonical order), so only the summation order differs.
TEST(CellsLoop, SameForcesAsAllPairs) {
  const System s = fluid(1500, 8.0);
  const Forces all = forces(s, PairMode::all, "tea32", 1), cells = forces(s, PairMode::cells, "tea32", 1);
  EXPECT_EQ(cells.sums.in_range, all.sums.in_range);
  double fmax = 0;
  for (double v : all.f) fmax = std::max(fmax, std::fabs(v));
  for (std::size_t k = 0; k < all.f.size(); ++k) ASSERT_NEAR(cells.f[k], all.f[k], 1e-12 * fmax) << k;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(cells.sums.virial[a], all.sums.virial[a], 1e-10 * std::fabs(all.sums.virial[a]));
  EXPECT_EQ(cells.sums.min_r2, all.sums.min_r2);
}

// One force evaluation gives the same bits on any team, for a hash and for the mt19937 stream (whose slots
// are counted per cell before the layers run). The 3 000-bead box (10 × 10 × 10 cells, five layers per colour)
// runs its layers on two threads, or on one for a team of 3 (too few layers; the sort and copies still use 3).
// The 12 288-bead box (16 layers) gives 3 threads blocks of 5, 5 and 6 layers, and 4 threads on a 2-core
// machine are paused by the OS mid-layer, so the others take over their layers and wait on their neighbours.
TEST(CellsLoop, SameBitsForAnyThreadCount) {
  struct Case {
    std::size_t n;
    double L;
    std::vector<int> teams;
  };
  for (const Case& k : {Case{3000, 10.0, {2, 3}}, Case{12288, 16.0, {2, 3, 4}}}) {
    const System s = fluid(k.n, k.L);
    for (const char* gen : {"tea32", "mt19937"}) {
      const Forces one = forces(s, PairMode::cells, gen, 1);
      for (int threads : k.teams) {
        const Forces many = forces(s, PairMode::cells, gen, threads);
        for (std::size_t c = 0; c < one.f.size(); ++c)
          ASSERT_EQ(std::bit_cast<std::uint64_t>(one.f[c]), std::bit_cast<std::uint64_t>(many.f[c]))
              << k.n << " beads, " << gen << ", threads " << threads << ", component " << c;
        for (int a = 0; a < 3; ++a)
          EXPECT_EQ(std::bit_cast<std::uint64_t>(one.sums.virial[a]), std::bit_cast<std::uint64_t>(many.sums.virial[a]));
        EXPECT_EQ(one.sums.min_r2, many.sums.min_r2);
        EXPECT_EQ(one.sums.in_range, many.sums.in_range);
      }
    }
  }
}

// A team smaller than the one asked for (OMP_THREAD_LIMIT, or a region inside another with nesting off) still
// runs every layer, with the same bits. Here the loop asks for 2 threads inside an active region, so it gets 1;
// layer queues planned for 2 threads once left an odd layer waiting forever for an even one nobody claimed.
TEST(CellsLoop, SmallerTeamThanAskedRunsEveryLayer) {
  const System s = fluid(12288, 16.0);
  const Forces one = forces(s, PairMode::cells, "tea32", 1);
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(1);
  Forces inner;
#pragma omp parallel num_threads(2)
  if (omp_get_thread_num() == 0) inner = forces(s, PairMode::cells, "tea32", 2);
  omp_set_max_active_levels(levels);
  ASSERT_EQ(inner.f.size(), one.f.size());
  for (std::size_t c = 0; c < one.f.size(); ++c)
    ASSERT_EQ(std::bit_cast<std::uint64_t>(one.f[c]), std::bit_cast<std::uint64_t>(inner.f[c])) << "component " << c;
}

}  // namespace dpdrng_test::dpd_test_neighbours
