// The defect generator: its name's grammar, that a zero defect is its base bit for bit, and that the injected
// defect has the size asked for, measured on large samples. Each tolerance is 6 standard errors of the
// estimate (derived at the test), so a correct implementation sits far inside it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/rng/stream.hpp"

namespace dpdrng_test::rng_test_defect {

using namespace dpdrng;
using namespace dpdrng::rng;

namespace {

constexpr std::size_t kN = std::size_t{1} << 21;

std::vector<double> zetas(const std::string& name, Distribution dist, std::uint64_t start = 11) {
  std::vector<double> z(kN);
  fill_noise(validated({name, 0}), dist, start, 0, z);
  return z;
}

double mean(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  return s / double(x.size());
}

// Sample variance about the sample mean, and the lag-k correlation coefficient.
double variance(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0;
  for (double v : x) s += (v - m) * (v - m);
  return s / double(x.size() - 1);
}
double lag_corr(const std::vector<double>& x, std::size_t k) {
  const double m = mean(x), var = variance(x);
  double s = 0;
  for (std::size_t i = 0; i + k < x.size(); ++i) s += (x[i] - m) * (x[i + k] - m);
  return s / double(x.size() - k) / var;
}

}  // namespace

TEST(Defect, ParsesItsName) {
  const DefectParams p = parse_defect("defect:variance=0.01,lag1=-0.25,mean=0.5,base=philox4x32");
  EXPECT_EQ(p.variance, 0.01);
  EXPECT_NEAR(p.lag1 * p.fresh(), -0.25, 1e-15);  // the weight a of η_{t−1} gives a·√(1−a²) = ρ
  EXPECT_LT(p.lag1, 0.0);
  EXPECT_NEAR(parse_defect("defect:lag1=0.5").lag1, std::sqrt(0.5), 1e-8);  // the largest: a = √(1−a²)
  EXPECT_EQ(p.mean, 0.5);
  EXPECT_EQ(parse_defect("defect:mean=-1e-3").mean, -1e-3);
  EXPECT_EQ(parse_defect("defect").variance, 0.0);
  EXPECT_EQ(find_generator("defect:lag1=0.5").name, "defect");
  EXPECT_EQ(describe(validated({"defect:variance=0.02", 0})), "defect:variance=0.02");
}

TEST(Defect, RefusesMalformedNames) {
  for (const char* bad : {"defect:", "defect:variance", "defect:variance=", "defect:variance=-1",
                          "defect:variance=nan", "defect:lag1=0.51", "defect:lag1=-1.5", "defect:mean=inf",
                          "defect:base=tea32", "defect:colour=red", "defect:variance=0.1,variance=0.2",
                          "defect:variance=0.1,", "defect:variance=0x10", "defect:aniso=1", "defect:aniso=-0.5",
                          "defect:aniso=0.1,aniso=0.2"})
    EXPECT_THROW(validated({bad, 0}), InputError) << bad;
  // A lag-1 defect needs the step in the hash input.
  EXPECT_THROW(check_defect_seeding(validated({"defect:lag1=0.1", 0}), Seeding::distance), InputError);
  EXPECT_NO_THROW(check_defect_seeding(validated({"defect:lag1=0.1", 0}), Seeding::pair_step));
  EXPECT_NO_THROW(check_defect_seeding(validated({"defect:variance=0.1", 0}), Seeding::distance));
  // An anisotropic defect needs the separation in the hash input.
  EXPECT_THROW(check_defect_seeding(validated({"defect:aniso=0.1", 0}), Seeding::pair_step), InputError);
  EXPECT_NO_THROW(check_defect_seeding(validated({"defect:aniso=0.1", 0}), Seeding::distance));
}

// key=N: Philox4x32-10 (Random123's known-answer vectors are checked in test_random123) under the key
// (3, N, 5, 6) instead of the paper's (3, 4, 5, 6), with no defect: an independent good generator per N.
TEST(Defect, KeyParameterRekeysTheBase) {
  EXPECT_EQ(parse_defect("defect:key=7").key, 7);
  EXPECT_EQ(parse_defect("defect:key=4294967295").key, 4294967295LL);
  EXPECT_EQ(parse_defect("defect:variance=0.1").key, -1);
  for (const char* bad : {"defect:key=-1", "defect:key=4294967296", "defect:key=1.5", "defect:key=1,key=2"})
    EXPECT_THROW(validated({bad, 0}), InputError) << bad;
  Defect d;
  d.p = parse_defect("defect:key=7");
  Philox4x32<10> rekeyed, paper;
  rekeyed.key = {3, 7, 5, 6};
  const PairInput p{3, 17, 0.37, -0.61, 0.05, 1234};
  EXPECT_EQ(pair_block<Seeding::pair_step>(d, p, 42).now, pair_block<Seeding::pair_step>(rekeyed, p, 42));
  EXPECT_NE(pair_block<Seeding::pair_step>(d, p, 42).now, pair_block<Seeding::pair_step>(paper, p, 42));
  EXPECT_EQ(d.distance(0.3, 0.2, 0.1).now, rekeyed.distance(0.3, 0.2, 0.1));
  Defect four;
  four.p = parse_defect("defect:key=4");  // the paper key's own second word: the plain base
  EXPECT_EQ(four.distance(0.3, 0.2, 0.1).now, paper.distance(0.3, 0.2, 0.1));
}

// No defect: the base's numbers, bit for bit, in every seeding and in counter streams; with a defect the words
// stay the base's (the word-level stream) while ζ changes.
TEST(Defect, ZeroDefectIsPhilox10) {
  Defect d;
  Philox4x32<10> base;
  const PairInput p{3, 17, 0.37, -0.61, 0.05, 1234};
  for (std::uint64_t step : {0ull, 1ull, 99ull}) {
    PairInput q = p;
    q.step = step;
    const auto a = pair_block<Seeding::pair_step>(d, q, 42);
    const auto b = pair_block<Seeding::pair_step>(base, q, 42);
    EXPECT_EQ(a.now, b);
    EXPECT_EQ(draw<Distribution::gauss>(a), draw<Distribution::gauss>(b));
    EXPECT_EQ(draw<Distribution::uniform>(a), draw<Distribution::uniform>(b));
  }
  EXPECT_EQ(draw<Distribution::gauss>(d.distance(0.3, 0.2, 0.1)), draw<Distribution::gauss>(base.distance(0.3, 0.2, 0.1)));
  std::vector<std::uint64_t> wd(1000), wb(1000);
  fill_stream(validated({"defect:variance=0.5,lag1=0.3,mean=1", 0}), 5, 3, wd);
  fill_stream(validated({"philox4x32", 10}), 5, 3, wb);
  EXPECT_EQ(wd, wb);
  EXPECT_EQ(zetas("defect", Distribution::gauss), zetas("philox4x32", Distribution::gauss));
}

// ⟨ζ²⟩ − ⟨ζ⟩² = 1 + ε. The sample variance of n Gaussians of variance s² has standard error s²·√(2/n); for the
// unit-variance uniform it is s²·√((9/5 − 1)/n) (fourth moment 9/5), smaller. 6 SE: 6·1.2·√(2/2^21) ≈ 0.0070,
// far below the ε = 0.05 tested and far above the estimate's spread.
TEST(Defect, VarianceIsOnePlusEpsilon) {
  for (Distribution dist : {Distribution::gauss, Distribution::uniform}) {
    for (double eps : {0.05, -0.05}) {
      const auto z = zetas("defect:variance=" + std::to_string(eps), dist);
      const double se = (1 + eps) * std::sqrt(2.0 / double(kN));
      EXPECT_NEAR(variance(z), 1 + eps, 6 * se) << to_string(dist) << " ε=" << eps;
      EXPECT_NEAR(mean(z), 0.0, 6 * std::sqrt((1 + eps) / double(kN)));
    }
  }
}

// ⟨ζ⟩ = μ with the variance left at 1: SE of the mean 1/√n.
TEST(Defect, MeanIsMu) {
  for (Distribution dist : {Distribution::gauss, Distribution::uniform}) {
    const auto z = zetas("defect:mean=0.02", dist);
    EXPECT_NEAR(mean(z), 0.02, 6 / std::sqrt(double(kN))) << to_string(dist);
    EXPECT_NEAR(variance(z), 1.0, 6 * std::sqrt(2.0 / double(kN)));
  }
}

// corr(ζ_t, ζ_{t−1}) = ρ, ⟨ζ²⟩ stays 1, and steps two apart are independent (ζ_t and ζ_{t−2} share no η). The
// lag-k sample correlation has standard error ≤ √((1 + 2ρ²)/n) for this MA(1) process (Bartlett); 6 SE ≈ 0.005.
TEST(Defect, Lag1CorrelationIsRho) {
  for (Distribution dist : {Distribution::gauss, Distribution::uniform})
    for (double rho : {0.2, -0.4}) {
      const auto z = zetas("defect:lag1=" + std::to_string(rho), dist);
      const double se = std::sqrt((1 + 2 * rho * rho) / double(kN));
      EXPECT_NEAR(lag_corr(z, 1), rho, 6 * se) << to_string(dist) << " ρ=" << rho;
      EXPECT_NEAR(lag_corr(z, 2), 0.0, 6 * se);
      EXPECT_NEAR(variance(z), 1.0, 6 * std::sqrt(2.0 / double(kN)));
    }
}

// The same in pair-step seeding, along the steps of one pair, as the DPD pair loop draws it.
TEST(Defect, Lag1AlongAPairsSteps) {
  const GeneratorSpec spec = validated({"defect:lag1=0.3,variance=0.1", 0});
  std::vector<double> z;
  z.reserve(kN);
  with_pair_noise(spec, Seeding::pair_step, Distribution::gauss, 9, [&](const auto& pn) {
    for (std::uint32_t pair = 0; pair < 64; ++pair)
      for (std::uint64_t step = 0; step < kN / 64; ++step) z.push_back(pn(PairInput{pair, pair + 100, 0, 0, 0, step}));
    return 0;
  });
  // Correlations across the joins between pairs (63 of 2^21 products) shift the estimate by < 1e-4.
  const double se = std::sqrt((1 + 2 * 0.09) / double(kN));
  EXPECT_NEAR(lag_corr(z, 1), 0.3, 6 * se);
  EXPECT_NEAR(variance(z), 1.1, 6 * 1.1 * std::sqrt(2.0 / double(kN)));
}

// The anisotropic defect: pairs along z have ζ variance 1 + 2κ, pairs in the x-y plane 1 − κ, and pairs whose
// directions are uniform on the sphere 1 (the mean of 3cos²θ − 1 over the sphere is 0: the second Legendre
// polynomial averages to zero), so the fluid as a whole is neither heated nor cooled.
TEST(Defect, AnisotropyFollowsThePairsDirection) {
  const double kappa = 0.3;
  const GeneratorSpec spec = validated({"defect:aniso=0.3", 0});
  constexpr std::size_t n = std::size_t{1} << 18;
  const auto sample = [&](auto direction) {
    std::vector<double> z;
    z.reserve(n);
    with_pair_noise(spec, Seeding::distance, Distribution::gauss, 9, [&](const auto& pn) {
      for (std::size_t k = 0; k < n; ++k) {
        const auto [dx, dy, dz] = direction(k);
        z.push_back(pn(PairInput{1, 2, dx, dy, dz, 0}));
      }
      return 0;
    });
    return z;
  };
  const auto tol = [](double v) { return 6 * v * std::sqrt(2.0 / double(n)); };
  // Distinct separations (the distance seeding hashes dx and dy) along z to within 1e-8 rad, along x, and on a
  // golden-spiral cover of the sphere.
  const auto along_z = sample([](std::size_t k) { return std::array{1e-9 * double(k + 1), 1e-9, 0.5}; });
  const auto along_x = sample([](std::size_t k) { return std::array{0.2 + 1e-6 * double(k), 0.0, 0.0}; });
  const auto sphere = sample([](std::size_t k) {
    const double c = 1 - 2 * (double(k) + 0.5) / double(n), s = std::sqrt(1 - c * c), phi = 2.399963229728653 * double(k);
    const double r = 0.8;
    return std::array{r * s * std::cos(phi), r * s * std::sin(phi), r * c};
  });
  EXPECT_NEAR(variance(along_z), 1 + 2 * kappa, tol(1 + 2 * kappa));
  EXPECT_NEAR(variance(along_x), 1 - kappa, tol(1 - kappa));
  EXPECT_NEAR(variance(sphere), 1.0, tol(1.0 + kappa));
  EXPECT_NEAR(mean(along_z), 0.0, 6 * std::sqrt((1 + 2 * kappa) / double(n)));
}

}  // namespace dpdrng_test::rng_test_defect
