// The pair loop's SIMD candidate filters (compress-store over a gathered list, and mask-then-recompute)
// against the scalar loop they stand for (min_image, r², keep r² < r_c² in order, NaN out): the same pairs, in
// the same order, with the same bits, for every range length around the vector width, ranges that start
// anywhere, lists gathered from several ranges, and appends after pairs already kept.
#include <gtest/gtest.h>

#include <bit>
#include <algorithm>
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

// a holds the same ka pairs after the `before` already kept as the reference b's kb, to the bit; the first
// `before` are untouched.
void expect_same(const Pairs& a, std::size_t ka, const Pairs& b, std::size_t kb, std::size_t before) {
  ASSERT_EQ(ka, kb);
  for (std::size_t t = 0; t < before; ++t) EXPECT_EQ(a.r2[t], -7.0);
  for (std::size_t t = before; t < ka; ++t) {
    EXPECT_EQ(a.j[t], b.j[t]) << t;
    EXPECT_EQ(bits(a.dx[t]), bits(b.dx[t]));
    EXPECT_EQ(bits(a.dy[t]), bits(b.dy[t]));
    EXPECT_EQ(bits(a.dz[t]), bits(b.dz[t]));
    EXPECT_EQ(bits(a.r2[t]), bits(b.r2[t]));
  }
}

// n beads uniform in `box`, positions readable `pad` entries past the last (zeros).
struct Beads {
  std::vector<double> x, y, z;
  Beads(const Box& box, std::size_t n, std::size_t pad, std::uint64_t seed) : x(n + pad), y(n + pad), z(n + pad) {
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (std::size_t k = 0; k < n; ++k) x[k] = box.L[0] * u(g), y[k] = box.L[1] * u(g), z[k] = box.L[2] * u(g);
  }
};

}  // namespace

TEST(PairFilter, MatchesTheScalarLoopForEveryRange) {
  // A 4 × 5 × 6 box of 600 beads: ~1 in 4 candidates of a bead lie within r_c = 1.2, and the minimum image
  // shifts by +L and −L along every axis.
  Box box;
  box.L = {4.0, 5.0, 6.0};
  const std::size_t n = 600;
  Beads beads(box, n, 0, 2024);
  std::vector<double>& x = beads.x, &y = beads.y, &z = beads.z;
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
        Pairs a(before + (hi - lo) + pf::kSlack);
        const std::size_t ka = pf::append_sparse(x.data(), y.data(), z.data(), lo, hi, c, a.out(), before);
        expect_same(a, ka, b, kb, before);
      }
}

