// The minimum image against its textbook form (two branches: subtract L above L/2, add L below −L/2), bit for
// bit, at the edges where a select could round or sign differently: ±L/2 exactly and one ulp either side, ±L,
// ±0, subnormals, and boxes from 1e-300 to 1e300. Also through a loop the compiler vectorises, as the pair
// loops use it.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "dpdrng/dpd/system.hpp"

namespace dpdrng_test::dpd_test_min_image {

using dpdrng::dpd::min_image;

namespace {
double reference(double d, double L, double half) {
  if (d > half) return d - L;
  if (d < -half) return d + L;
  return d;
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// Edge values of d for a box of side L: within the domain |d| < 1.5 L.
std::vector<double> edges(double L) {
  const double h = L / 2, inf = std::numeric_limits<double>::infinity();
  const double den = std::numeric_limits<double>::denorm_min(), tiny = std::numeric_limits<double>::min();
  std::vector<double> out;
  for (double v : {0.0, den, tiny, 1e-300, h, L, 1.25 * L, 1.4999 * L, 0.3 * L, L - den})
    for (double s : {1.0, -1.0}) {
      out.push_back(s * v);
      out.push_back(std::nextafter(s * v, inf));
      out.push_back(std::nextafter(s * v, -inf));
    }
  return out;
}
}  // namespace

TEST(MinImage, MatchesBranchyReferenceAtEdges) {
  int checked = 0;
  for (double L : {1.0, 10.3, 7.0 / 3.0, 1e-300, 3e-7, 1e300, 123456.789}) {
    const double half = L / 2;
    for (double d : edges(L)) {
      ASSERT_EQ(bits(min_image(d, L, half)), bits(reference(d, L, half))) << "d=" << d << " L=" << L;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  // The sign of zero survives inside the box, as with the branches.
  EXPECT_TRUE(std::signbit(min_image(-0.0, 10.0, 5.0)));
  EXPECT_FALSE(std::signbit(min_image(0.0, 10.0, 5.0)));
  // Exactly ±L/2 stays; one ulp beyond wraps.
  EXPECT_EQ(min_image(5.0, 10.0, 5.0), 5.0);
  EXPECT_EQ(min_image(-5.0, 10.0, 5.0), -5.0);
  EXPECT_EQ(min_image(std::nextafter(5.0, 6.0), 10.0, 5.0), std::nextafter(5.0, 6.0) - 10.0);
}

// Differences of wrapped coordinates, as the pair loops form them, through an array loop (vectorised at -O3).
TEST(MinImage, MatchesBranchyReferenceOnWrappedDifferencesInALoop) {
  std::mt19937_64 gen(77);
  for (double L : {10.3, 6.0, 1.7}) {
    std::uniform_real_distribution<double> u(0.0, L);
    const std::size_t n = 4099;
    std::vector<double> x(n), got(n);
    for (auto& v : x) v = u(gen);
    x[7] = 0.0, x[8] = std::nextafter(L, 0.0), x[9] = L / 2;
    for (std::size_t i : {std::size_t(0), std::size_t(8), std::size_t(9), std::size_t(1234)}) {
      const double xi = x[i], half = L / 2;
      for (std::size_t t = 0; t < n; ++t) got[t] = min_image(x[t] - xi, L, half);
      for (std::size_t t = 0; t < n; ++t)
        ASSERT_EQ(bits(got[t]), bits(reference(x[t] - xi, L, half))) << "t=" << t << " L=" << L;
    }
  }
}

}  // namespace dpdrng_test::dpd_test_min_image
