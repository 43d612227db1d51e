#pragma once
// From stored cells to verdicts: cells that differ only by replica form a variant; every variant is compared
// with the reference (MT19937) variant of the same distribution and Δt. Each observable's comparison leads with
// its effect size, the shift against the reference and its 95 % CI, and ends in one of three outcomes:
// `equivalent` (two one-sided tests: the shift lies inside ±δ, δ the observable's margin, Holm over the study's
// equivalence tests), `differs` (two-sided, Holm over one family holding every test of the study: observables,
// ⟨ζ²⟩ = 1, pass fractions and correlations) or `inconclusive` (neither). Every verdict, bold mark and chart
// of the report reads those decisions.
//
// The error model: a shift's standard error comes from the replicas' spreads — the variant's, its reference's and
// those of the reference under the study's other feeds and distributions (one generator, so one variance), pooled
// with their degrees of freedom (Student t). The pool is left out when the compared replicas vary more than it
// does (stats::pooled_t's consistency test). The runs' own block errors are not used: over the 108 null
// comparisons of the committed studies (tools/z_dispersion.py) their z-scores have a variance of 1.50
// [1.16, 1.99] for the pressure and 1.24 [0.97, 1.65] for the temperature; score_dispersion() checks the chosen
// model on any study.
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/moments.hpp"
#include "dpdrng/stats/noise_power.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/observables.hpp"

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

// The equivalence test of one observable (stats::equivalence_p at its margin) and the decision on it.
struct Equivalence {
  double p = NAN;           // NaN: no margin, or too few replicas (not part of the equivalence family)
  double p_adjusted = NAN;  // Holm-adjusted over the study's equivalence tests
  bool equivalent = false;  // p_adjusted < α: the (1 − 2α′) CI of the shift lies inside ±margin
  bool tested() const { return std::isfinite(p); }
};

enum class Outcome { none, equivalent, differs, inconclusive };
const char* to_string(Outcome o);  // "", "equivalent", "differs", "inconclusive"

// One observable of one variant against the reference.
struct Comparison {
  std::string observable;   // "pressure_mean", "vpdf_vs_mt", ...
  std::size_t n = 0, n_ref = 0;
  double value = NAN, value_sd = NAN;  // mean and spread over replicas
  double ref = NAN, ref_sd = NAN;
  // Scalars: |value − ref| / |ref| (|value − ref| for observables that are themselves error rates, and for the
  // bilayer's); curves: mean relative deviation of the variant's mean curve from the reference's over the
  // bins tested.
  double error_rate = NAN;
  // Scalars: the 1σ of the relative shift under the error model (the replicas' spread). NaN for curves.
  double sigma = NAN;
  // The effect: (value − ref)/|ref| for water scalars; for curves the kept bin whose 95 % CI reaches furthest
  // from 0, its relative difference; (value − ref) for the bilayer's paired scalars. With its 95 % CI.
  bool relative = true;
  double shift = NAN, ci_low = NAN, ci_high = NAN;
  double margin = NAN;  // δ on the shift's scale; NaN: no equivalence test
  Equivalence equivalence;
  Outcome outcome = Outcome::none;  // set by the analysis from both decisions
  // Normal scores of the shift (stats::normal_score), zero-mean unit-variance under the null when the standard
  // error is right: under the error model used, and over the runs' own block errors pooled (normal).
  double score = NAN, score_runs = NAN;
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
  Decision zeta_decision;  // ⟨ζ²⟩ = 1, a member of the study's one family
  // ⟨ζ²⟩ / ⟨ζ²⟩_reference − 1: the shift of k_BT that fluctuation–dissipation predicts (T ∝ σ²⟨ζ²⟩).
  double zeta_predicted_shift = NAN;
  // The noise's effective power as the force receives it (stats::effective_noise_power): the w_R²-weighted ⟨ζ²⟩
  // times 1 + 2Σρ_k over the lags every replica stored (`power_lags`; 0: the weighted moment alone), the
  // replicas' means averaged and their standard errors combined. NaN when the cells hold no weighted moment.
  stats::NoisePower noise_power;
  std::size_t power_lags = 0;
  // The temperature shift the two effective powers predict against the reference, with its standard error; the
  // reference's ρ are taken as 0 where its cells hold none (a stream draws independent numbers).
  stats::NoisePower power_predicted_shift;
  // Why this variant has no verdict against the reference (empty when it has one): its reference replicas
  // are missing, unreadable or failed.
  std::string no_reference;
  // any test differs → differs; every observable with a margin equivalent → equivalent; else inconclusive.
  // none: no verdict (the reference, no data, no reference data).
  Outcome outcome = Outcome::none;
  std::string verdict;       // the outcome in words with what it rests on, or why there is none
  double min_p = NAN;        // smallest adjusted two-sided P-value of the variant (NaN: nothing tested)
  std::size_t tests = 0;     // tests behind the verdict (this variant's share of the family)
  std::string min_p_what;
};

