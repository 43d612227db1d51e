// A run's own standard errors, which the study pools with the replicas' spread: they must be the errors of the
// run's estimates, with the degrees of freedom they claim. Checked on AR(1) series, whose integrated
// autocorrelation time is known in closed form, and on the jackknife curves of a short water run against the
// identity every leave-one-out set satisfies.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/splitmix.hpp"

namespace dpdrng_test::dpd_test_run_errors {

using namespace dpdrng;
using namespace dpdrng::dpd;

namespace {

struct Normal {
  std::uint64_t state;
  double operator()() {
    const double u1 = (double(rng::splitmix64_mix(state++) >> 11) + 0.5) * 0x1p-53;
    const double u2 = double(rng::splitmix64_mix(state++) >> 11) * 0x1p-53;
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  }
};

// x_t = φ x_{t−1} + √(1 − φ²) ε_t, unit variance, started in equilibrium.
std::vector<double> ar1(Normal& z, std::size_t n, double phi) {
  std::vector<double> x(n);
  x[0] = z();
  for (std::size_t t = 1; t < n; ++t) x[t] = phi * x[t - 1] + std::sqrt(1 - phi * phi) * z();
  return x;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v) s += x;
  return s / double(v.size());
}
double variance(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (const double x : v) s += (x - m) * (x - m);
  return s / double(v.size() - 1);
}

}  // namespace

// AR(1) with φ = 0.8: τ_int = (1 + φ)/(2(1 − φ)) = 4.5 (Madras & Sokal 1988, eq. 2.6 for an exponential
// autocorrelation ρ(t) = φ^|t|), so the mean of n = 2 000 samples has variance 2τ/n = 0.0045. Over 400
// independent series: the spread of the means, the mean of sem² and the theory agree; sem² scatters as a
// variance estimate with sem_dof degrees of freedom (var(sem²)/sem²² ≈ 2/sem_dof); and std_sem is the spread
// of the series' standard deviations.
TEST(RunErrors, AutocorrelatedMeansGetTheirErrorAndDegreesOfFreedom) {
  Normal z{2024};
  const std::size_t n = 2000, series = 400;
  std::vector<double> means, sem2, dof, sds, std_sem2;
  for (std::size_t k = 0; k < series; ++k) {
    const Stat s = make_stat(ar1(z, n, 0.8));
    means.push_back(s.mean);
    sem2.push_back(s.sem * s.sem);
    dof.push_back(s.sem_dof);
    sds.push_back(s.std);
    std_sem2.push_back(s.std_sem * s.std_sem);
  }
  const double theory = 2 * 4.5 / double(n);
  EXPECT_NEAR(mean(sem2) / theory, 1.0, 0.1);
  // The spread of 400 means estimates their variance to ±7 % (1σ): a 25 % band.
  EXPECT_NEAR(variance(means) / mean(sem2), 1.0, 0.25);
  const double claimed = 2 / mean(dof), seen = variance(sem2) / (mean(sem2) * mean(sem2));
  EXPECT_GT(seen / claimed, 0.5);
  EXPECT_LT(seen / claimed, 1.6);
  EXPECT_NEAR(variance(sds) / mean(std_sem2), 1.0, 0.25);
}

// Short series fall back on independent-sample errors with n − 1 degrees of freedom.
TEST(RunErrors, ShortSeriesUseIndependentSampleErrors) {
  const Stat s = make_stat({1, 2, 3, 4, 5});
  EXPECT_NEAR(s.sem, std::sqrt(2.5 / 5), 1e-15);
  EXPECT_EQ(s.sem_dof, 4.0);
}

// Every leave-one-out set of an estimate θ that is a mean over blocks satisfies Σ_b w_b θ_(b) = (B − 1) W θ, with
// w_b the weight left when block b is out and W the total; for equal blocks, Σ_b θ_(b) = B θ. g(r) and the
// velocity density have equal blocks of samples here, the MSD's bead groups hold 12 or 13 beads. A sample in two
// blocks, or a curve normalised by the wrong count, breaks it.
TEST(RunErrors, JackknifeCurvesAreLeaveOneOutSets) {
  WaterConfig cfg;  // the paper's scene, 400 production steps
  cfg.steps = 420, cfg.equilibrate = 20, cfg.threads = 1;
  cfg.generator = rng::validated({"philox4x32", 10});
  const RunResult r = run_water(cfg);
  ASSERT_TRUE(r.ok()) << r.status;
  ASSERT_EQ(r.rdf.jackknife.size(), kStatBlocks);
  ASSERT_EQ(r.velocity_pdf.jackknife.size(), kStatBlocks);
  ASSERT_EQ(r.msd.jackknife.size(), kStatBlocks);
  // 400 production steps, a sample every 10: 40 samples, 2 a block, so each leave-one-out set holds 38 of 40.
  const auto check = [](const std::vector<std::vector<double>>& jack, const std::vector<double>& full) {
    for (std::size_t k = 0; k < full.size(); ++k) {
      double sum = 0;
      for (const auto& j : jack) sum += j[k];
      EXPECT_NEAR(sum, double(jack.size()) * full[k], 1e-12 * (1 + std::abs(full[k]))) << "bin " << k;
    }
  };
  check(r.rdf.jackknife, r.rdf.g);
  std::vector<double> pooled(r.velocity_pdf.v.size());
  for (std::size_t k = 0; k < pooled.size(); ++k)
    pooled[k] = (r.velocity_pdf.pdf[0][k] + r.velocity_pdf.pdf[1][k] + r.velocity_pdf.pdf[2][k]) / 3.0;
  check(r.velocity_pdf.jackknife, pooled);
  // 256 beads in 20 groups of 12 or 13: unequal weights, so the identity holds for the weighted sum.
  std::vector<double> weighted(r.msd.msd.size(), 0.0);
  for (std::size_t g = 0; g < kStatBlocks; ++g) {
    const double beads = 256.0 - double((g + 1) * 256 / kStatBlocks - g * 256 / kStatBlocks);
    for (std::size_t k = 0; k < weighted.size(); ++k) weighted[k] += beads * r.msd.jackknife[g][k];
  }
  for (std::size_t k = 0; k < weighted.size(); ++k)
    EXPECT_NEAR(weighted[k], double(kStatBlocks - 1) * 256.0 * r.msd.msd[k], 1e-9 * (1 + r.msd.msd[k])) << k;
  EXPECT_GT(r.msd.diffusion_sem, 0);
  EXPECT_EQ(r.msd.diffusion_sem_dof, double(kStatBlocks - 1));
  EXPECT_GT(r.velocity_pdf.error_rate_kT_mean_sem, 0);
  EXPECT_EQ(r.velocity_pdf.error_rate_kT_mean_sem_dof, double(kStatBlocks - 1));
}

// The store writes a run's state by name and reads it back: every name parses to its state, the text of a
// status names it, and an unknown name is the user's error, not a crash.
TEST(RunState, NamesRoundTrip) {
  for (RunState st : {RunState::ok, RunState::unstable, RunState::disrupted})
    EXPECT_EQ(parse_run_state(to_string(st)), st) << to_string(st);
  EXPECT_EQ(RunStatus::unstable(12, "NaN force").text(), "unstable at step 12: NaN force");
  EXPECT_EQ(RunStatus::disrupted(3, "lipid lost").text(), "disrupted at step 3: lipid lost");
  EXPECT_THROW(parse_run_state("exploded"), InputError);
  EXPECT_THROW(parse_run_state(""), InputError);
}

}  // namespace dpdrng_test::dpd_test_run_errors
