// The pair loop's SIMD candidate filters (compress-store and mask-then-recompute) against the scalar loop it stands for (min_image, r², keep r² < r_c²
// in order, NaN out): the same pairs, in the same order, with the same bits, for every range length around
// the vector width, ranges that start anywhere, and appends after pairs already kept.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "dpdrng/dpd/pair_filter.hpp"

namespace dpdrng_test::dpd_test_pair_filter {

using dpdrng::dpd::Box;
namespace pf = dpdrng::dpd::pair_filter;

namespace {

struct Pairs {
  std::vector<double> dx, dy, dz, r2;
  std::vector<std::uint32_t> j;
  explicit Pairs(std::size_t n) : dx(n, -7.0), dy(n, -7.0), dz(n, -7.0), r2(n, -7.0), j(n, 99) {}
  pf::Out out() { return {dx.data(), dy.data(), dz.data(), r2.data(), j.data()}; }
};

// The reference: one candidate at a time, with a branch.
std::size_t plain(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                  std::uint32_t lo, std::uint32_t hi, const pf::Centre& c, Pairs& p, std::size_t kept) {
  for (std::uint32_t k = lo; k < hi; ++k) {
    using dpdrng::dpd::min_image;
    const double a = min_image(x[k] - c.x, c.Lx, c.hx), b = min_image(y[k] - c.y, c.Ly, c.hy),
                 d = min_image(z[k] - c.z, c.Lz, c.hz);
    const double r2 = a * a + b * b + d * d;
    if (!(r2 < c.rc2)) continue;
    p.dx[kept] = a, p.dy[kept] = b, p.dz[kept] = d, p.r2[kept] = r2, p.j[kept] = k;
    ++kept;
  }
  return kept;
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

}  // namespace

TEST(PairFilter, MatchesTheScalarLoopForEveryRange) {
  // A 4 × 5 × 6 box of 600 beads: ~1 in 4 candidates of a bead lie within r_c = 1.2, and the minimum image
  // shifts by +L and −L along every axis.
  Box box;
  box.L = {4.0, 5.0, 6.0};
  std::mt19937_64 g(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 600;
  std::vector<double> x(n), y(n), z(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = 4.0 * u(g), y[k] = 5.0 * u(g), z[k] = 6.0 * u(g);
  x[7] = std::numeric_limits<double>::quiet_NaN();  // r² NaN: never kept
  x[8] = x[0], y[8] = y[0], z[8] = z[0];              // r = 0 from bead 0: kept
  x[9] = x[0] + 1.2, y[9] = y[0], z[9] = z[0];        // r² at r_c², up to rounding: as the scalar loop decides
  for (const std::uint32_t centre : {0u, 1u, 300u, 599u})
    for (std::uint32_t lo = 0; lo < 20; lo += 3)
      for (std::uint32_t len : {0u, 1u, 2u, 3u, 4u, 5u, 7u, 8u, 9u, 15u, 16u, 17u, 63u, 64u, 65u, 580u}) {
        const std::uint32_t hi = std::min<std::uint32_t>(lo + len, n);
        const pf::Centre c = pf::centre(box, x[centre], y[centre], z[centre], 1.44);
        const std::size_t before = 3;  // pairs already kept: appended after them
        Pairs b(before + (hi - lo) + pf::kSlack);
        const std::size_t kb = plain(x, y, z, lo, hi, c, b, before);
        for (const bool sparse : {false, true}) {
          Pairs a(before + (hi - lo) + pf::kSlack);
          const std::size_t ka = sparse ? pf::append_sparse(x.data(), y.data(), z.data(), lo, hi, c, a.out(), before)
                                        : pf::append_in_range(x.data(), y.data(), z.data(), lo, hi, c, a.out(), before);
          ASSERT_EQ(ka, kb) << centre << " " << lo << " " << len << " sparse " << sparse;
          for (std::size_t t = 0; t < before; ++t) EXPECT_EQ(a.r2[t], -7.0);  // untouched
          for (std::size_t t = before; t < ka; ++t) {
            EXPECT_EQ(a.j[t], b.j[t]);
            EXPECT_EQ(bits(a.dx[t]), bits(b.dx[t]));
            EXPECT_EQ(bits(a.dy[t]), bits(b.dy[t]));
            EXPECT_EQ(bits(a.dz[t]), bits(b.dz[t]));
            EXPECT_EQ(bits(a.r2[t]), bits(b.r2[t]));
          }
        }
      }
}

// A range whose every candidate is inside r_c keeps them all, in order; one with none keeps nothing.
TEST(PairFilter, KeepsAllOrNothing) {
  Box box;
  box.L = {10.0, 10.0, 10.0};
  std::vector<double> x(21), y(21, 5.0), z(21, 5.0);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = 5.0 + 0.01 * double(k);
  Pairs p(x.size() + pf::kSlack);
  const pf::Centre near = pf::centre(box, 5.0, 5.0, 5.0, 1.0);
  ASSERT_EQ(pf::append_in_range(x.data(), y.data(), z.data(), 0, 21, near, p.out(), 0), 21u);
  for (std::uint32_t t = 0; t < 21; ++t) EXPECT_EQ(p.j[t], t);
  const pf::Centre far = pf::centre(box, 0.0, 0.0, 0.0, 1.0);
  EXPECT_EQ(pf::append_in_range(x.data(), y.data(), z.data(), 0, 21, far, p.out(), 0), 0u);
}

}  // namespace dpdrng_test::dpd_test_pair_filter
