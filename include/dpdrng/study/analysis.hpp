#pragma once
// From stored cells to verdicts: cells that differ only by replica form a variant; every variant is compared
// with the reference (MT19937) variant of the same distribution and Δt. Each comparison carries its noise
// floor (what MT-vs-MT comparisons give with the same number of replicas) and a P-value, so a difference is
// only called a difference when the replicas resolve it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

struct VariantKey {
  std::string generator;
  int rounds = 1;
  std::string distribution;
  std::string seeding;
  double dt = 0.04;
  bool reference = false;

  std::string label() const;  // "tea32(1)"
  auto operator<=>(const VariantKey&) const = default;
};
VariantKey variant_of(const Cell& cell);

// One observable of one variant against the reference.
struct Comparison {
  std::string observable;   // "temperature_mean", "vpdf_vs_mt", ...
  std::size_t n = 0, n_ref = 0;
  double value = 0, value_sd = 0;  // mean and spread over replicas
  double ref = 0, ref_sd = 0;
  double error_rate = 0;    // |value − ref| / |ref| for scalars (|value − ref| for observables that are themselves
                            // error rates); mean relative curve deviation for curves
  double noise_floor = 0;   // the same quantity for MT against MT (1σ for scalars)
  double p_value = 1;       // Welch's t-test of "no difference" (NaN when replicas cannot tell); paired t below
  bool available = false;
  std::string note;
  // Bilayer scalars are compared replica by replica (each replica starts every generator from one state):
  // mean of value − ref over the replicas both have, its 95 % CI half-width, and p_value is the paired t-test.
  bool paired = false;
  double diff = NAN, diff_ci = NAN;
  std::size_t n_pairs = 0;
};

// A pass fraction pooled over a variant's replicas (χ² over steps, lag-1 t over pairs).
struct PassSummary {
  std::string test;    // "chi2", "ttest"
  std::string stream;  // "x" (one word per call), "a"/"b" (64TEA, Philox, ...)
  std::size_t trials = 0, passed = 0;
  double fraction = 0, ci_low = 0, ci_high = 1;
  double binomial_p = 1;  // vs the 1 − α a good generator gives
  bool available = false;
};

struct NistRow {
  std::string test, variant;
  std::vector<double> histogram;  // C1..C10
  double p_uniformity = 1;
  double passed = 0, applicable = 0;
  bool proportion_ok = true, uniformity_ok = true;
  bool ok = true;  // the battery's own (reference) second-level verdict when stored, else both checks above
};

struct VariantReport {
  VariantKey key;
  std::vector<const CellResult*> cells;  // ok cells only
  std::vector<const CellResult*> broken;  // unstable or failed
  std::vector<Comparison> observables;
  std::vector<PassSummary> passes;
  std::vector<NistRow> nist;             // from the first cell that ran the battery
  std::string nist_cell;
  std::string nist_report;               // the battery's own finalAnalysisReport text, when stored
  double nist_sequences = 0, nist_failed = NAN, nist_columns = 0;
  double ns_per_number = NAN, step_ms = NAN, rng_share = NAN;
  std::string verdict;       // "indistinguishable from MT at this sample size" / "differs (p = …: …)" / "no data"
  double min_p = 1;          // smallest Bonferroni-adjusted P-value behind the verdict
  std::string min_p_what;
  double worst_error_over_floor = NAN;  // max over observables of error_rate / noise_floor
};

struct Analysis {
  double alpha = 0.01;
  bool bilayer = false;  // the membrane scene: physics only, absolute differences, paired tests
  std::vector<VariantReport> variants;  // reference variants first, then in sweep order
  const VariantReport* reference_for(const VariantKey& k) const;
};

Analysis analyse(const StudyConfig& config, const std::vector<CellResult>& cells);

// The bilayer scene's scalars: cells store <name>_mean, _std and _sem (measure.hpp).
struct BilayerObservable {
  const char* name;   // "tension"
  const char* label;  // "Σ"
  const char* what;   // "tension L_z[P_zz − (P_xx+P_yy)/2]"
};
const std::vector<BilayerObservable>& bilayer_observables();

// Replica mean of a cell scalar with its 95 % confidence half-width: Student t over the replicas when there are
// at least two; with one replica, 1.96 × the run's own block standard error (`sem_name`), flagged.
struct ReplicaMean {
  double mean = NAN, ci95 = NAN;
  std::size_t n = 0;
  bool from_run_sem = false;
};
ReplicaMean replica_mean(const std::vector<const CellResult*>& cells, const std::string& name,
                         const std::string& sem_name);

// Two-sided paired t-test of x against y on the replicas both hold (x, y: replica → value); NaN below 2 pairs.
struct PairedTest {
  std::size_t n = 0;
  double diff = NAN, ci95 = NAN, p_value = NAN;
};
PairedTest paired_test(const std::map<int, double>& x, const std::map<int, double>& y);

// Mean relative deviation of `curve` from `ref` over the bins where ref >= threshold (NaN if none).
double curve_error(const std::vector<double>& curve, const std::vector<double>& ref, double threshold);
// Two-sided Welch t-test of equal means; NaN when either sample has fewer than 2 values or no spread.
double welch_p(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace dpdrng::study
