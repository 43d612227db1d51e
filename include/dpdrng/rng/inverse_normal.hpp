#pragma once
// Φ⁻¹(u), the inverse of the standard normal CDF, in double precision: one uniform in, one N(0,1) number out,
// with no pairing of uniforms (unlike Box–Muller).
//
// Three rational approximations P(x)/Q(x) of degree 8/8, fitted for least relative error by
// tools/fit_inverse_normal.py (Sanathanan–Koerner iteration with Lawson reweighting, 60 digits):
//  - centre, |q| ≤ 0.425 with q = u − ½:  Φ⁻¹(u) = q·P(x)/Q(x), x = 0.425² − q²;
//  - near tail, t = √(−2·log p) in [t0, 9], p = min(u, 1 − u), t0 = t(0.075):  |Φ⁻¹(u)| = P(t − t0)/Q(t − t0);
//  - far tail, t in [9, 38] (p down to 2^-1022):  |Φ⁻¹(u)| = P(t − 9)/Q(t − 9).
// Each fit is below 2e-18 relative, so the result's error is the rounding of the evaluation. Every coefficient is
// positive, so the Horner sums do not cancel. The centre is expanded about its edge: in powers of q² the
// numerator and denominator both nearly vanish at |q| = 0.425 and would lose three digits there.
//
// Domain: u in [2^-1022, 1 − 2^-53] (a normal p); 0 and 1 are outside. 1 − u is exact for u ≥ ½, and q = u − ½
// is exact for every u on the 2^-53 grid (for other u below ¼ it is rounded once).
// Accuracy against MPFR and GSL's gsl_cdf_ugaussian_Pinv: tests/rng/test_inverse_normal.cpp.
//
// Branch-free as unit_math.hpp: every lane computes the log and the square root, and the piece is chosen by
// selecting coefficients, so the batched form runs the same operations in SIMD lanes and gives the same bits
// (the build has -ffp-contract=off; products are fused only where std::fma says so).
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "dpdrng/rng/simd.hpp"
#include "dpdrng/rng/unit_math.hpp"

