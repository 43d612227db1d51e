// Distributions against their analytic moments, the [0,1) mappings at their edges, and pair-seeding symmetry.
// Samples come from fixed seeds, so every test is deterministic; each tolerance is 6 standard errors of the
// estimate (derived in the comments), so a correct implementation sits far inside it for any seed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/rng/stream.hpp"
#include "every_generator.hpp"

namespace dpdrng_test::rng_test_distribution {

using namespace dpdrng::rng;

namespace {

constexpr std::size_t kN = std::size_t{1} << 20;
const double kSqrtN = std::sqrt(static_cast<double>(kN));

TEST(Distribution, ToUnitEdges) {
  EXPECT_EQ(to_unit(0), 0.0);
  EXPECT_EQ(to_unit(~std::uint64_t{0}), 1.0 - 0x1p-53);  // never 1.0
  EXPECT_LT(to_unit(~std::uint64_t{0}), 1.0);
  EXPECT_EQ(to_unit_open0(0), 0x1p-53);  // never 0, so log() stays finite
  EXPECT_EQ(to_unit_open0(~std::uint64_t{0}), 1.0);
  EXPECT_EQ(to_unit(std::uint64_t{1} << 63), 0.5);
}

TEST(Distribution, UniformBounds) {
  EXPECT_EQ(uniform_unit_variance(std::array<std::uint64_t, 1>{0}), -std::numbers::sqrt3);
  EXPECT_LT(uniform_unit_variance(std::array<std::uint64_t, 1>{~std::uint64_t{0}}), std::numbers::sqrt3);
}

// Box–Muller's extreme inputs stay finite: the 32-bit halves path at u1 = 2^-32 and the 53-bit path at 2^-53.
TEST(Distribution, BoxMullerEdgesAreFinite) {
  const double z32 = box_muller(std::array<std::uint64_t, 1>{0});  // single precision: within 2 float ulp
  EXPECT_NEAR(z32, std::sqrt(64 * std::numbers::ln2), 2 * 0x1p-24 * z32);  // u1 = 2^-32, u2 = 0: cos = 1
  const double z53 = box_muller(std::array<std::uint64_t, 2>{0, 0});
  EXPECT_DOUBLE_EQ(z53, std::sqrt(106 * std::numbers::ln2));
  EXPECT_EQ(box_muller(std::array<std::uint64_t, 1>{0xffffffffull}), 0.0);  // u1 = 1: log 0
}

struct Moments {
  double mean = 0, m2 = 0, m4 = 0, min = INFINITY, max = -INFINITY, tail3 = 0;
};

Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) {
    m.mean += v;
    m.m2 += v * v;
    m.m4 += v * v * v * v;
    m.min = std::min(m.min, v);
    m.max = std::max(m.max, v);
    m.tail3 += std::abs(v) > 3.0;
  }
  const double n = static_cast<double>(x.size());
  m.mean /= n, m.m2 /= n, m.m4 /= n, m.tail3 /= n;
  return m;
}

// Every generator at its default rounds, the reference stream included.
std::vector<GeneratorSpec> strong_generators() { return dpdrng_test::every_generator(false, true); }

// Gaussian: E z = 0, E z² = 1, E z⁴ = 3, P(|z| > 3) = erfc(3/√2) = 0.0026998.
// Standard errors with N = 2^20: mean 1/√N; E z²: √(E z⁴ − 1)/√N = √2/√N; E z⁴: √(E z⁸ − 9)/√N = √96/√N
// (E z⁸ = 105); tail fraction √(p(1−p)/N).
void expect_gauss_moments(const std::vector<double>& z, const std::string& what) {
  const Moments m = moments(z);
  const double p3 = std::erfc(3 / std::numbers::sqrt2);
  EXPECT_NEAR(m.mean, 0.0, 6 / kSqrtN) << what;
  EXPECT_NEAR(m.m2, 1.0, 6 * std::sqrt(2.0) / kSqrtN) << what;
  EXPECT_NEAR(m.m4, 3.0, 6 * std::sqrt(96.0) / kSqrtN) << what;
  EXPECT_NEAR(m.tail3, p3, 6 * std::sqrt(p3 * (1 - p3)) / kSqrtN) << what;
}

