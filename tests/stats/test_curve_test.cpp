// The L² F test of two groups of curves: a hand computation, its calibration under the null on correlated,
// unequal-variance bins, and its power.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/stats/binomial.hpp"
#include "dpdrng/stats/curve_test.hpp"

namespace dpdrng_test::stats_test_curve_test {

using namespace dpdrng::stats;

namespace {

// Upper tail of F(d1, d2) at f by Simpson integration of its density on t = f/(f + d2/d1) ∈ [0, 1) (the
// regularized incomplete beta), sharing nothing with GSL.
double f_upper(double f, double d1, double d2) {
  const double x = d1 * f / (d1 * f + d2), a = d1 / 2, b = d2 / 2;
  const double lbeta = std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b);
  const auto g = [&](double t) {
    return t <= 0 || t >= 1 ? 0.0 : std::exp((a - 1) * std::log(t) + (b - 1) * std::log1p(-t) - lbeta);
  };
  const int n = 400000;
  const double h = (1 - x) / n;
  double s = g(x) + g(1);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * g(x + k * h);
  return s * h / 3;
}

// Gaussian curves of `bins` bins: bin k has mean sin(0.3k) + shift and sd 0.5 + k/bins (unequal), neighbouring
// bins correlated by an AR(1) of coefficient rho along the curve. A run is the mean of `blocks` block curves
// (each with √blocks times the noise), and brings its leave-one-block-out curves along.
struct CurveSource {
  std::uint64_t state;
  double normal() {
    const double u1 = (double(dpdrng::rng::splitmix64_mix(state++) >> 11) + 0.5) * 0x1p-53;
    const double u2 = double(dpdrng::rng::splitmix64_mix(state++) >> 11) * 0x1p-53;
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  }
  std::vector<double> curve(std::size_t bins, double rho, double shift, double scale) {
    std::vector<double> c(bins);
    double e = normal();
    for (std::size_t k = 0; k < bins; ++k) {
      if (k > 0) e = rho * e + std::sqrt(1 - rho * rho) * normal();
      c[k] = std::sin(0.3 * double(k)) + shift + scale * (0.5 + double(k) / double(bins)) * e;
    }
    return c;
  }
  struct Group {
    Curves curves;
    std::vector<Curves> jackknife;
  };
  Group group(std::size_t n, std::size_t bins, double rho, double shift, std::size_t blocks = 20) {
    Group g;
    for (std::size_t i = 0; i < n; ++i) {
      Curves b;
      for (std::size_t k = 0; k < blocks; ++k) b.push_back(curve(bins, rho, shift, std::sqrt(double(blocks))));
      std::vector<double> mean(bins, 0.0);
      for (const auto& c : b)
        for (std::size_t k = 0; k < bins; ++k) mean[k] += c[k] / double(blocks);
      Curves jack;
      for (const auto& c : b) {
        std::vector<double> j(bins);
        for (std::size_t k = 0; k < bins; ++k) j[k] = (mean[k] * double(blocks) - c[k]) / double(blocks - 1);
        jack.push_back(std::move(j));
      }
      g.curves.push_back(std::move(mean));
      g.jackknife.push_back(std::move(jack));
    }
    return g;
  }
};

CurveTest run(CurveSource& src, std::size_t n, double rho, double shift, bool with_jackknife) {
  const auto x = src.group(n, 40, rho, shift), y = src.group(n, 40, rho, 0);
  std::vector<Curves> jack = x.jackknife;
  jack.insert(jack.end(), y.jackknife.begin(), y.jackknife.end());
  return curve_test(x.curves, y.curves, with_jackknife ? jack : std::vector<Curves>{});
}

}  // namespace

// By hand: x = {(1,2), (3,4)}, y = {(2,2), (4,6)}. Mean curves (2,3) and (3,4): nm/(n+m)·‖x̄ − ȳ‖² = 1·2 = 2.
// Residuals (−1,−1), (1,1), (−1,−2), (1,2) on ν = 2: tr Σ̂ = 14/2 = 7, so F = 2/7. Their Gram matrix's squared
// entries sum to 188, tr Σ̂² = 188/4 = 47; without runs' curves d is the plug-in 7²/47.
TEST(CurveTest, HandComputation) {
  const CurveTest t = curve_test({{1, 2}, {3, 4}}, {{2, 2}, {4, 6}});
  EXPECT_EQ(t.bins, 2u);
  EXPECT_NEAR(t.f, 2.0 / 7.0, 1e-15);
  EXPECT_FALSE(t.d_from_runs);
  EXPECT_NEAR(t.d, 49.0 / 47.0, 1e-12);
  EXPECT_NEAR(t.dof2, 2 * 49.0 / 47.0, 1e-12);
  EXPECT_NEAR(t.p_value, f_upper(2.0 / 7.0, t.dof1, t.dof2), 1e-6);
}

