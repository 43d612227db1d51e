#include "dpdrng/stats/power_sums.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

PowerSums PowerSums::of(std::span<const double> x) {
  PowerSums s;
  for (double v : x) {
    if (!std::isfinite(v)) throw InputError("moments: non-finite value in the sample");
    s.add(v);
  }
  return s;
}

Moments moments(const PowerSums& s, double target, double alpha) {
  Moments m;
  m.n = s.n;
  if (s.n == 0) {
    m.reason = "empty sample";
    return m;
  }
  const double n = double(s.n);
  const double mean = s.s1 / n, r2 = s.s2 / n, r3 = s.s3 / n, r4 = s.s4 / n;
  m.mean = mean;
  if (s.n < 4) {
    m.reason = "fewer than 4 values";
    return m;
  }
  // Central moments from the raw ones (Kendall & Stuart, The Advanced Theory of Statistics, vol. 1, §3.7).
  const double c2 = r2 - mean * mean;
  const double c3 = r3 - 3 * mean * r2 + 2 * mean * mean * mean;
  const double c4 = r4 - 4 * mean * r3 + 6 * mean * mean * r2 - 3 * mean * mean * mean * mean;
  if (!(c2 > 0)) {
    m.reason = "no spread";
    return m;
  }
  const double z = gsl_cdf_ugaussian_Pinv(0.975);
  m.mean_se = std::sqrt(c2 / n);
  m.variance = c2 * n / (n - 1);
  // Var(s²) = (μ4 − σ⁴ (n − 3)/(n − 1)) / n (Cramér, Mathematical Methods of Statistics, §27.4).
  const double var_se = std::sqrt(std::max(0.0, c4 - c2 * c2 * (n - 3) / (n - 1)) / n);
  m.variance_ci = {m.variance - z * var_se, m.variance + z * var_se};
  m.second_moment = r2;
  const double sm_se = std::sqrt(std::max(0.0, r4 - r2 * r2) / n);
  m.second_moment_ci = {r2 - z * sm_se, r2 + z * sm_se};
  m.skewness = c3 / std::pow(c2, 1.5);
  m.kurtosis = c4 / (c2 * c2);
  m.skewness_se = std::sqrt(6 / n);
  m.kurtosis_se = std::sqrt(24 / n);
  if (sm_se > 0) {
    m.second_moment_z = (r2 - target) / sm_se;
    m.second_moment_p = 2 * gsl_cdf_ugaussian_Q(std::fabs(m.second_moment_z));
    m.verdict = verdict_at(m.second_moment_p, alpha);
  } else {
    m.reason = "constant square";
  }
  return m;
}

}  // namespace dpdrng::stats