// Uniform √3(2u−1): E x = 0, E x² = 1, E x⁴ = 9/5, |x| ≤ √3. E x⁸ = 3⁴/9 = 9, so the standard errors are
// 1/√N, √(1.8 − 1)/√N and √(9 − 1.8²)/√N. The extremes: P(no sample within 2√3·ε of a bound) = (1−ε)^N
// = e^-20 for ε = 20/N, so a correct stream reaches past that point on both sides.
void expect_uniform_moments(const std::vector<double>& x, const std::string& what) {
  const Moments m = moments(x);
  EXPECT_NEAR(m.mean, 0.0, 6 / kSqrtN) << what;
  EXPECT_NEAR(m.m2, 1.0, 6 * std::sqrt(0.8) / kSqrtN) << what;
  EXPECT_NEAR(m.m4, 1.8, 6 * std::sqrt(9 - 1.8 * 1.8) / kSqrtN) << what;
  const double edge = std::numbers::sqrt3 * (1 - 2 * 20.0 / kN);
  EXPECT_GE(m.min, -std::numbers::sqrt3) << what;
  EXPECT_LT(m.max, std::numbers::sqrt3) << what;
  EXPECT_LT(m.min, -edge) << what;
  EXPECT_GT(m.max, edge) << what;
}

TEST(Distribution, GaussMomentsEveryGenerator) {
  for (const auto& s : strong_generators()) {
    std::vector<double> z(kN);
    fill_gauss(s, 20240611, 0, z);
    expect_gauss_moments(z, describe(s));
  }
}

TEST(Distribution, UniformMomentsEveryGenerator) {
  for (const auto& s : strong_generators()) {
    std::vector<double> x(kN);
    fill_uniform(s, 20240611, 0, x);
    expect_uniform_moments(x, describe(s));
  }
}

// The scalar path the DPD engine uses: PairNoise over 2^20 distinct pairs at one step, pair-step seeding.
TEST(Distribution, PairNoiseMomentsScalarPath) {
  GeneratorSpec s;
  s.name = "philox4x32";
  for (auto dist : {Distribution::gauss, Distribution::uniform}) {
    std::vector<double> v(kN);
    with_pair_noise(validated(s), Seeding::pair_step, dist, 42, [&](const auto& noise) {
      for (std::size_t k = 0; k < kN; ++k) {
        const auto i = static_cast<std::uint32_t>(k % 1024), j = static_cast<std::uint32_t>(1024 + k / 1024);
        v[k] = noise(PairInput{i, j, 0.1, 0.2, 0.3, 7});
      }
    });
    if (dist == Distribution::gauss)
      expect_gauss_moments(v, "pair-step gauss");
    else
      expect_uniform_moments(v, "pair-step uniform");
  }
}

// ζ_ij = ζ_ji: the pair seen from j (indices swapped, separation negated) gives the same number once
// canonical() has ordered it, for every keyed generator, pair seeding and distribution.
TEST(Seeding, SymmetricForEveryGeneratorAndSeeding) {
  const PairInput pairs[] = {{3, 17, 0.25, -0.5, 0.125, 9},
                             {40000, 2, -0.731, 0.002, 0.9, 123456789},
                             {7, 8, 1e-12, -3e-7, 0.0, 0},
                             {1u << 31, 5, -0.0, 0.5, -0.5, ~std::uint64_t{0}}};
  for (const auto& s : dpdrng_test::every_generator(true))
    for (auto seeding : {Seeding::distance, Seeding::pair_step})
      for (auto dist : {Distribution::gauss, Distribution::uniform})
        with_pair_noise(s, seeding, dist, 0x5eed, [&](const auto& noise) {
          for (const PairInput& p : pairs) {
            const PairInput swapped{p.j, p.i, -p.dx, -p.dy, -p.dz, p.step};
            const double a = noise(canonical(p)), b = noise(canonical(swapped));
            EXPECT_EQ(a, b) << describe(s) << " " << to_string(seeding) << " " << to_string(dist) << " pair " << p.i
                            << "," << p.j;
            EXPECT_TRUE(std::isfinite(a));
          }
        });
}

TEST(Seeding, CanonicalOrdersAndNegates) {
  const PairInput p = canonical({9, 4, 0.5, -0.25, 1.0, 3});
  EXPECT_EQ(p.i, 4u);
  EXPECT_EQ(p.j, 9u);
  EXPECT_EQ(p.dx, -0.5);
  EXPECT_EQ(p.dy, 0.25);
  EXPECT_EQ(p.dz, -1.0);
  EXPECT_EQ(p.step, 3u);
  const PairInput q = canonical(p);  // already canonical: unchanged
  EXPECT_EQ(q.i, 4u);
  EXPECT_EQ(q.dx, -0.5);
}

}  // namespace

}  // namespace dpdrng_test::rng_test_distribution
