#pragma once
// t-tests of means with every independent estimate of the noise pooled in. A study compares few replicas
// (3–16), whose spread alone estimates a variance with few degrees of freedom; each run also knows its own
// standard error from block averages, an independent estimate of the same variance with many more.
#include <cstddef>
#include <span>

namespace dpdrng::stats {

// An estimate of the variance of one observation (a run's own block standard error squared, say) with its
// degrees of freedom.
struct VarianceEstimate {
  double variance = 0;
  double dof = 0;
};

struct TTest {
  std::size_t n = 0, m = 0;  // observations (paired: differences, m = 0)
  double diff = 0;           // mean(x) − mean(y); paired: the mean difference
  double sd = 0;             // pooled standard deviation of one observation
  double se = 0;             // standard error of diff
  double dof = 0;            // of the pooled variance
  double t = 0;
  double p_value = 0;        // two-sided; NaN when there is no degree of freedom to estimate the variance
  bool extra_pooled = false; // the extra estimates entered the variance (see below)
  double ci_half_width(double confidence) const;  // t_{dof,(1+c)/2} · se; NaN when p_value is
};

// The extra estimates are pooled only when the samples' own spread is consistent with them: when it is larger
// (one-sided F test of the two variance estimates at kConsistencyLevel), the observations vary for a reason
// the extra estimates cannot see (a run's memory of its initial state, a mode slower than the run), and the
// spread alone is used.
inline constexpr double kConsistencyLevel = 0.05;

// Student's two-sample t-test of equal means with one variance for both samples (R's
// t.test(x, y, var.equal = TRUE) when `extra` is empty). The variance is pooled from both samples' spreads and
// the extra estimates, each weighted by its degrees of freedom. An observation's variance is the same under the
// null of identical sources, which is what a study tests. Needs at least one value on each side.
TTest pooled_t(std::span<const double> x, std::span<const double> y, std::span<const VarianceEstimate> extra = {});

// Paired t-test on the differences d (R's t.test(x, y, paired = TRUE) when `extra` is empty), the variance of
// one difference pooled from their spread and the extra estimates.
TTest paired_t(std::span<const double> d, std::span<const VarianceEstimate> extra = {});

// The smallest true difference that a two-sided t-test at level `alpha`, with standard error `se` on `dof`
// degrees of freedom, rejects with probability `power`: (t_{dof,1−α/2} + t_{dof,power}) · se. The usual
// approximation of the noncentral t's power (Cohen, Statistical Power Analysis, 1988, ch. 2), exact as dof → ∞;
// it ignores the chance of rejecting on the wrong side, which is below α/2. NaN for dof ≤ 0 or se not finite.
double detectable_difference(double se, double dof, double alpha, double power);

}  // namespace dpdrng::stats
