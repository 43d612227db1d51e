// Accuracy of Box–Muller's own log and cos against MPFR at 160 bits, over the inputs Box–Muller actually feeds
// them, random points plus the edges where the reductions switch branch: the double kernels (rng/unit_math.hpp)
// in ulp of the double result, u1 in (0, 1] and u2 in [0, 1) on the 2^-53 grid (to_unit_open0 / to_unit) and on
// the 2^-32 grid; the single-precision kernels (rng/unit_math_f32.hpp) in ulp of the float result (24-bit
// significand), every 32-bit word class they treat differently. The bounds are stated per function; measured
// worst cases are recorded as properties.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/simd.hpp"
#include "mpfr_value.hpp"

namespace dpdrng_test::rng_test_unit_math {

using namespace dpdrng::rng;

namespace {

// |got − ref| in units of the last place of ref at a precision of `bits` (53: double, 24: float), i.e.
// ulp = 2^(e−bits) for ref in [2^(e−1), 2^e).
double ulps(double got, const Mp& ref, int bits = 53) {
  if (mpfr_zero_p(ref.v)) return got == 0.0 ? 0.0 : INFINITY;
  Mp d;
  mpfr_set_d(d.v, got, MPFR_RNDN);
  mpfr_sub(d.v, d.v, ref.v, MPFR_RNDN);
  mpfr_abs(d.v, d.v, MPFR_RNDN);
  mpfr_mul_2si(d.v, d.v, bits - mpfr_get_exp(ref.v), MPFR_RNDN);
  return mpfr_get_d(d.v, MPFR_RNDN);
}

void ref_log(Mp& out, double u) {
  mpfr_set_d(out.v, u, MPFR_RNDN);
  mpfr_log(out.v, out.v, MPFR_RNDN);
}

void ref_cos_2pi(Mp& out, double u) {
  Mp t;
  mpfr_const_pi(out.v, MPFR_RNDN);
  mpfr_set_d(t.v, u, MPFR_RNDN);
  mpfr_mul(out.v, out.v, t.v, MPFR_RNDN);
  mpfr_mul_2si(out.v, out.v, 1, MPFR_RNDN);
  mpfr_cos(out.v, out.v, MPFR_RNDN);
}

std::vector<std::uint64_t> random_words(int n, std::uint64_t seed) {
  std::mt19937_64 pick(seed);
  std::vector<std::uint64_t> w(n);
  for (auto& x : w) x = pick();
  return w;
}

// u1 as Box–Muller makes it: both grids, random words, every power of two down to the grid's smallest value
// (and a few neighbours: small u1 is rare among random words but gives the largest |z|), 1 and just below,
// and both sides of the reduction boundary √½.
std::vector<double> log_inputs() {
  std::vector<double> u;
  for (std::uint64_t w : random_words(60000, 11)) {
    u.push_back(to_unit_open0(w));
    u.push_back((static_cast<double>(w & 0xffffffffu) + 1.0) * 0x1p-32);
  }
  for (int k = 0; k <= 53; ++k) {
    const double p = std::ldexp(1.0, -k);
    u.push_back(p);
    if (p + 0x1p-53 <= 1.0) u.push_back(p + 0x1p-53);
    if (p - 0x1p-53 > 0.0) u.push_back(p - 0x1p-53);
  }
  for (int k = 1; k <= 200; ++k) {
    u.push_back(k * 0x1p-53);
    u.push_back(k * 0x1p-32);
    u.push_back(1.0 - (k - 1) * 0x1p-53);
    u.push_back(1.0 - (k - 1) * 0x1p-32);
  }
  double lo = std::numbers::sqrt2 / 2, hi = lo;
  for (int k = 0; k < 200; ++k) u.push_back(lo = std::nextafter(lo, 0.0)), u.push_back(hi = std::nextafter(hi, 1.0));
  return u;
}

// u2 on both grids, random, and around every quarter and eighth: the quadrant switches and cos's zeros and ±1.
std::vector<double> cos_inputs() {
  std::vector<double> u;
  for (std::uint64_t w : random_words(60000, 12)) {
    u.push_back(to_unit(w));
    u.push_back(static_cast<double>(w >> 32) * 0x1p-32);
  }
  for (int e = 0; e < 8; ++e) {
    const double c = e / 8.0;
    for (int k = 0; k <= 100; ++k) {
      for (double step : {0x1p-53, 0x1p-32}) {
        if (c + k * step < 1.0) u.push_back(c + k * step);
        if (c - k * step >= 0.0) u.push_back(c - k * step);
      }
    }
  }
  return u;
}

TEST(UnitMath, LogUnitWithinOneUlpOfMpfr) {
  Mp ref;
  double worst = 0, worst_at = 0;
  for (double u : log_inputs()) {
    ref_log(ref, u);
    const double e = ulps(math::log_unit(u), ref);
    if (e > worst) worst = e, worst_at = u;
  }
  EXPECT_LE(worst, 1.0) << "at u = " << worst_at;
  RecordProperty("log_unit_max_ulp", std::to_string(worst));
  std::printf("log_unit: max %.3f ulp (at u = %a)\n", worst, worst_at);
}

TEST(UnitMath, Cos2PiWithinTwoAndAHalfUlpOfMpfr) {
  Mp ref;
  double worst = 0, worst_at = 0;
  for (double u : cos_inputs()) {
    ref_cos_2pi(ref, u);
    const double got = math::cos_2pi(u);
    if (u == 0.25 || u == 0.75) {  // the exact zeros: MPFR's 2π·u is not exactly π/2, the reduction is
      EXPECT_EQ(got, 0.0) << u;
      continue;
    }
    const double e = ulps(got, ref);
    if (e > worst) worst = e, worst_at = u;
  }
  EXPECT_LE(worst, 2.5) << "at u = " << worst_at;
  RecordProperty("cos_2pi_max_ulp", std::to_string(worst));
  std::printf("cos_2pi: max %.3f ulp (at u = %a)\n", worst, worst_at);
  EXPECT_EQ(math::cos_2pi(0.0), 1.0);
  EXPECT_EQ(math::cos_2pi(0.5), -1.0);
}

// The whole Box–Muller number, z = √(−2 log u1)·cos(2πu2), from both block shapes: relative errors add up
// (log, halved by the sqrt; cos; the sqrt and the product 0.5 each), so 4 ulp of z, in double for a two-word block
// and in float for a one-word block (its z is a product of two floats, exact in double).
TEST(UnitMath, BoxMullerWithinFourUlpOfMpfr) {
  Mp r, c;
  double worst53 = 0, worst24 = 0;
  auto error = [&](double u1, double u2, double z, int bits) {
    ref_log(r, u1);
    mpfr_mul_si(r.v, r.v, -2, MPFR_RNDN);
    mpfr_sqrt(r.v, r.v, MPFR_RNDN);
    ref_cos_2pi(c, u2);
    mpfr_mul(r.v, r.v, c.v, MPFR_RNDN);
    return mpfr_zero_p(r.v) ? 0.0 : ulps(z, r, bits);
  };
  for (std::uint64_t w : random_words(40000, 13)) {
    const double e24 = error((static_cast<double>(w & 0xffffffffu) + 1.0) * 0x1p-32,
                             static_cast<double>(w >> 32) * 0x1p-32, box_muller(std::array<std::uint64_t, 1>{w}), 24);
    const std::uint64_t w2 = w * 0x9e3779b97f4a7c15ull;
    const double e53 = error(to_unit_open0(w), to_unit(w2), box_muller(std::array<std::uint64_t, 2>{w, w2}), 53);
    worst24 = std::max(worst24, e24);
    worst53 = std::max(worst53, e53);
  }
  EXPECT_LE(worst53, 4.0);
  EXPECT_LE(worst24, 4.0);
  RecordProperty("box_muller_max_ulp", std::to_string(worst53));
  RecordProperty("box_muller32_max_float_ulp", std::to_string(worst24));
  std::printf("box_muller: max %.3f ulp (two words), %.3f float ulp (one word)\n", worst53, worst24);
}

// 32-bit words for the single-precision kernels: random ones, the smallest and largest (u1 = 2^-32 and 1),
// 2^k − 1 ± a few (v = x + 1 crosses a power of two), both sides of every reduction boundary √½·2^j, and every
// multiple of 2^29 ± a few (cos's quarter and eighth points, its zeros and ±1).
std::vector<std::uint32_t> word_inputs() {
  std::vector<std::uint32_t> x;
  for (std::uint64_t w : random_words(60000, 14)) x.push_back(static_cast<std::uint32_t>(w >> 16));
  auto around = [&](double centre, int reach) {
    for (int k = -reach; k <= reach; ++k) {
      const double v = std::floor(centre) + k;
      if (v >= 0 && v <= 0xffffffffu) x.push_back(static_cast<std::uint32_t>(v));
    }
  };
  for (int k = 0; k <= 32; ++k) {
    around(std::ldexp(1.0, k) - 1, 40);
    around(std::ldexp(std::numbers::sqrt2 / 2, k) - 1, 40);
  }
  around(0, 200);
  around(0xffffffffu, 200);
  for (int e = 0; e <= 8; ++e) around(e * 0x1p29, 100);
  return x;
}

TEST(UnitMath, LogU32WithinOneAndAHalfFloatUlpOfMpfr) {
  Mp ref;
  double worst = 0;
  std::uint32_t worst_at = 0;
  for (std::uint32_t x : word_inputs()) {
    ref_log(ref, (static_cast<double>(x) + 1.0) * 0x1p-32);  // exact: 33 bits
    const double e = ulps(math::log_u32(x), ref, 24);
    if (e > worst) worst = e, worst_at = x;
  }
  EXPECT_EQ(math::log_u32(0xffffffffu), 0.0f);
  EXPECT_LE(worst, 1.5) << "at x = " << worst_at;
  RecordProperty("log_u32_max_float_ulp", std::to_string(worst));
  std::printf("log_u32: max %.3f float ulp (at x = %u)\n", worst, worst_at);
}

TEST(UnitMath, Cos2PiU32WithinTwoAndAHalfFloatUlpOfMpfr) {
  Mp ref;
  double worst = 0;
  std::uint32_t worst_at = 0;
  for (std::uint32_t x : word_inputs()) {
    const float got = math::cos_2pi_u32(x);
    if (x == 0x40000000u || x == 0xc0000000u) {  // the exact zeros: the integer reduction hits them exactly
      EXPECT_EQ(got, 0.0f) << x;
      continue;
    }
    ref_cos_2pi(ref, static_cast<double>(x) * 0x1p-32);
    const double e = ulps(got, ref, 24);
    if (e > worst) worst = e, worst_at = x;
  }
  EXPECT_LE(worst, 2.5) << "at x = " << worst_at;
  RecordProperty("cos_2pi_u32_max_float_ulp", std::to_string(worst));
  std::printf("cos_2pi_u32: max %.3f float ulp (at x = %u)\n", worst, worst_at);
  EXPECT_EQ(math::cos_2pi_u32(0), 1.0f);
  EXPECT_EQ(math::cos_2pi_u32(0x80000000u), -1.0f);
}

// The batched Gaussian runs the single-precision kernels on 16 lanes (GNU vectors, register-table lookups) and the
// pair loop on one: the same template, so the same bits, checked lane for lane over every word class above.
// minus_two_log_u32, which Box–Muller uses, folds the −2 into the constants: the bits of −2.0f * log_u32.
TEST(UnitMath, U32KernelsSixteenLanesEqualOneLaneBitwise) {
  const auto x = word_inputs();
  auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  for (std::size_t k = 0; k + 16 <= x.size(); k += 16) {
    const auto v = simd::load<simd::u32x16>(x.data() + k);
    const simd::f32x16 log16 = math::log_u32(v), m2log16 = math::minus_two_log_u32(v), cos16 = math::cos_2pi_u32(v);
    for (int j = 0; j < 16; ++j) {
      const std::uint32_t w = x[k + j];
      ASSERT_EQ(bits(log16[j]), bits(math::log_u32(w))) << w;
      ASSERT_EQ(bits(m2log16[j]), bits(math::minus_two_log_u32(w))) << w;
      ASSERT_EQ(bits(cos16[j]), bits(math::cos_2pi_u32(w))) << w;
      if (w != 0xffffffffu) {
        ASSERT_EQ(bits(math::minus_two_log_u32(w)), bits(-2.0f * math::log_u32(w))) << w;
      }
    }
  }
  EXPECT_EQ(bits(math::minus_two_log_u32(0xffffffffu)), 0u);  // +0: log 1 = +0 and −2·(+0) would be −0
}

// The batched Gaussian's sqrt: the SIMD instruction must equal std::sqrt lane for lane (both correctly rounded).
TEST(UnitMath, SimdSqrtEqualsStdSqrt) {
  const auto u = log_inputs();
  for (std::size_t k = 0; k + 8 <= u.size(); k += 8) {
    const auto got = simd::sqrt(simd::load<simd::f64x8>(u.data() + k));
    for (int j = 0; j < 8; ++j) ASSERT_EQ(got[j], std::sqrt(u[k + j])) << u[k + j];
  }
  std::vector<float> f(u.begin(), u.end());
  for (std::size_t k = 0; k + 16 <= f.size(); k += 16) {
    const auto got = simd::sqrt(simd::load<simd::f32x16>(f.data() + k));
    for (int j = 0; j < 16; ++j) ASSERT_EQ(got[j], std::sqrt(f[k + j])) << f[k + j];
  }
}

}  // namespace

}  // namespace dpdrng_test::rng_test_unit_math
