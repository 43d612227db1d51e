// Discrete Fourier transform (spectral) test, SP800-22 2.6, on GSL's FFT.
#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_fft_real.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// GSL plans for one length, kept per thread: building them costs as much as a transform.
struct ComplexPlan {
  std::size_t n = 0;
  std::unique_ptr<gsl_fft_complex_wavetable, decltype(&gsl_fft_complex_wavetable_free)> table{
      nullptr, &gsl_fft_complex_wavetable_free};
  std::unique_ptr<gsl_fft_complex_workspace, decltype(&gsl_fft_complex_workspace_free)> work{
      nullptr, &gsl_fft_complex_workspace_free};
  std::vector<double> cos_t, sin_t;  // e^{-2 pi i k / 2n}, k < n

  void prepare(std::size_t size) {
    if (n == size) return;
    table.reset(gsl_fft_complex_wavetable_alloc(size));
    work.reset(gsl_fft_complex_workspace_alloc(size));
    if (!table || !work) throw std::runtime_error("GSL FFT allocation failed");
    cos_t.resize(size);
    sin_t.resize(size);
    for (std::size_t k = 0; k < size; ++k) {
      const double a = std::numbers::pi * static_cast<double>(k) / static_cast<double>(size);
      cos_t[k] = std::cos(a);
      sin_t[k] = std::sin(a);
    }
    n = size;
  }
};

// |X_k|, k < n/2, of the +-1 sequence for even n: the n real points packed as n/2 complex ones
// (z_j = x_2j + i x_2j+1), one complex FFT of half the length, then the usual even/odd split
// X_k = E_k + e^{-2 pi i k/n} O_k with E_k = (Z_k + conj Z_{h-k})/2, O_k = (Z_k - conj Z_{h-k})/(2i).
void magnitudes_even(const BitSequence& s, std::vector<double>& mag) {
  const std::size_t n = s.size(), h = n / 2;
  thread_local ComplexPlan plan;
  thread_local std::vector<double> z;
  plan.prepare(h);
  z.resize(2 * h);
  const auto words = s.words();
  for (std::size_t i = 0; i < n; i += 64) {
    const std::uint64_t w = words[i / 64];
    const std::size_t cnt = std::min<std::size_t>(64, n - i);
    for (std::size_t b = 0; b < cnt; ++b) z[i + b] = static_cast<double>(static_cast<int>((w >> (63 - b)) & 1) * 2 - 1);
  }
  if (gsl_fft_complex_forward(z.data(), 1, h, plan.table.get(), plan.work.get()) != 0)
    throw std::runtime_error("GSL FFT failed");
  mag.resize(h);
  for (std::size_t k = 0; k < h; ++k) {
    const std::size_t j = k == 0 ? 0 : h - k;
    const double zr = z[2 * k], zi = z[2 * k + 1], cr = z[2 * j], ci = -z[2 * j + 1];
    const double er = 0.5 * (zr + cr), ei = 0.5 * (zi + ci);
    // (Z_k - conj Z_j) / (2i) = (d_i - i d_r) / 2 with d = Z_k - conj Z_j
    const double orr = 0.5 * (zi - ci), oi = -0.5 * (zr - cr);
    const double wr = plan.cos_t[k], wi = -plan.sin_t[k];
    const double xr = er + wr * orr - wi * oi, xi = ei + wr * oi + wi * orr;
    mag[k] = std::sqrt(xr * xr + xi * xi);
  }
}

// Odd n: GSL's mixed-radix real transform (FFTPACK's layout r0 r1 i1 r2 i2 ..., as in the reference).
void magnitudes_odd(const BitSequence& s, std::vector<double>& mag) {
  const std::size_t n = s.size(), h = n / 2;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = s[i] ? 1.0 : -1.0;
  std::unique_ptr<gsl_fft_real_wavetable, decltype(&gsl_fft_real_wavetable_free)> table(
      gsl_fft_real_wavetable_alloc(n), &gsl_fft_real_wavetable_free);
  std::unique_ptr<gsl_fft_real_workspace, decltype(&gsl_fft_real_workspace_free)> work(
      gsl_fft_real_workspace_alloc(n), &gsl_fft_real_workspace_free);
  if (!table || !work || gsl_fft_real_transform(x.data(), 1, n, table.get(), work.get()) != 0)
    throw std::runtime_error("GSL FFT failed");
  mag.resize(h);
  if (h > 0) mag[0] = std::fabs(x[0]);
  for (std::size_t k = 1; k < h; ++k) mag[k] = std::sqrt(x[2 * k - 1] * x[2 * k - 1] + x[2 * k] * x[2 * k]);
}

}  // namespace

TestResult fft(const BitSequence& s) {
  TestResult r = make(Test::FFT, s.size());
  const std::size_t n = s.size();
  if (n < 2) return too_short(r, 2);
  thread_local std::vector<double> mag;
  if (n % 2 == 0)
    magnitudes_even(s, mag);
  else
    magnitudes_odd(s, mag);
  const double nd = static_cast<double>(n);
  const double upper = std::sqrt(2.995732274 * nd);
  std::size_t count = 0;
  for (double m : mag) count += m < upper;
  const double N_l = static_cast<double>(count), N_o = 0.95 * nd / 2.0;
  const double d = (N_l - N_o) / std::sqrt(nd / 4.0 * 0.95 * 0.05);
  r.parameters = {{"threshold", upper}, {"N0", N_o}, {"N1", N_l}};
  r.values.push_back({"-", d, erfc(std::fabs(d) / std::sqrt(2.0))});
  return r;
}

}  // namespace dpdrng::stats::nist
