// Discrete Fourier transform (spectral) test, SP800-22 2.6, on FFTW's real-to-complex transform.
#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {
using namespace detail;

namespace {

// In-place plans, kept for the first kKept lengths the process asks for (a battery needs one). FFTW's planner
// (planning and destroying) must run in one thread at a time, which the mutex ensures; executing a plan may run
// in any number of threads, on arrays of the alignment it was planned for (fftw_malloc's). FFTW_ESTIMATE plans
// without timing anything, so the plan, and with it every rounding, depends only on the length and the
// machine's SIMD. In place, because FFTW's estimated out-of-place plan for 2^20 points takes twice as long (two
// 8 MB arrays instead of one).
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
    Lease(fftw_plan p, bool o) : plan(p), own(o) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() {
      if (own) plans().destroy(plan);
    }
  };

  ~Plans() {
    for (auto& [n, p] : plans_) fftw_destroy_plan(p);
  }
  Lease get(std::size_t n) {
    std::lock_guard lock(mutex_);
    auto it = plans_.find(n);
    if (it != plans_.end()) return {it->second, false};
    const fftw_plan p = plan(n);
    if (plans_.size() >= kKept) return {p, true};
    plans_.emplace(n, p);
    return {p, false};
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
  static fftw_plan plan(std::size_t n) {
    const Buffer<fftw_complex> data(n / 2 + 1);
    const fftw_plan p = fftw_plan_dft_r2c_1d(static_cast<int>(n), reinterpret_cast<double*>(data.data), data.data,
                                             FFTW_ESTIMATE);
    if (!p) throw std::runtime_error("FFTW could not plan a transform of length " + std::to_string(n));
    return p;
  }
  std::mutex mutex_;
  std::map<std::size_t, fftw_plan> plans_;
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

double squared_modulus(const fftw_complex& z) { return z[0] * z[0] + z[1] * z[1]; }

// The smallest q with sqrt(q) >= t (t > 0). sqrt is correctly rounded, hence monotone, so sqrt(q) < t exactly
// when q is below it: the peaks are counted on squared moduli without a square root each.
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

TestResult fft(const BitSequence& s) {
  TestResult r = make(Test::FFT, s.size());
  const std::size_t n = s.size(), h = n / 2;
  if (n < 2) return too_short(r, 2);
  const double nd = static_cast<double>(n);
  const double upper = std::sqrt(2.995732274 * nd);
  // |X_k| < upper, k < n/2
  const double upper2 = square_threshold(upper);
  const fftw_complex* X = transform(s);
  std::size_t count = 0;
  for (std::size_t k = 0; k < h; ++k) count += squared_modulus(X[k]) < upper2;
  const double N_l = static_cast<double>(count), N_o = 0.95 * nd / 2.0;
  const double d = (N_l - N_o) / std::sqrt(nd / 4.0 * 0.95 * 0.05);
  r.parameters = {{"threshold", upper}, {"N0", N_o}, {"N1", N_l}};
  r.values.push_back({"-", d, erfc(std::fabs(d) / std::sqrt(2.0))});
  return r;
}

}  // namespace dpdrng::stats::nist
