#include "dpdrng/stats/pass_fraction.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

namespace {

// Beta quantile: GSL's Newton-based inverse, checked against the forward CDF; bisection on the CDF (monotone,
// so it always converges) where the inverse fails, which it can for very unequal shape parameters.
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
  if (n > std::numeric_limits<unsigned int>::max()) throw InputError("pass fraction: more than 2^32 - 1 trials");
  return static_cast<unsigned int>(n);
}

}  // namespace

std::pair<double, double> clopper_pearson(std::size_t successes, std::size_t trials, double confidence) {
  if (trials == 0) return {0.0, 1.0};
  const double x = static_cast<double>(successes), n = static_cast<double>(trials);
  const double tail = 0.5 * (1.0 - confidence);
  const double low = successes == 0 ? 0.0 : beta_quantile(tail, x, n - x + 1.0);
  const double high = successes == trials ? 1.0 : beta_quantile(1.0 - tail, x + 1.0, n - x);
  return {low, high};
}

double binomial_test_p(std::size_t successes, std::size_t trials, double p) {
  const unsigned int n = as_uint(trials), x = as_uint(successes);
  const double mean = static_cast<double>(n) * p;
  if (static_cast<double>(x) == mean) return 1.0;
  // Outcomes "no more likely than x" (up to R's relative tolerance, so that ties of equal probability count).
  const double bound = gsl_ran_binomial_pdf(x, p, n) * (1.0 + 1e-7);
  double total = 0.0;
  if (static_cast<double>(x) < mean) {
    // The probabilities fall monotonically on [ceil(mean), n]: find the first one at or below the bound.
    long lo = static_cast<long>(std::ceil(mean)), hi = static_cast<long>(n);
    long first = static_cast<long>(n) + 1;
    while (lo <= hi) {
      const long mid = lo + (hi - lo) / 2;
      if (gsl_ran_binomial_pdf(static_cast<unsigned int>(mid), p, n) <= bound) {
        first = mid;
        hi = mid - 1;
      } else {
        lo = mid + 1;
      }
    }
    total = gsl_cdf_binomial_P(x, p, n) +
            (first <= static_cast<long>(n) ? gsl_cdf_binomial_Q(static_cast<unsigned int>(first - 1), p, n) : 0.0);
  } else {
    // Rising on [0, floor(mean)]: the outcomes at or below the bound are 0 .. last.
    long lo = 0, hi = static_cast<long>(std::floor(mean));
    long last = -1;
    while (lo <= hi) {
      const long mid = lo + (hi - lo) / 2;
      if (gsl_ran_binomial_pdf(static_cast<unsigned int>(mid), p, n) <= bound) {
        last = mid;
        lo = mid + 1;
      } else {
        hi = mid - 1;
      }
    }
    total = gsl_cdf_binomial_Q(x - 1, p, n) +
            (last >= 0 ? gsl_cdf_binomial_P(static_cast<unsigned int>(last), p, n) : 0.0);
  }
  return std::min(1.0, total);
}

PassFraction pass_fraction(std::size_t passed, std::size_t trials, const PassFractionOptions& options) {
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) throw InputError("pass fraction: alpha must lie in (0,1)");
  if (!(options.confidence > 0.0 && options.confidence < 1.0))
    throw InputError("pass fraction: the confidence level must lie in (0,1)");
  if (passed > trials) throw InputError("pass fraction: more passes than trials");
  PassFraction pf;
  pf.trials = trials;
  pf.passed = passed;
  pf.confidence = options.confidence;
  pf.expected = 1.0 - options.alpha;
  if (trials == 0) {
    pf.reason = "no applicable test to count";
    return pf;
  }
  pf.fraction = static_cast<double>(passed) / static_cast<double>(trials);
  std::tie(pf.ci_low, pf.ci_high) = clopper_pearson(passed, trials, options.confidence);
  pf.binomial_p = binomial_test_p(passed, trials, pf.expected);
  pf.verdict = verdict_at(pf.binomial_p, 1.0 - options.confidence);
  return pf;
}

PassFraction pass_fraction(std::span<const Verdict> verdicts, const PassFractionOptions& options) {
  const auto passed = static_cast<std::size_t>(std::count(verdicts.begin(), verdicts.end(), Verdict::pass));
  const auto na = static_cast<std::size_t>(std::count(verdicts.begin(), verdicts.end(), Verdict::not_applicable));
  PassFraction pf = pass_fraction(passed, verdicts.size() - na, options);
  pf.not_applicable = na;
  return pf;
}

}  // namespace dpdrng::stats
