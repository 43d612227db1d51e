#include "dpdrng/stats/ttest.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dpdrng/common/error.hpp"
#include "scale.hpp"

namespace dpdrng::stats {

namespace {

void check_finite(std::span<const double> x, const char* test) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw InputError(std::string(test) + ": value " + std::to_string(i) + " is not a finite number");
}

bool all_equal(std::span<const double> x) {
  return std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); });
}

double max_abs(std::span<const double> x) {
  double m = 0.0;
  // std::max rather than std::fmax (a libm call per value): a NaN is passed over by both.
  for (const double v : x) m = std::max(m, std::fabs(v));
  return m;
}

}  // namespace

std::optional<double> lag1_autocorrelation(std::span<const double> x) {
  // An exactly constant series has no defined r; testing equality first matters because the rounded mean of
  // equal values need not equal them, and the tiny equal residues would give r ≈ (n−1)/n.
  if (x.size() < 2 || all_equal(x)) return std::nullopt;
  const double k = detail::unit_scale(max_abs(x));
  double sum = 0.0;
  for (const double v : x) sum += k * v;
  const double m = sum / static_cast<double>(x.size());
  double c0 = 0.0, c1 = 0.0;
  for (std::size_t t = 0; t < x.size(); ++t) {
    const double d = k * x[t] - m;
    c0 += d * d;
    if (t + 1 < x.size()) c1 += d * (k * x[t + 1] - m);
  }
  if (!(c0 > 0.0)) return std::nullopt;
  return c1 / c0;
}

double correlation_p_value(double r, std::size_t n, double* t_out) {
  const double dof = static_cast<double>(n - 2);
  const double one_minus_r2 = 1.0 - r * r;
  // |r| = 1 only arises from rounding on perfectly (anti)correlated data: t is infinite and p zero.
  const double t = one_minus_r2 > 0.0 ? r * std::sqrt(dof / one_minus_r2)
                                      : std::copysign(std::numeric_limits<double>::infinity(), r);
  if (t_out) *t_out = t;
  if (std::isinf(t)) return 0.0;
  return std::min(1.0, 2.0 * gsl_cdf_tdist_Q(std::fabs(t), dof));
}

Lag1Result lag1_ttest(std::span<const double> x, double alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) throw InputError("ttest: alpha must lie in (0,1)");
  check_finite(x, "ttest");
  Lag1Result res;
  res.n = x.size();
  res.alpha = alpha;
  if (res.n < 3) {
    res.reason = "needs at least 3 values (has " + std::to_string(res.n) + ")";
    return res;
  }
  res.dof = res.n - 2;
  const auto r = lag1_autocorrelation(x);
  if (!r) {
    res.reason = "constant series: the lag-1 correlation is undefined";
    return res;
  }
  res.r = *r;
  res.p_value = correlation_p_value(res.r, res.n, &res.statistic);
  res.verdict = verdict_at(res.p_value, alpha);
  return res;
}

}  // namespace dpdrng::stats
