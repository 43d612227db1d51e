// compact_in_range against the plain loop it replaces (keep r² < rc2 in order, NaN out): the same pairs, in the
// same order, with the same bits, for every length around the 64-pair runs of its bit mask.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "dpdrng/dpd/pair_loop.hpp"

namespace dpdrng_test::dpd_test_compact {

using dpdrng::dpd::compact_in_range;

namespace {

struct Rows {
  std::vector<double> dx, dy, dz, r2;
  std::vector<std::uint32_t> j;
};

Rows random_rows(std::size_t m, double inside_fraction, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Rows r;
  for (std::size_t t = 0; t < m; ++t) {
    r.dx.push_back(u(g) - 0.5), r.dy.push_back(u(g) - 0.5), r.dz.push_back(u(g) - 0.5);
    r.r2.push_back(u(g) < inside_fraction ? u(g) : 1.0 + u(g));
  }
  r.j.assign(m, 0);
  return r;
}

// The branchy loop, one pair at a time: the reference. Partners first_j + t, or ids[t] when given.
std::size_t plain(std::uint32_t first_j, double rc2, Rows& r, const std::uint32_t* ids = nullptr) {
  std::size_t k = 0;
  for (std::size_t t = 0; t < r.r2.size(); ++t) {
    if (!(r.r2[t] < rc2)) continue;
    r.j[k] = ids ? ids[t] : first_j + std::uint32_t(t);
    r.dx[k] = r.dx[t], r.dy[k] = r.dy[t], r.dz[k] = r.dz[t], r.r2[k] = r.r2[t];
    ++k;
  }
  return k;
}

}  // namespace

TEST(CompactInRange, MatchesThePlainLoopAtEveryLength) {
  for (const std::size_t m : {0, 1, 2, 63, 64, 65, 127, 128, 129, 255, 1000})
    for (const double fraction : {0.0, 0.05, 0.5, 1.0}) {
      Rows a = random_rows(m, fraction, 17 + m);
      if (m > 3) a.r2[1] = std::numeric_limits<double>::quiet_NaN(), a.r2[2] = 1.0;  // NaN and r² = rc2: out
      Rows b = a;
      const std::size_t ka =
          compact_in_range(5, m, 1.0, a.dx.data(), a.dy.data(), a.dz.data(), a.r2.data(), a.j.data());
      const std::size_t kb = plain(5, 1.0, b);
      ASSERT_EQ(ka, kb) << m << " " << fraction;
      for (std::size_t t = 0; t < ka; ++t) {
        EXPECT_EQ(a.j[t], b.j[t]);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.dx[t]), std::bit_cast<std::uint64_t>(b.dx[t]));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.dy[t]), std::bit_cast<std::uint64_t>(b.dy[t]));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.dz[t]), std::bit_cast<std::uint64_t>(b.dz[t]));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.r2[t]), std::bit_cast<std::uint64_t>(b.r2[t]));
      }
      if (fraction == 1.0 && m > 3) {
        EXPECT_EQ(ka, m - 2);
      }
      if (fraction == 0.0) {
        EXPECT_EQ(ka, 0u);
      }
    }
}

// The cells loop's form: partners read from a candidate list (here in descending order, so that an index
// written from t instead of ids[t] would show).
TEST(CompactInRange, PartnerListMatchesThePlainLoop) {
  for (const std::size_t m : {0, 1, 41, 64, 65, 200}) {
    Rows a = random_rows(m, 0.15, 91 + m);
    std::vector<std::uint32_t> ids(m);
    for (std::size_t t = 0; t < m; ++t) ids[t] = std::uint32_t(10'000 - 3 * t);
    Rows b = a;
    const std::size_t ka = compact_in_range([&](std::size_t t) { return ids[t]; }, m, 1.0, a.dx.data(),
                                            a.dy.data(), a.dz.data(), a.r2.data(), a.j.data());
    const std::size_t kb = plain(0, 1.0, b, ids.data());
    ASSERT_EQ(ka, kb) << m;
    for (std::size_t t = 0; t < ka; ++t) {
      EXPECT_EQ(a.j[t], b.j[t]);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a.r2[t]), std::bit_cast<std::uint64_t>(b.r2[t]));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a.dz[t]), std::bit_cast<std::uint64_t>(b.dz[t]));
    }
  }
}

}  // namespace dpdrng_test::dpd_test_compact
