// Discrete Fourier transform (spectral) test, SP800-22 2.6, on FFTW's real-to-complex transform.
#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"
#include "fft_wisdom.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// In-place plans, kept for the first kKept lengths the process asks for (a battery needs one). FFTW's planner
// (planning, destroying, wisdom) must run in one thread at a time, which the mutex ensures; executing a plan may
// run in any number of threads, on arrays of the alignment it was planned for (fftw_malloc's). A length the
// shipped wisdom covers gets its plan (FFTW_WISDOM_ONLY: nothing is timed); any other FFTW_ESTIMATE's, which
// times nothing either, so a plan never depends on the machine's load. Its roundings do depend on the plan and
// the SIMD, which is why the count is taken by spectral_peaks_below. In place, because FFTW's estimated
// out-of-place plan for 2^20 points takes twice as long (two 8 MB arrays instead of one).
class Plans;
Plans& plans();

class Plans {
 public:
  static constexpr std::size_t kKept = 8;

  // A plan for length n: a kept one, or (once kKept lengths are kept) one of the holder's own, destroyed with
  // it, so that a caller sweeping lengths (a fuzzer) does not keep a plan for every length it ever tried.
  struct Lease {
    fftw_plan plan;
    bool own;
    bool from_wisdom;
    Lease(fftw_plan p, bool o, bool w) : plan(p), own(o), from_wisdom(w) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() {
      if (own) plans().destroy(plan);
    }
  };

  Plans() { import_shipped(); }
  ~Plans() {
    for (auto& [n, m] : plans_) fftw_destroy_plan(m.plan);
  }
  Lease get(std::size_t n) {
    std::lock_guard lock(mutex_);
    auto it = plans_.find(n);
    if (it != plans_.end()) return {it->second.plan, false, it->second.from_wisdom};
    const Made m = plan(n);
    if (plans_.size() >= kKept) return {m.plan, true, m.from_wisdom};
    plans_.emplace(n, m);
    return {m.plan, false, m.from_wisdom};
  }
  // The wisdom FFTW_PATIENT finds for length n now, the shipped wisdom forgotten first (plans made from it stay
  // valid) and imported again after.
  std::string patient_wisdom(std::size_t n) {
    std::lock_guard lock(mutex_);
    fftw_forget_wisdom();
    const fftw_plan p = make(n, FFTW_PATIENT);
    if (!p) throw std::runtime_error("FFTW could not plan a transform of length " + std::to_string(n));
    char* text = fftw_export_wisdom_to_string();
    std::string out = text ? text : "";
    fftw_free(text);
    fftw_destroy_plan(p);
    fftw_forget_wisdom();
    import_shipped();
    return out;
  }
  void destroy(fftw_plan p) {
    std::lock_guard lock(mutex_);
    fftw_destroy_plan(p);
  }

  template <class T>
  struct Buffer {
    explicit Buffer(std::size_t count) : data(static_cast<T*>(fftw_malloc(sizeof(T) * count))) {
      if (!data) throw std::bad_alloc();
    }
    ~Buffer() { fftw_free(data); }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    T* data;
  };

 private:
  struct Made {
    fftw_plan plan;
    bool from_wisdom;
  };
  static void import_shipped() { fftw_import_wisdom_from_string(detail::kFftWisdom); }
  // An in-place plan for length n on an array of fftw_malloc's alignment, or null.
  static fftw_plan make(std::size_t n, unsigned flags) {
    const Buffer<fftw_complex> data(n / 2 + 1);
    return fftw_plan_dft_r2c_1d(static_cast<int>(n), reinterpret_cast<double*>(data.data), data.data, flags);
  }
  static Made plan(std::size_t n) {
    if (const fftw_plan p = make(n, FFTW_PATIENT | FFTW_WISDOM_ONLY)) return {p, true};
    const fftw_plan p = make(n, FFTW_ESTIMATE);
    if (!p) throw std::runtime_error("FFTW could not plan a transform of length " + std::to_string(n));
    return {p, false};
  }
  std::mutex mutex_;
  std::map<std::size_t, Made> plans_;
};

Plans& plans() {
  static Plans p;
  return p;
}

// Per-thread array, the n real inputs overwritten by the n/2+1 complex outputs; grown to the longest sequence.
struct Array {
  std::size_t capacity = 0;
  std::unique_ptr<Plans::Buffer<fftw_complex>> data;

  fftw_complex* get(std::size_t n) {
    if (n > capacity) {
      data = std::make_unique<Plans::Buffer<fftw_complex>>(n / 2 + 1);
      capacity = n;
    }
    return data->data;
  }
};

// x_i = 2 s_i - 1, a word's 64 bits at a time.
void fill_plus_minus_one(const BitSequence& s, double* x) {
  const std::size_t n = s.size();
  const auto words = s.words();
  for (std::size_t i = 0; i < n; i += 64) {
    const std::uint64_t w = words[i / 64];
    const std::size_t cnt = std::min<std::size_t>(64, n - i);
    for (std::size_t b = 0; b < cnt; ++b) x[i + b] = ((w >> (63 - b)) & 1) ? 1.0 : -1.0;
  }
}

}  // namespace

