// The error model on null studies run by the engine: good generators (Philox4x32-10, SplitMix64,
// Threefry2x64-20) against MT19937 under every noise and two Δt, four studies with their own seeds, each
// comparison a pure-noise shift. The scores of those shifts must not be over-dispersed under the error model the
// verdicts use (the runs' block errors, which the verdicts do not use, are printed beside them), no verdict may
// say "differs", and the check must be able to see standard errors √2 too small.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/measure.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng_test::study_test_error_model {

using namespace dpdrng::study;

namespace {

// Per study 8 references (gauss under three feeds and uniform, at two Δt) × 3 good generators = 24 null
// comparisons per observable, 4 replicas each: 128 short runs of 64 beads; four studies give 96 comparisons.
const std::string kNullStudy = R"([study]
name = "null"
replicas = 4
[sweep]
distributions = ["gauss", "uniform"]
feeds = ["halves", "blocks", "inverse"]
[[sweep.generator]]
name = "philox4x32"
rounds = [10]
[[sweep.generator]]
name = "splitmix64"
[[sweep.generator]]
name = "threefry2x64"
rounds = [20]
[scene]
particles = 64
dt = [0.03, 0.04]
steps = 600
equilibrate = 100
[tests]
chi2_steps = 1
ttest_pairs = 0
nist_generators = []
[cost]
numbers = 1024
)";

}  // namespace

TEST(StudyErrorModel, NullStudyScoresAreNotOverDispersed) {
  std::map<std::string, std::vector<double>> chosen, runs;
  for (int seed : {99, 100, 101, 102}) {
    std::string text = kNullStudy;
    text.insert(text.find("[sweep]"), "seed = " + std::to_string(seed) + "\n");
    const StudyConfig cfg = parse_config(text, "null.toml");
    std::vector<CellResult> cells;
    for (const auto& c : enumerate_cells(cfg)) cells.push_back(measure_cell(c, cfg, 1));
    const Analysis a = analyse(cfg, cells);
    for (const auto& v : a.variants) {
      EXPECT_NE(v.outcome, Outcome::differs) << seed << " " << v.key.label() << " " << v.verdict;
      if (!known_good(v.key)) continue;
      for (const auto& o : v.observables)
        if (o.test == std::string("t"))
          chosen[o.observable].push_back(o.score), runs[o.observable].push_back(o.score_runs);
    }
  }
  ASSERT_EQ(chosen.size(), 11u);  // T, its fluctuation, P, P_xx, P_yy, P_zz, D, T_conf, T_x, T_y, T_z
  for (const auto& [name, z] : chosen) {
    const auto d = dpdrng::stats::score_dispersion(z, 0.99), r = dpdrng::stats::score_dispersion(runs[name], 0.99);
    std::printf("%s: replicas' spread %.2f [%.2f, %.2f], runs' block errors %.2f [%.2f, %.2f], 99 %% CI over %zu\n",
                name.c_str(), d.ratio, d.low, d.high, r.ratio, r.low, r.high, d.k);
    EXPECT_EQ(d.k, 96u) << name;
    // Over-dispersed at 99 %: the model's standard errors are too small for this observable.
    EXPECT_LE(d.low, 1.0) << name;
    // The check resolves standard errors √2 too small at this count: the same scores scaled to a dispersion of 2
    // are seen as over-dispersed.
    std::vector<double> inflated;
    for (const double x : z) inflated.push_back(std::sqrt(2.0 / d.ratio) * x);
    EXPECT_GT(dpdrng::stats::score_dispersion(inflated, 0.99).low, 1.0) << name;
  }
}

}  // namespace dpdrng_test::study_test_error_model