// A list gathered from five ranges, one empty (as a cell's candidates are, run by run), and filtered from any start:
// the scalar loop over the same candidates, with min_image; and without it (Wrap = false) where every
// candidate lies within half an edge of the centre, which gives the same bits.
TEST(PairFilter, ListedCandidatesMatchTheScalarLoop) {
  Box box;
  box.L = {4.0, 5.0, 6.0};
  const std::size_t n = 300;
  Beads beads(box, n, pf::kSlack, 7);
  std::vector<double>& x = beads.x, &y = beads.y, &z = beads.z;
  std::mt19937_64 g(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  x[40] = std::numeric_limits<double>::quiet_NaN();
  // Ranges of every length around the vector width, one of them empty.
  const std::uint32_t ranges[][2] = {{30, 47}, {100, 100}, {150, 159}, {200, 201}, {250, 266}};
  std::vector<double> lx(n + 2 * pf::kSlack), ly(lx.size()), lz(lx.size());
  std::vector<std::uint32_t> id(lx.size());
  std::size_t t = 0;
  for (const auto& r : ranges) t = pf::list_range(x.data(), y.data(), z.data(), r[0], r[1], lx.data(), ly.data(),
                                                  lz.data(), id.data(), t);
  ASSERT_EQ(t, 17u + 0u + 9u + 1u + 16u);
  std::vector<double> cx, cy, cz;  // the listed candidates, for the reference
  for (const auto& r : ranges)
    for (std::uint32_t k = r[0]; k < r[1]; ++k) cx.push_back(x[k]), cy.push_back(y[k]), cz.push_back(z[k]);
  for (std::size_t k = 0; k < t; ++k) {
    ASSERT_EQ(bits(lx[k]), bits(cx[k]));
    ASSERT_EQ(bits(lz[k]), bits(cz[k]));
  }
  const pf::Listed list{lx.data(), ly.data(), lz.data(), id.data()};
  for (const std::uint32_t centre : {0u, 3u, 99u, 280u})
    for (std::uint32_t lo = 0; lo <= t; ++lo) {
      const pf::Centre c = pf::centre(box, x[centre], y[centre], z[centre], 1.44);
      Pairs b(t + pf::kSlack + 3), a(t + pf::kSlack + 3);
      const std::size_t kb = plain(cx, cy, cz, lo, std::uint32_t(t), c, b, 3);
      for (std::size_t q = 3; q < kb; ++q) b.j[q] = id[b.j[q]];  // list index → partner id
      expect_same(a, pf::append_listed<true>(list, lo, std::uint32_t(t), c, a.out(), 3), b, kb, 3);
    }
  // Within half an edge of the centre (2, 2.5, 3) along every axis: min_image changes nothing.
  const pf::Centre mid = pf::centre(box, 2.0, 2.5, 3.0, 1.44);
  for (std::size_t k = 0; k < t; ++k) lx[k] = 0.1 + 3.8 * u(g), ly[k] = 0.1 + 4.8 * u(g), lz[k] = 0.1 + 5.8 * u(g);
  cx.assign(lx.begin(), lx.begin() + std::ptrdiff_t(t)), cy.assign(ly.begin(), ly.begin() + std::ptrdiff_t(t));
  cz.assign(lz.begin(), lz.begin() + std::ptrdiff_t(t));
  for (std::uint32_t lo = 0; lo <= t; ++lo) {
    Pairs b(t + pf::kSlack), a(t + pf::kSlack);
    const std::size_t kb = plain(cx, cy, cz, lo, std::uint32_t(t), mid, b, 0);
    for (std::size_t q = 0; q < kb; ++q) b.j[q] = id[b.j[q]];
    expect_same(a, pf::append_listed<false>(list, lo, std::uint32_t(t), mid, a.out(), 0), b, kb, 0);
  }
}

// The all-pairs filter with the single-precision prefilter (append_rounded) against the exact one
// (append_sparse): the same pairs, bits and order, in a small box (images shift every way) and a large one
// (positions far from the origin, where rounding to float moves them most), with candidates placed just
// inside and just outside r_c along random directions, a NaN, and rows of every length.
TEST(PairFilter, RoundedPrefilterKeepsExactlyTheExactFiltersPairs) {
  std::mt19937_64 g(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double L : {4.4, 1000.0}) {
    Box box;
    box.L = {L, L * 1.1, L * 0.9};
    const std::size_t n = 700;
    Beads beads(box, n, 0, 99 + std::uint64_t(L));
    std::vector<double>& x = beads.x, &y = beads.y, &z = beads.z;
    // Beads 1 … 400 around bead 0 (and across the box's faces) at r = r_c (1 ± 1e-9 … 1 ± 1e-6).
    for (std::size_t k = 1; k <= 400; ++k) {
      const double c = 2 * u(g) - 1, phi = 6.283185307179586 * u(g), sn = std::sqrt(1 - c * c);
      const double r = 1.0 + (k % 2 ? 1 : -1) * std::pow(10.0, -9.0 + 3.0 * u(g));
      const double px = std::fmod(x[0] + r * sn * std::cos(phi) + box.L[0], box.L[0]);
      const double py = std::fmod(y[0] + r * sn * std::sin(phi) + box.L[1], box.L[1]);
      const double pz = std::fmod(z[0] + r * c + box.L[2], box.L[2]);
      x[k] = px, y[k] = py, z[k] = pz;
    }
    x[500] = std::numeric_limits<double>::quiet_NaN();
    std::vector<float> xf(n + pf::kSlackF), yf(xf.size()), zf(xf.size());
    double extent = std::max({box.L[0], box.L[1], box.L[2]});
    for (std::size_t k = 0; k < n; ++k) {
      xf[k] = float(x[k]), yf[k] = float(y[k]), zf[k] = float(z[k]);
      if (!std::isnan(x[k])) extent = std::max({extent, x[k], y[k], z[k]});
    }
    const float threshold = pf::rounded_threshold(1.0, extent);
    std::vector<double> lx(n + pf::kSlackF), ly(lx.size()), lz(lx.size());
    std::vector<std::uint32_t> id(lx.size());
    std::size_t near = 0;
    for (const std::uint32_t centre : {0u, 0u, 7u, 350u, 699u})
      for (const std::uint32_t lo : {0u, 1u, 5u, 17u, 650u}) {
        const pf::Centre c = pf::centre(box, x[centre], y[centre], z[centre], 1.0);
        const auto Lx = float(box.L[0]), Ly = float(box.L[1]), Lz = float(box.L[2]);
        const pf::Rounded f{xf.data(), yf.data(), zf.data(), xf[centre], yf[centre], zf[centre], Lx, Ly, Lz,
                            threshold};
        Pairs a(n + pf::kSlack), b(n + pf::kSlack);
        const std::size_t kb = pf::append_sparse(x.data(), y.data(), z.data(), lo, n, c, b.out(), 0);
        const std::size_t ka = pf::append_rounded(x.data(), y.data(), z.data(), f, lo, n, c,
                                                  {lx.data(), ly.data(), lz.data(), id.data()}, a.out(), 0);
        expect_same(a, ka, b, kb, 0);
        if (centre == 0) near += kb;
      }
    EXPECT_GT(near, 400u) << "L = " << L;  // about half the 400 placed at r_c are inside, in each of two rows
  }
}

// The all-pairs filter with the 16-bit grid prefilter (append_grid) against the exact one (append_sparse):
// the same pairs, bits and order, with candidates placed just inside and just outside r_c along random
// directions and across the box's faces, positions an image or more outside the box (the grid wraps them),
// a NaN and an infinity, rows of every length, in the paper's box, a box just over 2 r_c across (where
// the images and the cutoff nearly meet) and a non-cubic one. Without AVX2 the grid serves no box and
// append_grid is the exact filter.
TEST(PairFilter, GridPrefilterKeepsExactlyTheExactFiltersPairs) {
  std::mt19937_64 g(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const std::array<double, 3> edges : {std::array<double, 3>{4.4, 4.4, 4.4}, {2.001, 2.001, 2.001},
                                            {4.4, 4.84, 3.96}}) {
    Box box;
    box.L = edges;
    const std::size_t n = 700;
    Beads beads(box, n, 0, 77);
    std::vector<double>& x = beads.x, &y = beads.y, &z = beads.z;
    for (std::size_t k = 1; k <= 400; ++k) {
      const double c = 2 * u(g) - 1, phi = 6.283185307179586 * u(g), sn = std::sqrt(1 - c * c);
      const double r = 1.0 + (k % 2 ? 1 : -1) * std::pow(10.0, -12.0 + 9.0 * u(g));
      x[k] = std::fmod(x[0] + r * sn * std::cos(phi) + box.L[0], box.L[0]);
      y[k] = std::fmod(y[0] + r * sn * std::sin(phi) + box.L[1], box.L[1]);
      z[k] = std::fmod(z[0] + r * c + box.L[2], box.L[2]);
      if (k % 7 == 0) x[k] += 3 * box.L[0], y[k] -= 2 * box.L[1];  // unwrapped images: the same pair
    }
    x[500] = std::numeric_limits<double>::quiet_NaN();
    z[501] = std::numeric_limits<double>::infinity();
    double extent = std::max({box.L[0], box.L[1], box.L[2]});
    for (std::size_t k = 0; k < n; ++k)
      for (const double v : {x[k], y[k], z[k]})
        if (std::isfinite(v)) extent = std::max(extent, std::abs(v));
    const bool serves = pf::grid_serves(box, 1.0, extent);
#if defined(__AVX512BW__) && defined(__AVX512F__) && defined(__AVX512VL__) || defined(__AVX2__)
    EXPECT_TRUE(serves) << "L = " << box.L[0];
#else
    EXPECT_FALSE(serves);
#endif
    std::array<std::vector<std::uint16_t>, 3> q;
    for (std::size_t a = 0; a < 3; ++a) {
      const std::vector<double>& p = a == 0 ? x : a == 1 ? y : z;
      q[a].resize(n + pf::kSlackG);
      for (std::size_t k = 0; k < n; ++k) q[a][k] = pf::to_grid(p[k], 65536.0 / box.L[a]);
    }
    const std::uint16_t threshold =
        pf::grid_threshold(1.0, 65536.0 / std::min({box.L[0], box.L[1], box.L[2]}));
    std::vector<double> lx(n + pf::kSlackF), ly(lx.size()), lz(lx.size());
    std::vector<std::uint32_t> id(lx.size());
    std::size_t near = 0;
    for (const std::uint32_t centre : {0u, 7u, 350u, 500u, 699u})
      for (const std::uint32_t lo : {0u, 1u, 5u, 17u, 33u, 650u}) {
        const pf::Centre c = pf::centre(box, x[centre], y[centre], z[centre], 1.0);
        const pf::Grid16 f{q[0].data(), q[1].data(), q[2].data(), q[0][centre], q[1][centre], q[2][centre],
                           threshold};
        Pairs a(n + pf::kSlack), b(n + pf::kSlack);
        const std::size_t kb = pf::append_sparse(x.data(), y.data(), z.data(), lo, n, c, b.out(), 0);
        const std::size_t ka = pf::append_grid(x.data(), y.data(), z.data(), f, lo, n, c,
                                               {lx.data(), ly.data(), lz.data(), id.data()}, a.out(), 0);
        expect_same(a, ka, b, kb, 0);
        if (centre == 0) near += kb;
      }
    EXPECT_GT(near, 800u) << "L = " << box.L[0];  // about half the 400 placed at r_c, in each row from lo < 400
  }
}

// The grid's coordinates: round(x·2¹⁶/L) mod 2¹⁶, the same for every image of a position, 0 where x is not
// finite; and its threshold, one above the largest sum a pair inside r_c can reach in the paper's box.
TEST(PairFilter, GridCoordinatesWrapAndTheThresholdBoundsTheCutoff) {
  const double L = 4.4, scale = 65536.0 / L;
  EXPECT_EQ(pf::to_grid(0.0, scale), 0);
  EXPECT_EQ(pf::to_grid(L / 2, scale), 32768);
  EXPECT_EQ(pf::to_grid(L - 1e-9, scale), 0);  // rounds up to 2¹⁶, which wraps
  EXPECT_EQ(pf::to_grid(1.1, scale), 16384);
  for (const double x : {0.3, 1.7, 4.1})
    for (const int image : {-3, -1, 1, 2, 1000})
      EXPECT_EQ(pf::to_grid(x + image * L, scale), pf::to_grid(x, scale)) << x << " " << image;
  EXPECT_EQ(pf::to_grid(std::numeric_limits<double>::quiet_NaN(), scale), 0);
  EXPECT_EQ(pf::to_grid(-std::numeric_limits<double>::infinity(), scale), 0);
  // r_c·S = 14 894.5…: (14 896.5…)²/2¹⁶ = 3 386.03…, so 3 386 + 2.
  EXPECT_EQ(pf::grid_threshold(1.0, scale), 3388);
}

// A list whose every candidate is inside r_c keeps them all, in order; one with none keeps nothing.
TEST(PairFilter, KeepsAllOrNothing) {
  Box box;
  box.L = {10.0, 10.0, 10.0};
  std::vector<double> x(21 + pf::kSlack), y(x.size(), 5.0), z(x.size(), 5.0);
  std::vector<std::uint32_t> id(x.size());
  for (std::size_t k = 0; k < 21; ++k) x[k] = 5.0 + 0.01 * double(k), id[k] = std::uint32_t(100 + k);
  const pf::Listed list{x.data(), y.data(), z.data(), id.data()};
  Pairs p(x.size() + pf::kSlack);
  const pf::Centre near = pf::centre(box, 5.0, 5.0, 5.0, 1.0);
  ASSERT_EQ(pf::append_listed<true>(list, 0, 21, near, p.out(), 0), 21u);
  for (std::uint32_t t = 0; t < 21; ++t) EXPECT_EQ(p.j[t], 100 + t);
  const pf::Centre far = pf::centre(box, 0.0, 0.0, 0.0, 1.0);
  EXPECT_EQ(pf::append_listed<true>(list, 0, 21, far, p.out(), 0), 0u);
}

}  // namespace dpdrng_test::dpd_test_pair_filter
