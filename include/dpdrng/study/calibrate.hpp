#pragma once
// `dpdrng study calibrate CONFIG`: how often the study's verdicts call a good generator "differs" (false-alarm
// rate) and how large an injected defect must be before they call it so (power), for the config's scene, run
// length, tests and error control.
//
// One pool of replicas serves every question. Replica r (the config's own seeding of replica r) holds the
// reference, three generators known to be good (philox4x32(10), threefry2x64(20), splitmix64) and, for the
// first `defect_replicas` replicas, one cell per defect size. A study of R replicas is a block of R consecutive
// pool replicas, so blocks are disjoint and independent:
//   null study:  reference + the three good generators, analysed exactly as `study report` does (the config's α
//                and error control over the whole family): 3 verdicts, each a false alarm when it says "differs";
//   power study: the same cells plus one defect variant (a study of four variants, like a sweep of four
//                generators), detected when the defect's verdict says "differs".
// The reference and good-generator cells are shared by the null and power studies of a block.
#include <filesystem>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/runner.hpp"
#include "dpdrng/study/store.hpp"

namespace dpdrng::study {

struct CalibrationPlan {
  int null_studies = 100;   // null studies at the config's replica count
  int power_studies = 10;   // power studies per defect size at the largest replica count (more at smaller ones)
  std::vector<int> replicas;  // replica counts to calibrate; empty = the config's
  std::vector<double> variance{0.0025, 0.005, 0.01, 0.02};  // ε of defect:variance=ε
  std::vector<double> lag1, mean;                            // ρ and μ (lag-1 runs in pair-step seeding)
  std::vector<double> aniso;  // κ of defect:aniso=κ (runs in distance seeding: it reads the separation)
  // Cells this process computes (round-robin over the pool's cells, as `study run --shard`): shards share the
  // pool directory, and the run that finds every cell stored analyses.
  Shard shard{};
  // At the study's own size: every variant slot of the config (generator × rounds, under all its noises and Δt)
  // holds its own good generator, defect:key=k (Philox4x32-10 under key k), so a null study has the config's
  // variants, tests and Holm family. Null studies only (no defects); see at_size_pool.
  bool at_size = false;
  // Stop starting cells after this many seconds of this invocation (0: no limit); what is stored stays, and a
  // rerun goes on from there. For calibrations longer than one sitting.
  double max_seconds = 0;
};

// The config's scene with the pool's generators and replicas, and without NIST cells (the battery reads words,
// and a defect generator's words are its base's). InputError for the bilayer scene.
StudyConfig calibration_pool(const StudyConfig& config, const CalibrationPlan& plan);
// The at-size pool: the config with slot k's generator replaced by defect:key=k, replicas = null_studies ×
// replicas, and reference replicas enough for each null study to hold its own `reference_replica_count()`:
// null study s compares variant replicas [sR, sR + R) with the same reference replicas (same initial states)
// plus R_ref − R extra ones of its own, numbered from null_studies × R. InputError for configs whose Δt carry
// extra replicas, integrators or reference gammas (their blocks are not laid out here).
StudyConfig at_size_pool(const StudyConfig& config, const CalibrationPlan& plan);
// Pool replicas holding defect cells: power_studies × the largest replica count.
int defect_replicas(const StudyConfig& config, const CalibrationPlan& plan);

struct Rate {
  std::size_t events = 0, trials = 0;
  double rate = 0, low = 0, high = 1;  // central 95 % Clopper–Pearson interval
};
Rate make_rate(std::size_t events, std::size_t trials);

struct NullRow {
  int replicas = 0;
  Rate verdicts;  // good-generator verdicts that say "differs"
  Rate studies;   // studies with any "differs" (the reference's own tests included)
  // The raw (uncorrected) two-sided P-value of every test of every good-generator variant in these null studies,
  // for the QQ plot against the uniform distribution they follow under the null.
  std::vector<double> p_values;
  std::size_t tests_per_study = 0;  // the Holm family of one null study (at_size: the config's own family)
};

// At the study's own size, how often a good generator is shown equivalent on an observable (its margin from the
// config): the replicas that verdict needs.
struct EquivalenceRow {
  int replicas = 0, reference_replicas = 0;
  std::string observable;
  double margin = 0;
  Rate equivalent;  // variant verdicts (slot × noise) whose equivalence test passes
};

// The error model's check on null comparisons (at_size): per scalar observable, the dispersion of the normal
// scores of every good variant's shift over the null studies; 1 when the standard errors are right.
struct DispersionRow {
  std::string observable;
  stats::Dispersion scores;
};

struct PowerRow {
  std::string kind;  // "variance", "lag1", "mean"
  double size = 0;
  int replicas = 0;
  Rate detected;
  double temperature_error = 0;  // mean relative T difference from the reference, replica by replica
};

// Size of defect detected with probability `power`, linear between the two sizes that bracket it. below: the
// smallest size tested already reaches it; above: the largest does not (value NaN then).
struct Threshold {
  std::string kind;
  int replicas = 0;
  double power = 0;
  double size = 0;
  bool below = false, above = false;
};

struct Calibration {
  std::string config_name;
  nlohmann::json scene;  // what the calibration holds for: calibration_key(config)
  double alpha = 0.01;
  std::string error_control;
  long steps = 0, production = 0;
  int config_replicas = 0, pool_replicas = 0, defect_replicas = 0;
  bool at_size = false;
  int reference_replicas = 0;  // of each null study at the config's size (at_size)
  // at_size: the null studies asked for; `nulls` adds up those recorded so far (its studies.trials), so a
  // calibration carried over several sittings reports what it holds.
  int null_studies_planned = 0;
  std::vector<NullRow> nulls;
  std::vector<EquivalenceRow> equivalence;  // at_size only
  std::vector<DispersionRow> dispersion;    // at_size only
  std::size_t scored_studies = 0;           // null studies whose records hold scores (at_size)
  std::vector<PowerRow> power;
  std::vector<Threshold> thresholds;
  std::size_t cells = 0, computed = 0, resumed = 0, failed = 0;
  std::size_t missing = 0;  // pool cells not stored yet (other shards'): nothing is analysed while any is
  double seconds = 0;     // wall time of this invocation
  double wall_total = 0;  // wall time of every invocation on this pool, summed
  double cell_seconds = 0;  // summed compute time of every cell in the pool (this and earlier invocations)
  std::string machine;
};

// The settings a calibration must share with a study for its numbers to apply: scene, noise distribution and
// seeding, α, error control and the test sizes behind the verdicts (not the replica count, a row of its own).
nlohmann::json calibration_key(const StudyConfig& config);

// Computes the pool's missing cells of the plan's shard one at a time (each with `threads` threads), saving each
// to `store`, then analyses, unless cells of other shards are still missing (`missing` > 0, nothing else set).
// At size, a null study is analysed as soon as its cells are stored and kept as pool/null-studies/study-NNN.json;
// the result adds up the recorded studies (`missing` counts the cells of the others).
// Progress and an ETA on `progress` when given.
Calibration calibrate(const StudyConfig& config, const CalibrationPlan& plan, Store& store, const MeasureFn& measure,
                      int threads, std::ostream* progress);

nlohmann::json to_json(const Calibration& c);
// Writes summary.md, calibration.json, false_alarms.csv, power.csv and charts/ (gnuplot) under dir.
void write_calibration(const Calibration& c, const std::filesystem::path& dir, bool charts, std::ostream* log);
// A calibration read back from what write_calibration committed (calibration.json and null_p_qq.csv): enough to
// draw its charts without its pool. InputError when dir holds no readable calibration.
Calibration read_calibration_tables(const std::filesystem::path& dir);
// Writes the chart CSVs and scripts of the calibration in dir (its charts/), drawn from its tables.
void write_calibration_charts(const Calibration& c, const std::filesystem::path& dir, bool run, std::ostream* log);

// A calibration.json as a report reads it: where it is (the report names it) and what it holds.
struct CalibrationRecord {
  std::filesystem::path file;
  nlohmann::json json;
};
// The calibration.json files in `places` (each a calibration.json, or a directory searched for them), in order,
// each parsed once; a file that is not JSON is left out.
std::vector<CalibrationRecord> read_calibrations(const std::vector<std::filesystem::path>& places);

// The report's detection-limit sentence for `config`, from `records`: the one whose key matches the config and
// that has a row for its replica count; "not calibrated for this config" otherwise. A calibration of null
// studies at the config's own size (`--at-size`) puts its false-alarm rate in front. Records of another layout
// are passed over.
std::string detection_limit_sentence(const StudyConfig& config, const std::vector<CalibrationRecord>& records);
std::string detection_limit_sentence(const StudyConfig& config, const std::filesystem::path& place);
// From the calibration at the config's own size among `records` (the first whose key matches): per observable,
// how often a good generator's variant came out `equivalent` at the config's replica count. Empty when none.
std::map<std::string, Rate> calibrated_equivalence(const StudyConfig& config,
                                                   const std::vector<CalibrationRecord>& records);

}  // namespace dpdrng::study
