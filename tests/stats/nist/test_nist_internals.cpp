// The spectral test's DFT moduli against slow references: GSL's mixed-radix real FFT and a direct O(n^2) DFT.
#include <gsl/gsl_fft_real.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng_test::stats_nist_test_nist_internals {

using namespace dpdrng::stats::nist;

namespace {

BitSequence random_bits(std::size_t n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<std::uint8_t> bits(n);
  for (auto& b : bits) b = static_cast<std::uint8_t>(g() >> 63);
  return BitSequence::from_bits(bits);
}

// |X_k|, k < n/2, from GSL's mixed-radix real transform (FFTPACK's halfcomplex layout r0 r1 i1 r2 i2 ...).
std::vector<double> gsl_magnitudes(const BitSequence& s) {
  const std::size_t n = s.size();
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = s[i] ? 1.0 : -1.0;
  gsl_fft_real_wavetable* table = gsl_fft_real_wavetable_alloc(n);
  gsl_fft_real_workspace* work = gsl_fft_real_workspace_alloc(n);
  const int status = gsl_fft_real_transform(x.data(), 1, n, table, work);
  gsl_fft_real_workspace_free(work);
  gsl_fft_real_wavetable_free(table);
  EXPECT_EQ(status, 0);
  std::vector<double> mag(n / 2);
  if (!mag.empty()) mag[0] = std::fabs(x[0]);
  for (std::size_t k = 1; k < mag.size(); ++k) mag[k] = std::hypot(x[2 * k - 1], x[2 * k]);
  return mag;
}

// |X_k|, k < n/2, summed term by term in long double.
std::vector<double> direct_magnitudes(const BitSequence& s) {
  const std::size_t n = s.size();
  std::vector<double> mag(n / 2);
  for (std::size_t k = 0; k < mag.size(); ++k) {
    long double re = 0, im = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const long double a = -2 * std::numbers::pi_v<long double> * static_cast<long double>((j * k) % n) / n;
      const long double x = s[j] ? 1 : -1;
      re += x * std::cos(a);
      im += x * std::sin(a);
    }
    mag[k] = static_cast<double>(std::hypot(re, im));
  }
  return mag;
}

// Parseval: the moduli have RMS sqrt(n), the scale of the transform's rounding.
void expect_same_magnitudes(const std::vector<double>& got, const std::vector<double>& want, std::size_t n) {
  ASSERT_EQ(got.size(), want.size()) << "n=" << n;
  const double tol = 1e-9 * std::sqrt(static_cast<double>(n));
  for (std::size_t k = 0; k < want.size(); ++k) ASSERT_NEAR(got[k], want[k], tol) << "n=" << n << " k=" << k;
}

TEST(FftInternals, MagnitudesAgreeWithGslMixedRadix) {
  // Powers of two, even and odd lengths with small factors, a prime, and SP800-22 Appendix B's 10^6.
  for (std::size_t n : {std::size_t{1} << 16, std::size_t{1} << 20, std::size_t{1000000}, std::size_t{19683},
                        std::size_t{78125}, std::size_t{10007}, std::size_t{48}}) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(n));
    std::vector<double> mag;
    dft_magnitudes(s, mag);
    expect_same_magnitudes(mag, gsl_magnitudes(s), n);
  }
}

TEST(FftInternals, MagnitudesAgreeWithADirectDft) {
  for (std::size_t n = 2; n <= 70; ++n) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(1000 + n));
    std::vector<double> mag;
    dft_magnitudes(s, mag);
    expect_same_magnitudes(mag, direct_magnitudes(s), n);
  }
}

// The test compares squared moduli with the smallest square whose root reaches the threshold: the same count as
// the moduli against the threshold (SP800-22 2.6, N1).
TEST(FftInternals, PeakCountIsTheModuliBelowTheThreshold) {
  for (std::size_t n : {std::size_t{1} << 16, std::size_t{100003}, std::size_t{1000}}) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(n + 1));
    std::vector<double> mag;
    dft_magnitudes(s, mag);
    const double T = std::sqrt(2.995732274 * static_cast<double>(n));
    double below = 0;
    for (double m : mag) below += m < T;
    EXPECT_EQ(fft(s).parameters[2].second, below) << "n=" << n;
  }
}

}  // namespace

}  // namespace dpdrng_test::stats_nist_test_nist_internals
