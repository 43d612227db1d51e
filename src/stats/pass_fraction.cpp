#include "dpdrng/stats/pass_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

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
