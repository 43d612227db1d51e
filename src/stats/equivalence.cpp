#include "dpdrng/stats/equivalence.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

namespace dpdrng::stats {
namespace {
constexpr double kNormalDof = 1e7;  // t beyond this many degrees of freedom differs from Φ by < 1e-7

double t_upper(double t, double dof) { return dof > kNormalDof ? gsl_cdf_ugaussian_Q(t) : gsl_cdf_tdist_Q(t, dof); }
double t_lower(double t, double dof) { return dof > kNormalDof ? gsl_cdf_ugaussian_P(t) : gsl_cdf_tdist_P(t, dof); }
}  // namespace

double equivalence_p(double diff, double se, double dof, double margin) {
  if (!(dof > 0) || !std::isfinite(se) || se < 0 || !(margin > 0) || !std::isfinite(diff)) return NAN;
  if (se == 0) return std::abs(diff) < margin ? 0.0 : 1.0;
  const double above = t_upper((diff + margin) / se, dof);  // H0: Δ ≤ −margin
  const double below = t_lower((diff - margin) / se, dof);  // H0: Δ ≥ margin
  return std::max(above, below);
}

double equivalence_power(double se, double dof, double alpha, double margin) {
  if (!(dof > 0) || !(se > 0) || !std::isfinite(se) || !(margin > 0) || !(alpha > 0 && alpha < 1)) return NAN;
  const double t = dof > kNormalDof ? gsl_cdf_ugaussian_Qinv(alpha) : gsl_cdf_tdist_Qinv(alpha, dof);
  const double room = margin / se - t;
  return room > 0 ? 2 * t_lower(room, dof) - 1 : 0.0;
}

int replicas_for_equivalence(double sd, double ratio, double dof, double alpha, double margin, double power,
                             int max_replicas) {
  const auto at = [&](int r) { return equivalence_power(sd * std::sqrt((1 + 1 / ratio) / r), dof, alpha, margin); };
  if (!(sd > 0) || !(ratio > 0) || !(power > 0 && power < 1) || std::isnan(at(2))) return -1;
  if (at(max_replicas) < power) return 0;
  if (at(2) >= power) return 2;
  int low = 2, high = max_replicas;  // at(low) < power ≤ at(high): the power grows with R
  while (high - low > 1) {
    const int mid = low + (high - low) / 2;
    (at(mid) >= power ? high : low) = mid;
  }
  return high;
}

double normal_score(double t, double dof) {
  if (std::isnan(t) || std::isnan(dof) || !(dof > 0)) return NAN;
  if (std::isinf(t)) return t;
  if (dof > kNormalDof) return t;
  // Through the nearer tail, which keeps its digits far out.
  return t < 0 ? gsl_cdf_ugaussian_Pinv(gsl_cdf_tdist_P(t, dof)) : gsl_cdf_ugaussian_Qinv(gsl_cdf_tdist_Q(t, dof));
}

Dispersion score_dispersion(std::span<const double> z, double confidence) {
  Dispersion d;
  double ss = 0;
  for (const double v : z)
    if (std::isfinite(v)) ss += v * v, ++d.k;
  if (d.k == 0) {
    d.ratio = d.low = d.high = NAN;
    return d;
  }
  const double k = double(d.k), tail = 0.5 * (1 - confidence);
  d.ratio = ss / k;
  d.low = ss / gsl_cdf_chisq_Qinv(tail, k);
  d.high = ss / gsl_cdf_chisq_Pinv(tail, k);
  return d;
}

}  // namespace dpdrng::stats
