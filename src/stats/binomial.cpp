#include "dpdrng/stats/binomial.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

namespace {

// Beta quantile: GSL's Newton-based inverse, checked against the forward CDF; bisection on the CDF (monotone,
// so it always converges) where the inverse fails, which it does for very unequal shape parameters
// (e.g. a = 792, b = 9 gives NaN).
double beta_quantile(double prob, double a, double b) {
  const double q = gsl_cdf_beta_Pinv(prob, a, b);
  if (std::isfinite(q) && q >= 0.0 && q <= 1.0 && std::fabs(gsl_cdf_beta_P(q, a, b) - prob) <= 1e-10 * prob)
    return q;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (gsl_cdf_beta_P(mid, a, b) < prob ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

unsigned int as_uint(std::size_t n) {
  if (n > std::numeric_limits<unsigned int>::max()) throw InputError("binomial test: more than 2^32 - 1 trials");
  return static_cast<unsigned int>(n);
}

void check(std::size_t successes, std::size_t trials) {
  if (successes > trials) throw InputError("binomial test: more successes than trials");
}

}  // namespace

std::pair<double, double> clopper_pearson(std::size_t successes, std::size_t trials, double confidence) {
  check(successes, trials);
  if (!(confidence > 0.0 && confidence < 1.0)) throw InputError("Clopper-Pearson: confidence must lie in (0,1)");
  if (trials == 0) return {0.0, 1.0};
  const double x = static_cast<double>(successes), n = static_cast<double>(trials);
  const double tail = 0.5 * (1.0 - confidence);
  const double low = successes == 0 ? 0.0 : beta_quantile(tail, x, n - x + 1.0);
  const double high = successes == trials ? 1.0 : beta_quantile(1.0 - tail, x + 1.0, n - x);
  return {low, high};
}

double binomial_test_p(std::size_t successes, std::size_t trials, double p0) {
  check(successes, trials);
  if (!(p0 >= 0.0 && p0 <= 1.0)) throw InputError("binomial test: p0 must lie in [0,1]");
  if (trials == 0) return 1.0;
  const unsigned int n = as_uint(trials), k = as_uint(successes);
  const double at_most = gsl_cdf_binomial_P(k, p0, n);
  const double at_least = k == 0 ? 1.0 : gsl_cdf_binomial_Q(k - 1, p0, n);
  return std::min(1.0, 2.0 * std::min(at_most, at_least));
}

}  // namespace dpdrng::stats