// d from runs' leave-one-block-out curves, by hand: one run with blocks' curves J = (0,0), (2,0), (1,3): residuals
// (−1,−1), (1,−1), (0,2), covariance (2/3)·Σ rrᵀ = (2/3)·[[2, 0], [0, 6]] on ν = 2. tr = 16/3, tr² = 256/9,
// tr(Σ̂²) = (4/9)(4 + 36) = 160/9. Unbiased for Wishart (c = (ν−1)(ν+2) = 4): tr(Σ)² = (6/4)(256/9 − 320/27) =
// 24.888…, tr(Σ²) = (4/4)(160/9 − 128/9) = 32/9, d = 7.0 → clamped to the 2 bins.
TEST(CurveTest, EffectiveBinsFromTheRunsCurves) {
  const std::vector<Curves> jack = {{{0, 0}, {2, 0}, {1, 3}}};
  const CurveTest t = curve_test({{1, 2}, {3, 4}}, {{2, 2}, {4, 6}}, jack);
  EXPECT_TRUE(t.d_from_runs);
  EXPECT_EQ(t.d_dof, 2.0);
  EXPECT_EQ(t.d, 2.0);
  EXPECT_NEAR(t.f, 2.0 / 7.0, 1e-15);  // the scale is the replicas'
  // Three bins, the third a copy of the first: the plug-in and unbiased estimates by the same algebra.
  const std::vector<Curves> jack3 = {{{0, 0, 0}, {2, 0, 2}, {1, 3, 1}}};
  const CurveTest u = curve_test({{1, 2, 1}, {3, 4, 3}}, {{2, 2, 2}, {4, 6, 4}}, jack3);
  // Covariance (2/3)·[[2,0,2],[0,6,0],[2,0,2]]: tr = 20/3, tr(Σ̂²) = (4/9)(4·4 + 36) = 208/9.
  const double tr = 20.0 / 3, tr2 = 208.0 / 9, nu = 2, c = (nu - 1) * (nu + 2);
  const double d = (nu * (nu + 1) / c * (tr * tr - 2 * tr2 / (nu + 1))) / (nu * nu / c * (tr2 - tr * tr / nu));
  EXPECT_NEAR(u.d, std::clamp(d, 1.0, 3.0), 1e-12);
}

TEST(CurveTest, RefusesWhatItCannotTest) {
  EXPECT_TRUE(std::isnan(curve_test({{1, 2}}, {{2, 2}, {4, 6}}).p_value));  // ν = 1
  EXPECT_TRUE(std::isnan(curve_test({}, {{2, 2}, {4, 6}}).p_value));
  EXPECT_TRUE(std::isnan(curve_test({{1, 1}, {1, 1}}, {{1, 1}, {1, 1}}).p_value));  // no spread
  EXPECT_THROW(curve_test({{1, 2}, {1}}, {{2, 2}, {4, 6}}), dpdrng::InputError);
}

// Under the null the rate of p < α must be α: 2000 pairs of groups of 4 runs of 40 bins with unequal variances,
// independent (ρ = 0) and strongly correlated (ρ = 0.9, d ≈ 4) along the curve, d from the runs' 20 blocks. The
// rate must lie in the 99.9 % binomial interval around α.
TEST(CurveTest, CalibratedUnderTheNull) {
  for (const double rho : {0.0, 0.9}) {
    CurveSource src{rho > 0 ? 12345u : 777u};
    std::size_t below05 = 0, below01 = 0;
    const std::size_t trials = 2000;
    for (std::size_t k = 0; k < trials; ++k) {
      const CurveTest t = run(src, 4, rho, 0, true);
      EXPECT_TRUE(t.d_from_runs);
      below05 += t.p_value < 0.05;
      below01 += t.p_value < 0.01;
    }
    for (const auto& [count, alpha] : {std::pair{below05, 0.05}, std::pair{below01, 0.01}})
      EXPECT_GT(binomial_test_p(count, trials, alpha), 0.001)
          << "rho " << rho << ": " << count << " of " << trials << " below " << alpha;
  }
}

// Without the runs' curves the plug-in d (at most n + m − 2) errs on the safe side: at most α false alarms.
TEST(CurveTest, ConservativeWithoutTheRunsCurves) {
  CurveSource src{4242};
  std::size_t below05 = 0;
  const std::size_t trials = 1000;
  for (std::size_t k = 0; k < trials; ++k) below05 += run(src, 4, 0.5, 0, false).p_value < 0.05;
  EXPECT_LT(below05, 50u);
}

// A uniform shift of the middle bin's noise (sd 1) across 40 bins is seen almost every time with 4 runs a side.
TEST(CurveTest, DetectsAShift) {
  CurveSource src{99};
  std::size_t detected = 0;
  for (int k = 0; k < 200; ++k) detected += run(src, 4, 0.0, 1.0, true).p_value < 0.01;
  EXPECT_GT(detected, 150u);
}

}  // namespace dpdrng_test::stats_test_curve_test
