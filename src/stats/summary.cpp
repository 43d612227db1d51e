#include "dpdrng/stats/summary.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

double mean(std::span<const double> x) {
  if (x.empty()) return NAN;
  double s = 0;
  for (const double v : x) s += v;
  return s / double(x.size());
}

double sample_sd(std::span<const double> x) {
  if (x.size() < 2) return NAN;
  const double m = mean(x);
  double s = 0;
  for (const double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / double(x.size() - 1));
}

double median(std::span<const double> x) {
  if (x.empty()) return NAN;
  std::vector<double> v(x.begin(), x.end());
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + long(mid), v.end());
  if (v.size() % 2 == 1) return v[mid];
  const double upper = v[mid];
  const double lower = *std::max_element(v.begin(), v.begin() + long(mid));
  return 0.5 * (lower + upper);
}

double t_half_width_factor(double dof, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) throw InputError("confidence must lie in (0,1)");
  return gsl_cdf_tdist_Qinv(0.5 * (1.0 - confidence), dof);
}

MeanCI mean_ci(std::span<const double> x, double confidence) {
  MeanCI r;
  r.n = x.size();
  r.mean = mean(x);
  r.half_width = x.size() < 2 ? NAN
                              : t_half_width_factor(double(x.size() - 1), confidence) * sample_sd(x) /
                                    std::sqrt(double(x.size()));
  return r;
}

}  // namespace dpdrng::stats