namespace {

// X_0 .. X_{n/2} of x_i = 2 s_i - 1, n >= 2, in a per-thread array valid until the thread's next call.
const fftw_complex* transform(const BitSequence& s) {
  const std::size_t n = s.size();
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::invalid_argument("FFT: sequence longer than FFTW's int lengths");
  const Plans::Lease plan = plans().get(n);
  thread_local Array a;
  fftw_complex* X = a.get(n);
  double* x = reinterpret_cast<double*>(X);
  fill_plus_minus_one(s, x);
  fftw_execute_dft_r2c(plan.plan, x, X);
  return X;
}

double squared_modulus(const double* z) { return z[0] * z[0] + z[1] * z[1]; }

// The smallest q with sqrt(q) >= t (t > 0). sqrt is correctly rounded, hence monotone, so sqrt(q) < t exactly
// when q is below it: moduli are compared on their squares without a square root each.
double square_threshold(double t) {
  double q = t * t;
  while (std::sqrt(q) < t) q = std::nextafter(q, INFINITY);
  while (std::sqrt(std::nextafter(q, 0.0)) >= t) q = std::nextafter(q, 0.0);
  return q;
}

}  // namespace

void dft_magnitudes(const BitSequence& s, std::vector<double>& mag) {
  const std::size_t h = s.size() / 2;
  mag.resize(h);
  if (h == 0) return;
  const fftw_complex* X = transform(s);
  for (std::size_t k = 0; k < h; ++k) mag[k] = std::sqrt(squared_modulus(X[k]));
}

double direct_modulus(const BitSequence& s, std::size_t k) {
  const std::size_t n = s.size();
  if (n == 0 || k >= n) throw std::invalid_argument("direct_modulus: k must be below the sequence length");
  long double re = 0, im = 0;
  std::size_t phase = 0;  // j·k mod n, kept exact
  for (std::size_t j = 0; j < n; ++j) {
    const long double a = -2.0L * std::numbers::pi_v<long double> * static_cast<long double>(phase) /
                          static_cast<long double>(n);
    const long double x = s[j] ? 1.0L : -1.0L;
    re += x * std::cos(a), im += x * std::sin(a);
    phase += k;
    if (phase >= n) phase -= n;
  }
  return static_cast<double>(std::sqrt(re * re + im * im));
}

// A double-precision FFT of n points is off in any output by at most c·log2(n)·u·‖X‖₂ (Higham, Accuracy and
// Stability of Numerical Algorithms, §24.1), ‖X‖₂ = n for inputs of ±1 and c a small constant: 1.2e-8 at 2^20
// with c = 5. The band, 2^-44·n·log2(n) (1.2e-6 there), is a hundred times that. |X_k|²/n is about exponential
// with mean 1, so a modulus lies inside the band with probability 2·band·(2T/n)·e^(−T²/n): about one in 4 700
// sequences of 2^20 bits has one to recompute.
double spectral_band(std::size_t n) {
  const double nd = static_cast<double>(std::max<std::size_t>(n, 2));
  return 0x1p-44 * nd * std::log2(nd);
}

std::size_t spectral_peaks_below(const BitSequence& s, const double* X, double T, double band) {
  const std::size_t h = s.size() / 2;
  const double low = square_threshold(T - band), high = square_threshold(T + band);
  // Below the band, and inside it: two plain counts that vectorise; the moduli inside it are found afterwards.
  std::size_t below = 0, inside = 0;
  for (std::size_t k = 0; k < h; ++k) {
    const double q = squared_modulus(X + 2 * k);
    below += q < low;
    inside += (q >= low) & (q < high);
  }
  for (std::size_t k = 0; inside > 0 && k < h; ++k) {
    const double q = squared_modulus(X + 2 * k);
    if (q < low || q >= high) continue;
    below += direct_modulus(s, k) < T;
    --inside;
  }
  return below;
}

std::string fft_plan(std::size_t n) {
  if (n < 2 || n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::invalid_argument("FFT: length out of FFTW's range");
  return plans().get(n).from_wisdom ? "FFTW wisdom (FFTW_PATIENT)" : "FFTW_ESTIMATE";
}

std::string fft_patient_wisdom(std::size_t n) {
  if (n < 2 || n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::invalid_argument("FFT: length out of FFTW's range");
  return plans().patient_wisdom(n);
}

TestResult fft(const BitSequence& s) {
  TestResult r = make(Test::FFT, s.size());
  const std::size_t n = s.size();
  if (n < 2) return too_short(r, 2);
  const double nd = static_cast<double>(n);
  const double upper = std::sqrt(2.995732274 * nd);
  // |X_k| < upper, k < n/2
  const fftw_complex* X = transform(s);
  const std::size_t count = spectral_peaks_below(s, reinterpret_cast<const double*>(X), upper, spectral_band(n));
  const double N_l = static_cast<double>(count), N_o = 0.95 * nd / 2.0;
  const double d = (N_l - N_o) / std::sqrt(nd / 4.0 * 0.95 * 0.05);
  r.parameters = {{"threshold", upper}, {"N0", N_o}, {"N1", N_l}};
  r.values.push_back({"-", d, erfc(std::fabs(d) / std::sqrt(2.0))});
  return r;
}

}  // namespace dpdrng::stats::nist
