#pragma once
// From stored cells to verdicts: cells that differ only by replica form a variant; every variant is compared
// with the reference (MT19937) variant of the same distribution and Δt. Every comparison is a test with a
// P-value on its own scale; the study's error control (Holm over the whole study, or over each variant) turns
// the P-values into one set of decisions, and every verdict, bold mark and chart of the report reads those.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/moments.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

struct VariantKey {
  std::string generator;
  int rounds = 1;
  rng::Distribution distribution = rng::Distribution::gauss;
  rng::Feed feed = rng::Feed::halves;
  rng::Seeding seeding = rng::Seeding::distance;  // unused by the reference
  double dt = 0.04;
  bool reference = false;
  std::string integrator;  // Cell::integrator: empty unless the sweep names integrators

  std::string label() const;  // "tea32(1)"
  // The label with the seeding: "tea32(1) distance"; the reference's label alone.
  std::string label_and_seeding() const;
  std::string noise() const;         // noise_name(distribution, feed)
  std::string seeding_name() const;  // "stream" for the reference
  auto operator<=>(const VariantKey&) const = default;
};
VariantKey variant_of(const Cell& cell);

// One test behind a verdict and what the error control decided on it.
struct Decision {
  double p = NAN;           // the test's own P-value; NaN when it could not be made (not part of any family)
  double p_adjusted = NAN;  // Holm-adjusted within the family
  bool differs = false;     // p_adjusted < α
  bool tested() const { return std::isfinite(p); }
};

// One observable of one variant against the reference.
struct Comparison {
  std::string observable;   // "temperature_mean", "vpdf_vs_mt", ...
  std::size_t n = 0, n_ref = 0;
  double value = NAN, value_sd = NAN;  // mean and spread over replicas
  double ref = NAN, ref_sd = NAN;
  // Scalars: |value − ref| / |ref| (|value − ref| for observables that are themselves error rates, and for the
  // bilayer's); curves: mean relative deviation of the variant's mean curve from the reference's over the
  // bins tested.
  double error_rate = NAN;
  // Scalars: the 1σ of error_rate if the variant were the reference, from the pooled variance (both groups'
  // replica spreads and every run's own standard error). NaN for curves.
  double sigma = NAN;
  const char* test = "";    // "t", "paired t", "F" (a literal)
  double statistic = NAN;   // t, or F
  double dof = NAN, dof2 = NAN;  // of t; of F: d and d(n + m − 2)
  Decision decision;
  bool available = false;
  std::string note;
  // Bilayer scalars are compared replica by replica (each replica starts every generator from one state):
  // mean of value − ref over the replicas both have and its 95 % CI half-width.
  bool paired = false;
  double diff = NAN, diff_ci = NAN;
  std::size_t n_pairs = 0;
};

// A pass fraction pooled over a variant's replicas (χ² over steps, lag-1 t over pairs): its central
// Clopper–Pearson interval at 1 − α and the central binomial test against 1 − α.
struct PassSummary {
  std::string test;    // "chi2", "ttest"
  std::string stream;  // "x" (one word per call), "a"/"b" (64TEA, Philox, ...)
  std::size_t trials = 0, passed = 0;
  double fraction = NAN, ci_low = 0, ci_high = 1;
  Decision decision;   // decision.p: the binomial test's P-value
  bool available = false;
};

// The correlation of ζ between neighbouring pairs ("pair") or consecutive steps of a pair ("time"): each
// replica's test combined over the replicas (Stouffer), the largest |r| shown.
struct CorrelationSummary {
  std::string what;  // "pair", "time"
  std::size_t replicas = 0;
  double worst_r = NAN;
  Decision decision;
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
  std::vector<CorrelationSummary> correlations;
  std::vector<NistRow> nist;             // from the first cell that ran the battery
  std::string nist_cell;
  std::string nist_report;               // the battery's own finalAnalysisReport text, when stored
  double nist_sequences = 0, nist_failed = NAN, nist_columns = 0;
  double ns_per_number = NAN, step_ms = NAN, rng_share = NAN;
  // ζ of the production steps' pairs inside r_c, the replicas' power sums added (n = 0: fewer than 4 stored).
  stats::MomentsResult zeta;
  Decision zeta_decision;  // ⟨ζ²⟩ = 1, Holm over every variant with ζ (a family apart from the verdicts')
  // ⟨ζ²⟩ / ⟨ζ²⟩_reference − 1: the shift of k_BT that fluctuation–dissipation predicts (T ∝ σ²⟨ζ²⟩).
  double zeta_predicted_shift = NAN;
  // Why this variant has no verdict against the reference (empty when it has one): its reference replicas
  // are missing, unreadable or failed.
  std::string no_reference;
  std::string verdict;       // "indistinguishable from MT at this sample size" / "differs (p = …: …)" / ...
  double min_p = NAN;        // smallest adjusted P-value behind the verdict (NaN: nothing tested)
  std::size_t tests = 0;     // tests behind the verdict (this variant's share of the family)
  std::string min_p_what;
};

struct Analysis {
  double alpha = 0.01;
  ErrorControl error_control = ErrorControl::study;
  std::size_t family_size = 0;  // tests in the study's family (study control), or in all families together
  std::size_t families = 0;     // 1 under study control, the variants with a test under variant control
  bool bilayer = false;  // the membrane scene: physics only, absolute differences, paired tests
  std::vector<VariantReport> variants;  // reference variants first, then in sweep order
  const VariantReport* reference_for(const VariantKey& k) const;
  std::string error_control_sentence() const;  // the rule, in words, for the report
};

Analysis analyse(const StudyConfig& config, const std::vector<CellResult>& cells);

// How small a temperature error the study's own t-tests see: for each variant with a verdict, the relative
// shift of k_BT that its temperature test (standard error and degrees of freedom as compared) rejects `power`
// of the time at Holm's strictest threshold α/m, m the size of the variant's family (stats::
// detectable_difference). A defect that shifts nothing else must pass that threshold to be declared.
struct TemperatureLimit {
  std::size_t variants = 0;
  double median = NAN, low = NAN, high = NAN;  // relative shift: median and range over the variants
  double threshold = NAN;                      // α/m (the largest m under variant control)
  double power = NAN;
};
TemperatureLimit temperature_limit(const Analysis& a, double power = 0.9);
std::string temperature_limit_sentence(const Analysis& a);  // "" when no variant has a temperature test

// The bilayer scene's scalars: cells store <name>_mean, _std, _sem and _sem_dof (measure.hpp).
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

// Mean relative deviation of `curve` from `ref` over the bins where ref >= threshold (NaN if none).
double curve_error(const std::vector<double>& curve, const std::vector<double>& ref, double threshold);

}  // namespace dpdrng::study
