#pragma once
// One convention for binomial proportions, shared by the cells, the report and the CLI: the central
// (equal-tailed) Clopper–Pearson interval and the two-sided exact test that agrees with it,
//   p = min(1, 2·min(P[X ≤ k], P[X ≥ k])),  X ~ Binomial(n, p0),
// so that "p < 1 − confidence" holds exactly when the central Clopper–Pearson interval at that confidence
// excludes p0. (R's binom.test sums the outcomes no more likely than k instead; its P-value can be half of
// this one, and then calls "different" a p0 that its own interval contains.)
#include <cstddef>
#include <utility>

namespace dpdrng::stats {

// Central Clopper–Pearson ("exact") interval for successes / trials: each tail holds (1 − confidence)/2.
// Returns {low, high}; {0, 1} for no trials.
std::pair<double, double> clopper_pearson(std::size_t successes, std::size_t trials, double confidence);

// The central two-sided exact binomial test of "success probability = p0" (see above). 1 for no trials.
double binomial_test_p(std::size_t successes, std::size_t trials, double p0);

}  // namespace dpdrng::stats
