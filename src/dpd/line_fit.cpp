#include "dpdrng/dpd/line_fit.hpp"

namespace dpdrng::dpd {

LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = double(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) sx += x[k], sy += y[k], sxx += x[k] * x[k], sxy += x[k] * y[k];
  const double den = m * sxx - sx * sx;
  if (!(den > 0)) return {};
  const double b = (m * sxy - sx * sy) / den;
  return {(sy - b * sx) / m, b};
}

}  // namespace dpdrng::dpd
