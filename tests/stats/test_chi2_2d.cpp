// The 2-D χ² on hand-counted grids (the χ²(3) tail in closed form), and the two ways words become pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/chi2_2d.hpp"

namespace dpdrng_test::stats_test_chi2_2d {

using namespace dpdrng::stats;

namespace {

// 32 pairs on a 2 × 2 grid with counts 12, 4, 8, 8 (expected 8): A = (16 + 16)/8 = 4 on 3 degrees of freedom,
// p = erfc(√(A/2)) + √(2A/π)·e^(−A/2) (the χ²(3) upper tail in closed form) = 0.26146...
TEST(Chi2d, HandCountedGrid) {
  std::vector<double> u1, u2;
  auto put = [&](double a, double b, int times) {
    for (int i = 0; i < times; ++i) u1.push_back(a), u2.push_back(b);
  };
  put(0.1, 0.2, 12);  // cell (0, 0)
  put(0.3, 0.7, 4);   // cell (0, 1)
  put(0.6, 0.4, 8);   // cell (1, 0)
  put(0.9, 0.99, 8);  // cell (1, 1)
  const auto r = chi2_2d(u1, u2, 2);
  EXPECT_EQ(r.counts, (std::vector<std::uint64_t>{12, 4, 8, 8}));
  EXPECT_DOUBLE_EQ(r.statistic, 4.0);
  EXPECT_EQ(r.dof, 3);
  EXPECT_NEAR(r.p_value, std::erfc(std::sqrt(2.0)) + std::sqrt(8 / std::numbers::pi) * std::exp(-2.0), 1e-14);
}

TEST(Chi2d, FullLatticeIsPerfectAndTheDiagonalFails) {
  std::vector<double> u1, u2;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) u1.push_back((i + 0.5) / 64), u2.push_back((j + 0.5) / 64);
  const auto r = chi2_2d(u1, u2, 8);
  EXPECT_EQ(r.statistic, 0.0);
  EXPECT_EQ(r.p_value, 1.0);
  EXPECT_EQ(r.verdict, Verdict::pass);
  const auto d = chi2_2d(u1, u1, 8);  // u2 = u1: uniform margins, every pair on the diagonal
  EXPECT_EQ(d.verdict, Verdict::fail);
}

TEST(Chi2d, WordPairings) {
  const std::vector<std::uint64_t> w{0x8000000040000000ull, 0xc000000000000000ull, 0x4000000000000000ull};
  std::vector<double> u1, u2;
  pair_words(w, WordPairing::halves, u1, u2);
  EXPECT_EQ(u1, (std::vector<double>{0.25, 0.0, 0.0}));  // low halves
  EXPECT_EQ(u2, (std::vector<double>{0.5, 0.75, 0.25}));  // high halves
  pair_words(w, WordPairing::words, u1, u2);
  EXPECT_EQ(u1, (std::vector<double>{0x8000000040000000ull * 0x1p-64}));  // an odd last word is left out
  EXPECT_EQ(u2, (std::vector<double>{0.75}));
}

TEST(Chi2d, IndependentWordsPass) {
  std::mt19937_64 g(12);
  std::vector<std::uint64_t> w(400000);
  for (auto& x : w) x = g();
  std::vector<double> u1, u2;
  pair_words(w, WordPairing::halves, u1, u2);
  EXPECT_GT(chi2_2d(u1, u2, 16).p_value, 1e-3);
  pair_words(w, WordPairing::words, u1, u2);
  EXPECT_GT(chi2_2d(u1, u2, 16).p_value, 1e-3);
}

TEST(Chi2d, SmallAndBadInput) {
  const std::vector<double> a{0.1, 0.2}, b{0.3, 0.4}, c{0.3};
  EXPECT_EQ(chi2_2d(a, b, 2).verdict, Verdict::not_applicable);
  EXPECT_THROW(chi2_2d(a, c, 2), dpdrng::InputError);
  EXPECT_THROW(chi2_2d(a, std::vector<double>{0.3, 1.0}, 2), dpdrng::InputError);
  EXPECT_THROW(chi2_2d(a, b, 1), dpdrng::InputError);
  EXPECT_THROW(parse_word_pairing("pairs"), dpdrng::InputError);
}

}  // namespace

}  // namespace dpdrng_test::stats_test_chi2_2d