namespace dpdrng::rng {

namespace inverse_normal_detail {
inline constexpr int kDegree = 8;
inline constexpr double kCentreEdge = 0x1.71eb851eb851fp-3;  // 0.425², the centre's x = kCentreEdge − q²
inline constexpr double kNearShift = 0x1.23568c24a29e0p+1;   // t0 = √(−2·log 0.075)
inline constexpr double kFarShift = 9.0;

inline constexpr double kCentreP[] = {0x1.b18d91e9eef76p+1, 0x1.3380569974dc9p+7, 0x1.56415b4cc6705p+11,
                                      0x1.7c1e5c0637d30p+14, 0x1.bbcf1ba1f383bp+16, 0x1.07d181df0e3c7p+18,
                                      0x1.1cebb2b67d926p+18, 0x1.ac951c3a15425p+16, 0x1.8d97068a52dbfp+12};
inline constexpr double kCentreQ[] = {0x1.0000000000000p+0,  0x1.832ebf351ddadp+5,  0x1.d1e0bbd9a4d92p+9,
                                      0x1.1d1a0a64163d8p+13, 0x1.792d40cc70328p+15, 0x1.0931d6fd06065p+17,
                                      0x1.6c82fcd2fec64p+17, 0x1.95b1c863ec514p+16, 0x1.cb625fb0df5f4p+13};
inline constexpr double kNearP[] = {0x1.7085226d3e525p+0,  0x1.a670d8aa20c00p+1,  0x1.7691b8d6fcdb7p+1,
                                    0x1.5802a7a9391bbp+0,  0x1.6b2eef744a339p-2,  0x1.c6fa2d9a944f6p-5,
                                    0x1.48b99fa95fcf2p-8,  0x1.e6501f85020dcp-13, 0x1.08788f3b4928dp-18};
inline constexpr double kNearQ[] = {0x1.0000000000000p+0,  0x1.7474fe474aa36p+0,  0x1.b662372234b61p-1,
                                    0x1.0e7c2bf14f40cp-2,  0x1.7a1ba95e1b833p-5,  0x1.28efc35ad1f88p-8,
                                    0x1.d399ed2cac7cdp-13, 0x1.08731bf06ce42p-18, 0x1.f58b379830d72p-40};
inline constexpr double kFarP[] = {0x1.14cc26e641fe8p+3,  0x1.107eac7f6e989p+2,  0x1.b6529f9504ac9p-1,
                                   0x1.7350baf296935p-4,  0x1.6422cdb54cc26p-8,  0x1.82d76142a6cb6p-13,
                                   0x1.c2132691af8cap-19, 0x1.ea8044258ca48p-26, 0x1.67b00963e7924p-34};
inline constexpr double kFarQ[] = {0x1.0000000000000p+0,  0x1.7e73a86fa0215p-2,  0x1.c1bd9da0d703ap-5,
                                   0x1.08b15b0463d02p-8,  0x1.489be357b4103p-13, 0x1.a08ee39ad833cp-19,
                                   0x1.dddbbb78fdaa2p-26, 0x1.67afe182ecd14p-34, 0x1.a50cab0beda8cp-64};

// The coefficient of the selected piece: selects, not an indexed load, so that SIMD lanes need no gather.
inline double pick(bool centre, bool far, double c, double n, double f) { return centre ? c : (far ? f : n); }

// P(x)/Q(x) of one piece, by the same operations in the same order as the selecting form below.
inline double rational(double x, const double* p, const double* q) {
  double num = p[kDegree], den = q[kDegree];
#pragma GCC unroll 8
  for (int k = kDegree - 1; k >= 0; --k) {
    num = std::fma(num, x, p[k]);
    den = std::fma(den, x, q[k]);
  }
  return num / den;
}
}  // namespace inverse_normal_detail

// The parts before and after the one square root, so that the batched form can take it with the SIMD
// instruction (libm's sqrt may set errno, which stops GCC from vectorising a loop around it).
// First part: t² = −2·log(min(u, 1 − u)).
inline double inverse_normal_radius2(double u) {
  const double p = u < 0.5 ? u : 1.0 - u;
  return -2.0 * math::log_unit(p);
}

// Second part: Φ⁻¹(u) given t = √(inverse_normal_radius2(u)).
inline double inverse_normal_finish(double u, double t) {
  using namespace inverse_normal_detail;
  const double q = u - 0.5;
  const bool centre = std::fabs(q) <= 0.425;
  const bool far = t > kFarShift;
  const double x = centre ? std::fma(-q, q, kCentreEdge) : t - (far ? kFarShift : kNearShift);
  double num = pick(centre, far, kCentreP[kDegree], kNearP[kDegree], kFarP[kDegree]);
  double den = pick(centre, far, kCentreQ[kDegree], kNearQ[kDegree], kFarQ[kDegree]);
#pragma GCC unroll 8
  for (int k = kDegree - 1; k >= 0; --k) {
    num = std::fma(num, x, pick(centre, far, kCentreP[k], kNearP[k], kFarP[k]));
    den = std::fma(den, x, pick(centre, far, kCentreQ[k], kNearQ[k], kFarQ[k]));
  }
  const double scale = centre ? q : (q < 0.0 ? -1.0 : 1.0);
  return scale * (num / den);
}

// The scalar form branches where the batched one selects: the centre (85 % of uniforms) skips the log and the
// square root. Each branch runs the operations the selecting form runs for that piece, so the bits agree.
inline double inverse_normal(double u) {
  using namespace inverse_normal_detail;
  const double q = u - 0.5;
  if (std::fabs(q) <= 0.425) return q * rational(std::fma(-q, q, kCentreEdge), kCentreP, kCentreQ);
  const double t = std::sqrt(inverse_normal_radius2(u));
  const double z = t > kFarShift ? rational(t - kFarShift, kFarP, kFarQ) : rational(t - kNearShift, kNearP, kNearQ);
  return q < 0.0 ? -1.0 * z : 1.0 * z;
}

// z[i] = inverse_normal(u[i]) for i < n, bit for bit, eight at a time.
inline void inverse_normal(const double* u, double* z, std::size_t n) {
  std::size_t c = 0;
  for (; c + 8 <= n; c += 8) {
    alignas(64) double t[8];
    for (std::size_t j = 0; j < 8; ++j) t[j] = inverse_normal_radius2(u[c + j]);
    simd::store(t, simd::sqrt(simd::load<simd::f64x8>(t)));
    for (std::size_t j = 0; j < 8; ++j) z[c + j] = inverse_normal_finish(u[c + j], t[j]);
  }
  for (; c < n; ++c) z[c] = inverse_normal(u[c]);
}

// A 52-bit uniform on the odd multiples of 2^-53, (2k + 1)·2^-53 for k = w >> 12: strictly inside (0, 1) from
// 2^-53 to 1 − 2^-53, symmetric about ½ (so Φ⁻¹ of it has mean exactly zero over the grid), every value exact.
constexpr double to_unit_mid(std::uint64_t w) { return static_cast<double>(((w >> 12) << 1) | 1u) * 0x1p-53; }

}  // namespace dpdrng::rng
