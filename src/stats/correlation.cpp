#include "dpdrng/stats/correlation.hpp"

#include <algorithm>
#include <cmath>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/ttest.hpp"
#include "scale.hpp"

namespace dpdrng::stats {

NoiseMatrix NoiseMatrix::pair_major(std::span<const double> data, std::size_t pairs, std::size_t steps) {
  if (data.size() != pairs * steps) throw InputError("noise matrix: data size is not pairs x steps");
  return NoiseMatrix(data, pairs, steps, steps, 1);
}

NoiseMatrix NoiseMatrix::step_major(std::span<const double> data, std::size_t pairs, std::size_t steps) {
  if (data.size() != pairs * steps) throw InputError("noise matrix: data size is not pairs x steps");
  return NoiseMatrix(data, pairs, steps, 1, pairs);
}

namespace {

// Pearson r over couples produced by `visit(f)` calling f(x, y) for each one. Three passes: the largest
// magnitudes (for the exact power-of-two scaling of scale.hpp), the means, then the centred co-moments, which
// keep the digits that the one-pass Σxy − n x̄ ȳ form loses when the means are far from zero.
template <class Visit>
CorrelationResult pooled_pearson(std::string what, Visit&& visit, double alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) throw InputError("correlation: alpha must lie in (0,1)");
  CorrelationResult res;
  res.what = std::move(what);
  res.alpha = alpha;
  bool finite = true, x_varies = false, y_varies = false;
  double x0 = 0.0, y0 = 0.0, x_max = 0.0, y_max = 0.0;
  visit([&](double x, double y) {
    if (res.n == 0) x0 = x, y0 = y;
    finite = finite && std::isfinite(x) && std::isfinite(y);
    x_varies = x_varies || x != x0;
    y_varies = y_varies || y != y0;
    // std::max, not std::fmax (a libm call per value): the same for every value, a NaN (left behind by both,
    // and refused below) included.
    x_max = std::max(x_max, std::fabs(x));
    y_max = std::max(y_max, std::fabs(y));
    ++res.n;
  });
  if (!finite) throw InputError("correlation: the noise contains a value that is not a finite number");
  if (res.n < 3) {
    res.reason = "needs at least 3 couples (has " + std::to_string(res.n) + ")";
    return res;
  }
  if (!x_varies || !y_varies) {
    res.reason = "a constant series: the correlation is undefined";
    return res;
  }
  const double kx = detail::unit_scale(x_max), ky = detail::unit_scale(y_max);
  double sx = 0.0, sy = 0.0;
  visit([&](double x, double y) {
    sx += kx * x;
    sy += ky * y;
  });
  const double mx = sx / static_cast<double>(res.n), my = sy / static_cast<double>(res.n);
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  visit([&](double x, double y) {
    const double dx = kx * x - mx, dy = ky * y - my;
    sxx += dx * dx;
    syy += dy * dy;
    sxy += dx * dy;
  });
  res.dof = res.n - 2;
  res.r = sxy / std::sqrt(sxx * syy);
  // Rounding can push |r| a hair past 1 for exactly proportional data.
  res.r = std::fmax(-1.0, std::fmin(1.0, res.r));
  res.p_value = correlation_p_value(res.r, res.n, &res.statistic);
  res.verdict = verdict_at(res.p_value, alpha);
  return res;
}

}  // namespace

CorrelationResult correlation_ttest(std::span<const double> x, std::span<const double> y, double alpha) {
  if (x.size() != y.size()) throw InputError("correlation: the two series differ in length");
  return pooled_pearson(
      "x vs y",
      [&](auto&& f) {
        for (std::size_t i = 0; i < x.size(); ++i) f(x[i], y[i]);
      },
      alpha);
}

CorrelationResult cross_pair_correlation(const NoiseMatrix& m, std::size_t offset, double alpha) {
  if (offset == 0) throw InputError("cross-pair correlation: the pair offset must be at least 1");
  return pooled_pearson(
      "pair p vs pair p+" + std::to_string(offset) + ", same step",
      [&](auto&& f) {
        for (std::size_t p = 0; p + offset < m.pairs(); ++p)
          for (std::size_t t = 0; t < m.steps(); ++t) f(m(p, t), m(p + offset, t));
      },
      alpha);
}

CorrelationResult cross_pair_correlation(const NoiseMatrix& m, std::span<const std::pair<std::size_t, std::size_t>> rows,
                                         double alpha) {
  for (const auto& [a, b] : rows)
    if (a >= m.pairs() || b >= m.pairs()) throw InputError("cross-pair correlation: a row index is out of range");
  return pooled_pearson(
      "listed pair couples, same step",
      [&](auto&& f) {
        for (const auto& [a, b] : rows)
          for (std::size_t t = 0; t < m.steps(); ++t) f(m(a, t), m(b, t));
      },
      alpha);
}

CorrelationResult across_time_correlation(const NoiseMatrix& m, std::size_t lag, double alpha) {
  if (lag == 0) throw InputError("across-time correlation: the lag must be at least 1");
  return pooled_pearson(
      "step t vs step t+" + std::to_string(lag) + ", same pair",
      [&](auto&& f) {
        for (std::size_t p = 0; p < m.pairs(); ++p)
          for (std::size_t t = 0; t + lag < m.steps(); ++t) f(m(p, t), m(p, t + lag));
      },
      alpha);
}

}  // namespace dpdrng::stats
