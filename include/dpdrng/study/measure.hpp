#pragma once
// The measurements of one cell, as small adapters over the engine (dpd::run_water) and the statistical tests
// (stats::chi2_uniform, stats::lag1_ttest, stats::nist). Each adapter writes named scalars and series into
// the CellResult; the names are what analysis.cpp and report.cpp read (the compared observables' names, standard
// errors and units are those of the observable table, observables.hpp):
//   physics  the kinetic temperature with its fluctuation, pressure_mean/_sem, pressure_conservative_mean,
//            pressure_xx/yy/zz, diffusion_coefficient/diffusion_sem, vpdf_error_mb/_sem, momentum_drift (each _sem
//            the run's own standard error, its degrees of freedom in _sem_dof); series temperature, vpdf/v,
//            vpdf/p, vpdf/mb, msd/tau, msd/msd, rdf/r, rdf/g; matrices vpdf/jackknife, msd/jackknife,
//            rdf/jackknife (the curve with one block of samples, or of beads for the MSD, left out: a row a block)
//   tests    chi2.<s>.trials/passed/fraction, ttest.<s>.…, with s = x (one word a call) or a, b (two words);
//            series chi2/<s>/p, ttest/<s>/p; corr.pair.r/p, corr.time.r/p
//   nist     nist/test, nist/variant (strings), nist/passed, nist/applicable, nist/p_uniformity (series),
//            nist/histogram (rows × 10)
//   cost     cost.ns_per_number, cost.step_seconds, cost.run_seconds, cost.rng_share, cost.numbers_per_step
//   bilayer  <obs>_mean/_std/_sem/_sem_dof for obs in temperature, pressure, pressure_xx/yy/zz, tension (L_z[P_zz −
//            (P_xx+P_yy)/2]), tension_conservative, thickness (head peak to peak), head_separation, tail_order;
//            lipids_out_max, momentum_drift; series profile/z (relative to the midplane), profile/head,
//            profile/tail, profile/water, order_by_bond, series/step, series/temperature, series/tension
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

// Which steps and pairs the engine must tap for this cell's tests.
struct TapPlan {
  std::vector<std::int64_t> chi2_steps;  // evenly spread over the production steps
  std::vector<std::int64_t> nist_steps;  // consecutive, at the end of the run: enough words for the battery
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // in couples of neighbouring pair ids
};
TapPlan plan_taps(const Cell& cell, const StudyConfig& config, int words_per_pair);

// Lags of the ζ autocorrelation every water cell measures on its tracked pairs (dpd/zeta_track.hpp).
inline constexpr int kStudyZetaLags = 5;
dpd::WaterConfig engine_config(const Cell& cell, const StudyConfig& config, int threads, const TapPlan& plan);
// The membrane scene's engine config: noise, Δt, steps, pairs and threads from the cell and [scene]; the warm-up
// is min(1 000, equilibrate) steps at the scene's dt_warmup, as for `dpdrng simulate --scene bilayer`.
dpd::BilayerConfig bilayer_engine_config(const Cell& cell, const StudyConfig& config, int threads);
// The engine's own checks (box larger than 2 r_c, …) on every distinct scene of the config, before anything runs:
// a scene the engine would refuse is a bad config (InputError naming "scene"), not a sweep of failed cells.
void validate_scene(const StudyConfig& config);

// Observables and costs of a finished (or blown-up) run.
void record_run(const dpd::RunResult& run, CellResult& out);
// Its error-budget part: configurational and per-component temperatures, per-component pressures with their
// standard errors, the w_R²-weighted ζ power and the ζ correlations (scalars named in measure_engine.cpp).
void record_physics(const dpd::RunResult& run, CellResult& out);
// χ² over the tapped steps, one test per step and output word, taken while the engine runs: take() is the run's
// RunHooks::raw (it tests a χ² step while its words are in cache, and gives back every step the NIST battery does
// not read), record() writes the pass fractions and each step's P-value and statistic.
class Chi2Steps {
 public:
  Chi2Steps(const TapPlan& plan, const TestParams& tests) : plan_(plan), tests_(tests) {}
  bool take(const dpd::RawTap& tap);
  void record(CellResult& out) const;

 private:
  const TapPlan& plan_;
  TestParams tests_;
  int words_ = 0;
  std::array<std::vector<stats::Chi2Result>, 2> results_;
};
// Lag-1 t over the tapped pairs, and the cross-pair / across-time correlations of ζ.
void record_ttest(const dpd::Taps& taps, const TestParams& tests, CellResult& out);
void record_correlations(const dpd::Taps& taps, const TestParams& tests, CellResult& out);
// The NIST battery on the bits of the tapped NIST steps, with the second-level counts.
void record_nist(const dpd::Taps& taps, const TapPlan& plan, const TestParams& tests, int threads, CellResult& out);

// A bilayer run's observables. A run that lost a lipid finished but is recorded with status "disrupted" (its
// structure is not the bilayer's), one that blew up as "unstable"; both keep the observables up to then.
void record_bilayer(const dpd::BilayerResult& run, CellResult& out);

// All of the above (water), or the bilayer run and record_bilayer: the study's production MeasureFn.
CellResult measure_cell(const Cell& cell, const StudyConfig& config, int threads);

}  // namespace dpdrng::study
