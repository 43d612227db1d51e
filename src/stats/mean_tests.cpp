#include "dpdrng/stats/mean_tests.hpp"

#include <gsl/gsl_cdf.h>

#include <cmath>

#include "dpdrng/stats/summary.hpp"

namespace dpdrng::stats {

namespace {

// Sum of squared deviations from the mean.
double squares(std::span<const double> x) {
  const double m = mean(x);
  double s = 0;
  for (const double v : x) s += (v - m) * (v - m);
  return s;
}

// diff, se and dof set: t and the two-sided P-value. A zero standard error is certainty either way.
void finish(TTest& r) {
  if (!(r.dof > 0)) {
    r.sd = r.se = r.t = r.p_value = NAN;
    return;
  }
  if (!(r.se > 0)) {
    r.t = r.diff == 0 ? 0 : std::copysign(INFINITY, r.diff);
    r.p_value = r.diff == 0 ? 1.0 : 0.0;
    return;
  }
  r.t = r.diff / r.se;
  r.p_value = std::fmin(1.0, 2.0 * gsl_cdf_tdist_Q(std::fabs(r.t), r.dof));
}

// Pooled variance from a sum of squares on `dof` degrees of freedom plus the extra estimates, unless the sum of
// squares says the observations vary more than the extra estimates allow.
void pool(TTest& r, double ss, double dof, std::span<const VarianceEstimate> extra) {
  double ess = 0, edof = 0;
  for (const auto& e : extra)
    if (e.dof > 0 && std::isfinite(e.variance)) ess += e.dof * e.variance, edof += e.dof;
  const bool consistent =
      !(dof > 0) || !(ess > 0) || gsl_cdf_fdist_Q((ss / dof) / (ess / edof), dof, edof) >= kConsistencyLevel;
  if (edof > 0 && consistent) ss += ess, dof += edof, r.extra_pooled = true;
  r.dof = dof;
  r.sd = dof > 0 ? std::sqrt(ss / dof) : NAN;
}

}  // namespace

double TTest::ci_half_width(double confidence) const {
  if (!std::isfinite(p_value)) return NAN;
  return t_half_width_factor(dof, confidence) * se;
}

double detectable_difference(double se, double dof, double alpha, double power) {
  if (!(dof > 0) || !std::isfinite(se) || !(alpha > 0 && alpha < 1) || !(power > 0 && power < 1)) return NAN;
  return (gsl_cdf_tdist_Qinv(0.5 * alpha, dof) + gsl_cdf_tdist_Pinv(power, dof)) * se;
}

TTest pooled_t(std::span<const double> x, std::span<const double> y, std::span<const VarianceEstimate> extra) {
  TTest r;
  r.n = x.size();
  r.m = y.size();
  if (x.empty() || y.empty()) {
    r.diff = r.sd = r.se = r.dof = r.t = r.p_value = NAN;
    return r;
  }
  r.diff = mean(x) - mean(y);
  pool(r, squares(x) + squares(y), double(x.size() + y.size()) - 2.0, extra);
  r.se = r.sd * std::sqrt(1.0 / double(x.size()) + 1.0 / double(y.size()));
  finish(r);
  return r;
}

TTest paired_t(std::span<const double> d, std::span<const VarianceEstimate> extra) {
  TTest r;
  r.n = d.size();
  if (d.empty()) {
    r.diff = r.sd = r.se = r.dof = r.t = r.p_value = NAN;
    return r;
  }
  r.diff = mean(d);
  pool(r, squares(d), double(d.size()) - 1.0, extra);
  r.se = r.sd / std::sqrt(double(d.size()));
  finish(r);
  return r;
}

}  // namespace dpdrng::stats
