#include "dpdrng/stats/noise_power.hpp"

#include "dpdrng/stats/summary.hpp"

namespace dpdrng::stats {

Shift independent_shift(const Measured& a, const Measured& b, double confidence) {
  Shift s;
  s.delta = a.mean - b.mean;
  const double va = a.se * a.se, vb = b.se * b.se;
  s.se = std::sqrt(va + vb);
  // An infinite ν contributes nothing to the denominator.
  const double den = (std::isinf(a.dof) ? 0.0 : va * va / a.dof) + (std::isinf(b.dof) ? 0.0 : vb * vb / b.dof);
  s.dof = den > 0 ? (va + vb) * (va + vb) / den : INFINITY;
  if (!(s.se >= 0) || !(s.dof > 0)) return s;
  // GSL's t quantile takes ν = ∞ poorly; 1e9 degrees of freedom are the normal quantile to double precision.
  const double half = t_half_width_factor(std::isinf(s.dof) ? 1e9 : s.dof, confidence) * s.se;
  s.low = s.delta - half, s.high = s.delta + half;
  return s;
}

NoisePower effective_noise_power(const Measured& m2w, std::span<const Measured> rho) {
  double factor = 1.0, rho_var = 0.0;
  for (const Measured& r : rho) factor += 2.0 * r.mean, rho_var += 4.0 * r.se * r.se;
  NoisePower p;
  p.value = m2w.mean * factor;
  p.se = std::sqrt(factor * factor * m2w.se * m2w.se + m2w.mean * m2w.mean * rho_var);
  return p;
}

NoisePower predicted_temperature_ratio(const NoisePower& variant, const NoisePower& reference) {
  NoisePower r;
  r.value = variant.value / reference.value;
  const double a = variant.se / variant.value, b = reference.se / reference.value;
  r.se = std::abs(r.value) * std::sqrt(a * a + b * b);
  return r;
}

}  // namespace dpdrng::stats
