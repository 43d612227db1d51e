// The feed of the Gaussian: which uniforms Box–Muller (or the inverse CDF) takes. Known values against a plain
// reimplementation of 32TEA (Wheeler & Needham 1994 with the paper's key and delta, as Okada et al. 2021 state
// it) and libm; symmetry ζ_ij = ζ_ji under every feed; ⟨ζ²⟩ of 32TEA(1) on the separations of pairs inside r_c.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/registry.hpp"
#include "every_generator.hpp"

namespace dpdrng::rng::test_feed {
namespace {

// 32TEA(n) from the cycle as printed: x0 low word, x1 high word, output (x1' << 32) | x0'.
std::uint64_t plain_tea32(std::uint64_t seed, int rounds) {
  std::uint32_t x0 = static_cast<std::uint32_t>(seed), x1 = static_cast<std::uint32_t>(seed >> 32), sum = 0;
  const std::uint32_t k[4] = {3, 4, 5, 6};
  for (int r = 0; r < rounds; ++r) {
    sum += 0x9E3779B9u;
    x0 += ((x1 << 4) + k[0]) ^ ((x1 >> 5) + k[1]) ^ (x1 + sum);
    x1 += ((x0 << 4) + k[2]) ^ ((x0 >> 5) + k[3]) ^ (x0 + sum);
  }
  return (std::uint64_t{x1} << 32) | x0;
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }


TEST(Feed, ParsesNamesAndRefusesUniformWithAnotherFeed) {
  for (Feed f : kFeeds) EXPECT_EQ(parse_feed(to_string(f)), f);
  EXPECT_THROW(parse_feed("pairs"), InputError);
  EXPECT_NO_THROW(check_feed(Distribution::uniform, Feed::halves));
  EXPECT_THROW(check_feed(Distribution::uniform, Feed::blocks), InputError);
  EXPECT_THROW(check_feed(Distribution::uniform, Feed::inverse), InputError);
  for (Feed f : kFeeds) EXPECT_NO_THROW(check_feed(Distribution::gauss, f));
}

// The second block's input: components rotated, step complemented, indices kept.
TEST(Feed, SecondInputRotatesAndComplementsAndCommutesWithCanonical) {
  const PairInput p{9, 4, 0.5, -0.25, 1.0, 3};
  const PairInput q = second_input(p);
  EXPECT_EQ(q.i, 9u);
  EXPECT_EQ(q.j, 4u);
  EXPECT_EQ(q.dx, -0.25);
  EXPECT_EQ(q.dy, 1.0);
  EXPECT_EQ(q.dz, 0.5);
  EXPECT_EQ(q.step, ~std::uint64_t{3});
  const PairInput a = second_input(canonical(p)), b = canonical(second_input(p));
  EXPECT_EQ(a.i, b.i);
  EXPECT_EQ(a.j, b.j);
  EXPECT_EQ(bits(a.dx), bits(b.dx));
  EXPECT_EQ(bits(a.dy), bits(b.dy));
  EXPECT_EQ(bits(a.dz), bits(b.dz));
  EXPECT_EQ(a.step, b.step);
}

// 32TEA(1), distance seeding: halves feeds Box–Muller the two 32-bit TEA words of the dx block, blocks the whole
// dx-seeded word (u1) and the whole dy-seeded word (u2), inverse the whole dx-seeded word through Φ⁻¹. The
// references use libm in long double: log_unit and cos_2pi are polynomial kernels accurate to a few ulps, the
// single-precision halves path to float accuracy.
TEST(Feed, KnownValuesOf32Tea1AgainstAPlainReimplementation) {
  const Tea32<1> tea{};
  const PairNoise<Tea32<1>, Seeding::distance, Distribution::gauss> halves{tea, 0, Feed::halves},
      blocks{tea, 0, Feed::blocks}, inverse{tea, 0, Feed::inverse};
  const double pi2 = 2 * 3.14159265358979323846264338327950288L;
  for (const PairInput p : {PairInput{0, 1, 0.3125, -0.71, 0.05, 4}, PairInput{12, 200, -0.0371, 0.4, -0.6, 8},
                            PairInput{5, 6, 0.9, 0.01, -0.02, 100}}) {
    const std::uint64_t wx = plain_tea32(bits(p.dx), 1), wy = plain_tea32(bits(p.dy), 1);
    {
      const long double u1 = ((wx & 0xffffffffu) + 1.0L) * 0x1p-32L, u2 = (wx >> 32) * 0x1p-32L;
      const long double z = std::sqrt(-2 * std::log(u1)) * std::cos(pi2 * u2);
      EXPECT_NEAR(halves(p), double(z), 2e-6 * std::fabs(double(z)) + 1e-6);
    }
    {
      const long double u1 = ((wx >> 11) + 1.0L) * 0x1p-53L, u2 = (wy >> 11) * 0x1p-53L;
      const long double z = std::sqrt(-2 * std::log(u1)) * std::cos(pi2 * u2);
      EXPECT_NEAR(blocks(p), double(z), 1e-13);
    }
    {
      // Φ(ζ) = u checked through erfc, the CDF side (no second inverse-CDF implementation needed).
      const long double u = (2.0L * (wx >> 12) + 1) * 0x1p-53L;
      const double z = inverse(p);
      EXPECT_NEAR(0.5 * std::erfc(-z / std::sqrt(2.0)), double(u), 1e-14);
    }
  }
}

// Two-word generators under blocks: u1 from word 0 of the (dx, dy) block, u2 from word 0 of the (dy, dz) block.
TEST(Feed, TwoWordGeneratorsTakeTheFirstWordOfEachBlock) {
  const Tea64<3> tea{};
  const PairNoise<Tea64<3>, Seeding::distance, Distribution::gauss> blocks{tea, 0, Feed::blocks};
  const PairInput p{1, 2, 0.25, -0.5, 0.75, 0};
  const auto a = tea.distance(0.25, -0.5, 0.75), b = tea.distance(-0.5, 0.75, 0.25);
  EXPECT_EQ(blocks(p), box_muller(std::array<std::uint64_t, 2>{a[0], b[0]}));
  EXPECT_NE(a[0], b[0]);
}

// ζ_ij = ζ_ji under every feed, generator and pair seeding: the pair seen from j, once canonical, gives the
// same number bit for bit; and the blocks feed really differs from halves (not a copy of it).
TEST(Feed, SymmetricUnderEveryFeedAndSeeding) {
  const PairInput pairs[] = {{3, 17, 0.25, -0.5, 0.125, 9},
                             {40000, 2, -0.731, 0.002, 0.9, 123456789},
                             {7, 8, 1e-12, -3e-7, 0.0, 0},
                             {1u << 31, 5, -0.0, 0.5, -0.5, ~std::uint64_t{0}}};
  for (const GeneratorSpec& s : dpdrng_test::every_generator(true))
    for (auto seeding : {Seeding::distance, Seeding::pair_step}) {
      std::vector<double> per_feed[3];
      for (Feed feed : kFeeds)
        with_pair_noise(
            s, seeding, Distribution::gauss, 0x5eed,
            [&](const auto& noise) {
              for (const PairInput& p : pairs) {
                const PairInput swapped{p.j, p.i, -p.dx, -p.dy, -p.dz, p.step};
                const double a = noise(canonical(p)), b = noise(canonical(swapped));
                EXPECT_EQ(bits(a), bits(b)) << describe(s) << " " << to_string(seeding) << " " << to_string(feed);
                EXPECT_TRUE(std::isfinite(a));
                per_feed[int(feed)].push_back(a);
              }
            },
            feed);
      // A single round of some hashes (Philox's) can map both feeds' inputs alike: the feeds' difference is
      // checked at the default rounds.
      if (s.rounds != find_generator(s.name).default_rounds) continue;
      for (std::size_t k = 0; k < per_feed[0].size(); ++k) {
        EXPECT_NE(per_feed[0][k], per_feed[1][k]) << describe(s) << " " << to_string(seeding);
        EXPECT_NE(per_feed[1][k], per_feed[2][k]) << describe(s) << " " << to_string(seeding);
      }
    }
}

// The separations of pairs inside r_c = 1 among 256 beads at ρ = 3 placed uniformly at random (minimum image),
// as the pair loop hashes them; 120 configurations give about 1.9e5 pairs.
std::vector<PairInput> pairs_inside_rc() {
  const int n = 256;
  const double L = std::cbrt(n / 3.0);
  std::mt19937_64 rng(2021);
  std::uniform_real_distribution<double> pos(0.0, L);
  std::vector<PairInput> out;
  for (int conf = 0; conf < 120; ++conf) {
    std::vector<double> x(n), y(n), z(n);
    for (int i = 0; i < n; ++i) x[i] = pos(rng), y[i] = pos(rng), z[i] = pos(rng);
    auto mi = [L](double d) { return d - L * std::nearbyint(d / L); };
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const double dx = mi(x[j] - x[i]), dy = mi(y[j] - y[i]), dz = mi(z[j] - z[i]);
        if (dx * dx + dy * dy + dz * dz < 1.0)
          out.push_back({std::uint32_t(i), std::uint32_t(j), dx, dy, dz, std::uint64_t(conf)});
      }
  }
  return out;
}

double second_moment(Feed feed, const std::vector<PairInput>& pairs) {
  const PairNoise<Tea32<1>, Seeding::distance, Distribution::gauss> noise{Tea32<1>{}, 0, feed};
  double s2 = 0;
  for (const PairInput& p : pairs) s2 += noise(p) * noise(p);
  return s2 / double(pairs.size());
}

// The one-round halves of one block are dependent: ⟨ζ²⟩ ≈ 0.965 (the fluid then runs 3.5 % cold). Two separately
// hashed words, or one word through Φ⁻¹, give ⟨ζ²⟩ = 1 within the sampling error √(2/n) ≈ 0.0032.
TEST(Feed, SecondMomentOf32Tea1OnPairsInsideTheCutoff) {
  const auto pairs = pairs_inside_rc();
  ASSERT_GT(pairs.size(), 150000u);
  const double se = std::sqrt(2.0 / double(pairs.size()));
  const double halves = second_moment(Feed::halves, pairs);
  EXPECT_GT(halves, 0.95);
  EXPECT_LT(halves, 0.98);
  EXPECT_NEAR(second_moment(Feed::blocks, pairs), 1.0, 4 * se);
  EXPECT_NEAR(second_moment(Feed::inverse, pairs), 1.0, 4 * se);
}

}  // namespace
}  // namespace dpdrng::rng::test_feed
