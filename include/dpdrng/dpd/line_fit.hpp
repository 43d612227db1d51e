#pragma once
// The least-squares line y = a + b x, for the fits of the engine and the studies (D from the MSD's slope).
#include <span>

namespace dpdrng::dpd {

struct LineFit {
  double intercept = 0, slope = 0;
};

// Over the points (x[k], y[k]): the normal equations solved in closed form,
//   b = (m Σxy − Σx Σy) / (m Σx² − (Σx)²),  a = (Σy − b Σx) / m,
// with the sums taken in index order. Fewer than two distinct x give {0, 0}. x and y must be equally long.
LineFit fit_line(std::span<const double> x, std::span<const double> y);

}  // namespace dpdrng::dpd
