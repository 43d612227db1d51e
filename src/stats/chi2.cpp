#include "dpdrng/stats/chi2.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_gamma.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"

namespace dpdrng::stats {

int sturges_bins(std::size_t n) {
  if (n <= 1) return 1;
  // ceil(log2 n) is the bit width of n − 1 for n >= 2.
  return 1 + static_cast<int>(std::bit_width(n - 1));
}

double chi2_upper_tail(double x, int dof) {
  if (x <= 0.0) return 1.0;
  gsl_sf_result r;
  const int status = gsl_sf_gamma_inc_Q_e(0.5 * dof, 0.5 * x, &r);
  // Underflow means the tail is below the smallest double: zero is the honest answer.
  if (status == GSL_EUNDRFLW) return 0.0;
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("chi2 tail: GSL gamma_inc_Q failed: ") + gsl_strerror(status));
  return r.val;
}

namespace {

void check_unit_interval(std::span<const double> u01) {
  // A count without an early exit vectorises; the offending value is looked for only when there is one.
  std::size_t outside = 0;
  for (const double u : u01) outside += !((u >= 0.0) & (u < 1.0));
  if (outside == 0) return;
  for (std::size_t i = 0; i < u01.size(); ++i) {
    const double u = u01[i];
    // Written so that NaN fails the test too.
    if (!(u >= 0.0 && u < 1.0))
      throw InputError("chi2: value " + std::to_string(i) + " is " + std::to_string(u) +
                       ", outside [0,1) (use --format u64 for generator words)");
  }
}

// Four histograms take consecutive values in turn and are summed at the end, so that increments of one bin do
// not wait for each other (the counts are integers: the same whatever the order). unit(v) is v's value in [0,1).
template <class T, class Unit>
std::vector<std::uint64_t> histogram(std::span<const T> values, int bins, Unit unit) {
  const auto w = static_cast<std::size_t>(bins);
  std::vector<std::uint64_t> four(4 * w, 0);
  const double k = bins;
  // u < 1 keeps u*k below k in round-to-nearest for every k; the clamp is a guard, not a correction.
  const auto bin = [&, last = w - 1](const T& v) { return std::min(static_cast<std::size_t>(unit(v) * k), last); };
  std::size_t t = 0;
  for (; t + 4 <= values.size(); t += 4)
    ++four[bin(values[t])], ++four[w + bin(values[t + 1])], ++four[2 * w + bin(values[t + 2])],
        ++four[3 * w + bin(values[t + 3])];
  for (; t < values.size(); ++t) ++four[bin(values[t])];
  std::vector<std::uint64_t> counts(w);
  for (std::size_t b = 0; b < w; ++b) counts[b] = four[b] + four[w + b] + four[2 * w + b] + four[3 * w + b];
  return counts;
}

void check_options(const Chi2Options& options) {
  if (options.bins < 0 || options.bins == 1) throw InputError("chi2: the bin count must be at least 2");
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) throw InputError("chi2: alpha must lie in (0,1)");
}

// The test on n values whose histogram count(bins) gives.
template <class Count>
Chi2Result chi2_of(std::size_t n, const Chi2Options& options, Count count) {
  Chi2Result res;
  res.n = n;
  res.alpha = options.alpha;
  res.bins = options.bins > 0 ? options.bins : sturges_bins(res.n);
  res.dof = res.bins - 1;
  res.expected = static_cast<double>(res.n) / res.bins;
  if (res.bins < 2 || res.expected < kMinExpectedPerBin) {
    res.reason = "needs at least " + std::to_string(static_cast<int>(kMinExpectedPerBin)) +
                 " expected values per bin (" + std::to_string(res.n) + " values in " + std::to_string(res.bins) +
                 " bins)";
    return res;
  }
  res.counts = count(res.bins);
  res.statistic = chi2_statistic_equal(res.counts, res.expected);
  res.p_value = chi2_upper_tail(res.statistic, res.dof);
  res.verdict = verdict_at(res.p_value, res.alpha);
  return res;
}

}  // namespace

Chi2Result chi2_uniform(std::span<const double> u01, const Chi2Options& options) {
  check_options(options);
  check_unit_interval(u01);
  return chi2_of(u01.size(), options, [u01](int bins) { return histogram(u01, bins, [](double u) { return u; }); });
}

Chi2Result chi2_uniform_words(std::span<const std::uint64_t> words, const Chi2Options& options) {
  check_options(options);
  return chi2_of(words.size(), options, [words](int bins) {
    return histogram(words, bins, [](std::uint64_t w) { return rng::to_unit(w); });
  });
}

double chi2_statistic_equal(std::span<const std::uint64_t> counts, double expected) {
  double a = 0.0;
  for (const std::uint64_t c : counts) {
    const double d = static_cast<double>(c) - expected;
    a += d * d;
  }
  return a / expected;
}

}  // namespace dpdrng::stats
