#include "dpdrng/stats/moments.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dpdrng/common/error.hpp"
#include "scale.hpp"

namespace dpdrng::stats {

void MomentSums::add(double x) {
  MomentSums one;
  one.n = 1;
  one.mean = x;
  merge(one);
}

void MomentSums::merge(const MomentSums& o) {
  if (o.n == 0) return;
  if (n == 0) {
    *this = o;
    return;
  }
  const double na = static_cast<double>(n), nb = static_cast<double>(o.n), nn = na + nb;
  const double d = o.mean - mean, dn = d / nn;
  const double m4n = m4 + o.m4 + d * dn * dn * dn * na * nb * (na * na - na * nb + nb * nb) +
                     6.0 * dn * dn * (na * na * o.m2 + nb * nb * m2) + 4.0 * dn * (na * o.m3 - nb * m3);
  const double m3n = m3 + o.m3 + d * dn * dn * na * nb * (na - nb) + 3.0 * dn * (na * o.m2 - nb * m2);
  const double m2n = m2 + o.m2 + d * dn * na * nb;
  mean += dn * nb;
  m2 = m2n;
  m3 = m3n;
  m4 = m4n;
  n += o.n;
}

MomentSums MomentSums::from_powers(std::size_t n, double s1, double s2, double s3, double s4) {
  MomentSums s;
  s.n = n;
  if (n == 0) return s;
  const double mu = s1 / static_cast<double>(n), nd = static_cast<double>(n);
  s.mean = mu;
  // Σ(x − μ)^k expanded with Σx = nμ (Kendall & Stuart, The Advanced Theory of Statistics, vol. 1, §3.7).
  s.m2 = std::max(0.0, s2 - nd * mu * mu);
  s.m3 = s3 - 3 * mu * s2 + 2 * nd * mu * mu * mu;
  s.m4 = std::max(0.0, s4 - 4 * mu * s3 + 6 * mu * mu * s2 - 3 * nd * mu * mu * mu * mu);
  return s;
}

namespace {
Interval around(double centre, double half) { return {centre - half, centre + half}; }
}  // namespace

MomentsResult moments_of(const MomentSums& s, double confidence, double target) {
  if (!(confidence > 0.0 && confidence < 1.0)) throw InputError("moments: confidence must lie in (0,1)");
  if (s.n == 0) throw InputError("moments: no values");
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  MomentsResult r;
  r.n = s.n;
  r.confidence = confidence;
  r.second_moment_target = target;
  const double n = static_cast<double>(s.n);
  const double c2 = s.m2 / n, c3 = s.m3 / n, c4 = s.m4 / n;  // central moments
  r.mean = s.mean;
  r.variance = s.n > 1 ? s.m2 / (n - 1) : nan;
  r.skewness = c3 / std::pow(c2, 1.5);
  r.kurtosis = c4 / (c2 * c2) - 3.0;
  r.second_moment = c2 + s.mean * s.mean;
  if (s.n < 4) {
    r.reason = "fewer than 4 values: no interval";
    r.mean_ci = r.variance_ci = r.second_moment_ci = {nan, nan};
    r.second_moment_p = nan;
    return r;
  }
  const double z = gsl_cdf_ugaussian_Qinv(0.5 * (1.0 - confidence));
  r.mean_ci = around(r.mean, z * std::sqrt(r.variance / n));
  const double s2 = r.variance;
  const double var_s2 = (c4 - s2 * s2 * (n - 3) / (n - 1)) / n;
  r.variance_ci = around(s2, z * std::sqrt(std::max(var_s2, 0.0)));
  // Var(x²) = E x⁴ − (E x²)², E x⁴ from the central moments about the mean μ: c4 + 4μc3 + 6μ²c2 + μ⁴.
  const double mu = s.mean;
  const double raw4 = c4 + 4 * mu * c3 + 6 * mu * mu * c2 + mu * mu * mu * mu;
  const double se = std::sqrt(std::max(raw4 - r.second_moment * r.second_moment, 0.0) * n / (n - 1) / n);
  r.second_moment_ci = around(r.second_moment, z * se);
  r.second_moment_p = se > 0 ? 2.0 * gsl_cdf_ugaussian_Q(std::fabs(r.second_moment - target) / se)
                             : (r.second_moment == target ? 1.0 : 0.0);
  return r;
}

namespace {

// A second-order quantity of the scaled values back in the data's units: NaN (with the reason noted once) when it
// lies outside the range of normal doubles there.
double unscale2(double scaled, double k, std::string& note) {
  const double v = scaled / k / k;
  if (scaled == 0 || std::isnan(scaled) || std::isnormal(v)) return v;
  if (note.empty())
    note = std::string("the variance and <x^2> are ") + (std::isinf(v) ? "above" : "below") +
           " the range of double precision for these values";
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

MomentsResult moments(std::span<const double> x, double confidence, double target) {
  double max_abs = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw InputError("moments: value " + std::to_string(i) + " is not a finite number");
    max_abs = std::max(max_abs, std::fabs(x[i]));
  }
  // On values scaled by a power of two (exact) into [0.5, 1): their powers up to the fourth neither overflow nor
  // underflow, so skewness, kurtosis and the z of the <x^2> test (all scale-free) come out as for values near 1.
  const double k = detail::unit_scale(max_abs);
  MomentSums s;
  for (const double v : x) s.add(v * k);
  MomentsResult r = moments_of(s, confidence, target * k * k);
  r.second_moment_target = target;
  r.mean /= k;
  r.mean_ci = {r.mean_ci.low / k, r.mean_ci.high / k};
  r.variance = unscale2(r.variance, k, r.out_of_range);
  r.variance_ci = {unscale2(r.variance_ci.low, k, r.out_of_range), unscale2(r.variance_ci.high, k, r.out_of_range)};
  r.second_moment = unscale2(r.second_moment, k, r.out_of_range);
  r.second_moment_ci = {unscale2(r.second_moment_ci.low, k, r.out_of_range),
                        unscale2(r.second_moment_ci.high, k, r.out_of_range)};
  return r;
}

}  // namespace dpdrng::stats
