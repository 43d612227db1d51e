#pragma once
// The paper's two tests applied the way the study applies them to a pairs × steps tap: χ² on every step's values
// (one step of the paper's scene = 32 640 pair numbers) and the lag-1 t-test on every pair's series over the
// steps. Feed the verdicts to pass_fraction(verdicts_of(...)).
#include <vector>

#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/ttest.hpp"

namespace dpdrng::stats {

// One χ² result per step, over that step's values of every pair (which must lie in [0,1)).
std::vector<Chi2Result> chi2_per_step(const NoiseMatrix& u01, const Chi2Options& options = {});

// One lag-1 t-test per pair, over that pair's values at consecutive steps.
std::vector<Lag1Result> lag1_per_pair(const NoiseMatrix& m, double alpha = 0.01);

}  // namespace dpdrng::stats
