#pragma once
// Equivalence and the check of an error model: Schuirmann's two one-sided tests of |shift| < δ, the normal
// score of a t statistic, and the dispersion of such scores over comparisons that should be pure noise.
#include <cstddef>
#include <span>

namespace dpdrng::stats {

// Two one-sided tests (Schuirmann, J. Pharmacokin. Biopharm. 15 (1987) 657) of H0: |Δ| ≥ margin against
// H1: |Δ| < margin, for an estimate `diff` of Δ with standard error `se` on `dof` degrees of freedom (Student t):
// p = max(P[T ≥ (diff + margin)/se], P[T ≤ (diff − margin)/se]). Rejecting at α is the same as the (1 − 2α)
// confidence interval diff ± t_{dof,1−α} se lying inside (−margin, margin). NaN when dof ≤ 0, se is not
// finite or margin ≤ 0; with se = 0, 0 inside the margin and 1 outside.
double equivalence_p(double diff, double se, double dof, double margin);

// The chance that those two tests at level `alpha` show equivalence when Δ = 0: the (1 − 2α) interval
// diff ± t_{dof,1−α} se lies inside ±margin exactly when |diff| < margin − t se, and diff/se is taken as Student t
// on dof: 2 F_dof(margin/se − t_{dof,1−α}) − 1, 0 when margin ≤ t se (Chow, Shao & Wang, Sample Size
// Calculations in Clinical Research, 2008, §3.2.3, with the true difference 0). NaN for dof ≤ 0, se ≤ 0 or not
// finite, margin ≤ 0, or α outside (0, 1).
double equivalence_power(double se, double dof, double alpha, double margin);

// The fewest replicas R (2 ≤ R ≤ max_replicas) for which equivalence_power reaches `power` when a replica's value
// has standard deviation `sd` and the reference has `ratio` × R replicas of the same spread, so that
// se = sd √((1 + 1/ratio) / R); `dof` stays as given (more replicas only add degrees of freedom, so R errs high).
// 0 when even max_replicas fall short; −1 for arguments equivalence_power refuses, sd or ratio ≤ 0.
int replicas_for_equivalence(double sd, double ratio, double dof, double alpha, double margin, double power,
                             int max_replicas = 100000);

// The standard-normal quantile of a t statistic's own distribution, Φ⁻¹(F_dof(t)): under the null it is
// N(0, 1) whatever the degrees of freedom, so scores of tests on different dof can be pooled. dof = ∞ (or
// larger than 1e7) is the normal itself. NaN for a t or dof that is not a number or dof ≤ 0.
double normal_score(double t, double dof);

// Mean square of scores that are N(0, 1) under a correct error model, with its central χ² confidence interval
// on k = scores degrees of freedom (k·ratio/χ²_{k,(1±c)/2}): above 1 the model's standard errors are too small.
// Non-finite scores are left out; ratio and bounds NaN when none is left.
struct Dispersion {
  std::size_t k = 0;
  double ratio = 0, low = 0, high = 0;
};
Dispersion score_dispersion(std::span<const double> z, double confidence = 0.95);

}  // namespace dpdrng::stats
