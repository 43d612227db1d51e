#include "dpdrng/stats/multiple.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

std::vector<double> holm_adjust(std::span<const double> p) {
  std::vector<double> out(p.size(), NAN);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::isfinite(p[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  const double m = double(order.size());
  double running = 0;
  for (std::size_t j = 0; j < order.size(); ++j) {
    running = std::max(running, std::min(1.0, (m - double(j)) * p[order[j]]));
    out[order[j]] = running;
  }
  return out;
}

double stouffer_two_sided(std::span<const double> p, std::span<const double> sign) {
  if (p.size() != sign.size()) throw InputError("Stouffer: as many signs as P-values are needed");
  double z = 0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p[i]) || !std::isfinite(sign[i])) continue;
    // Φ⁻¹(1 − p/2) through the upper tail, which keeps its digits for tiny p.
    const double zi = gsl_cdf_ugaussian_Qinv(std::clamp(p[i], 1e-300, 1.0) / 2);
    z += (sign[i] < 0 ? -zi : sign[i] > 0 ? zi : 0.0);
    ++k;
  }
  if (k == 0) return NAN;
  z /= std::sqrt(double(k));
  return std::min(1.0, 2 * gsl_cdf_ugaussian_Q(std::fabs(z)));
}

}  // namespace dpdrng::stats