struct Analysis {
  double alpha = 0.01;
  ErrorControl error_control = ErrorControl::study;
  std::size_t family_size = 0;  // tests in the study's family (study control), or in all families together
  std::size_t families = 0;     // 1 under study control, the variants with a test under variant control
  std::size_t equivalence_tests = 0;  // the equivalence family (always study-wide)
  std::map<std::string, double> margins;  // the config's, by margin key
  bool bilayer = false;  // the membrane scene: physics only, absolute differences, paired tests
  std::vector<VariantReport> variants;  // reference variants first, then in sweep order
  const VariantReport* reference_for(const VariantKey& k) const;
  std::string error_control_sentence() const;  // the rule, in words, for the report
  std::string error_model_sentence() const;    // which standard error the comparisons use
  std::string equivalence_text() const;        // the equivalence family, in words
};

Analysis analyse(const StudyConfig& config, const std::vector<CellResult>& cells);

// Variants of generators known to be good, whose comparisons with the reference are null comparisons: the
// generators the calibration calls good (philox4x32 at 7 rounds or more, threefry2x64 at 13 or more,
// splitmix64) and TEA at 16 rounds or more (half of the cipher's 32 cycles and more).
bool known_good(const VariantKey& k);

// The z-score check of the error model: per scalar observable, the dispersion (stats::score_dispersion) of the
// shifts' normal scores over the non-reference variants `is_null` accepts, under the model used (`chosen`) and
// over the runs' block errors (`runs`). Variants that share a reference share its noise, so their scores are
// positively correlated and the interval is narrower than it should be.
struct ScoreCheck {
  std::string observable;
  stats::Dispersion chosen, runs;
};
std::vector<ScoreCheck> score_dispersion(const Analysis& a, const std::function<bool(const VariantKey&)>& is_null,
                                         double confidence = 0.95);

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

// How many replicas a generator as good as the reference needs to come out `equivalent` on each observable with
// a margin, `power` of the time: the two one-sided tests (stats::equivalence_power) at Holm's strictest
// threshold α/m over the study's m equivalence tests, a shift's standard error one replica's spread s (each
// comparison's standard error over √(1/n + 1/n_ref), median over the comparisons) × √(1/R + 1/R_ref) with R_ref/R
// kept at the study's ratio, Student t on the comparisons' degrees of freedom. A model: it adds no degrees of
// freedom with R and ignores Holm's looser later thresholds (both make R high), and it ignores the comparisons
// whose replicas' own spread replaces the pool (5 % of good ones, which rarely pass); a study calibrated at its own
// size measures the rate at its R (study calibrate --at-size).
struct EquivalenceReplicas {
  std::string observable;
  double margin = NAN;           // δ on the shift's scale
  std::size_t comparisons = 0;   // the variants' comparisons behind the medians
  double sd = NAN;               // one replica's spread relative to the reference's mean (median over comparisons)
  double dof = NAN;              // median degrees of freedom of the comparisons
  int replicas = 0, reference_replicas = 0;  // the study's (medians over the comparisons)
  double threshold = NAN;        // α/m
  double power_now = NAN;        // the predicted chance at the study's replicas
  int needed = -1;               // replicas for `power`; 0: more than 100 000; −1: not modelled (see not_modelled)
  std::string not_modelled;      // why the row is not modelled, "" when it is
};
std::vector<EquivalenceReplicas> equivalence_replicas(const Analysis& a, double power = 0.9);

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
