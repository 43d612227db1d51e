#pragma once
// What the CI-size calibration (calibrate.cpp) and the at-size one (calibrate_at_size.cpp) share: the analysis of
// a block of pool cells, the run loop over a pool's missing cells, and the fields every calibration.json carries.
#include <functional>
#include <iosfwd>
#include <vector>

#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/calibrate.hpp"

namespace dpdrng::study::calibration_detail {

std::vector<int> replica_counts(const StudyConfig& config, const CalibrationPlan& plan);
Analysis analyse_block(const StudyConfig& study, const std::vector<const CellResult*>& cells);
bool says_differs(const VariantReport& v, double alpha);
// The raw P-value of every test of a variant that has one (observables, pass fractions, ζ correlations, ⟨ζ²⟩ = 1).
void append_p_values(const VariantReport& v, std::vector<double>& out);

// Computes `todo` one cell at a time (each with `threads` threads) into `store`, a failure stored as a failed
// cell; progress lines with an ETA on `progress`; `saved` is called after each cell is stored. No cell is started
// once `max_seconds` (> 0) have passed since the call (the first always is). Returns the number computed.
std::size_t compute_cells(const std::vector<Cell>& todo, const StudyConfig& pool, const MeasureFn& measure,
                          int threads, Store& store, std::ostream* progress,
                          const std::function<void(const Cell&)>& saved, double max_seconds);
// The cells of `shard` not stored yet; those stored are counted in out.resumed.
std::vector<Cell> shard_todo(const std::vector<Cell>& cells, Shard shard, const Store& store, Calibration& out);
// Every cell file of the store; OutputError naming the first unreadable one.
std::vector<CellResult> load_cells(const Store& store);
// The scene, α, run length and replica counts the calibration holds for.
void describe(Calibration& out, const StudyConfig& config, const StudyConfig& pool);
// This invocation's wall time, and the sum over every invocation on this pool (kept in the pool directory).
void add_wall_time(Calibration& out, const Store& store, double seconds);

Calibration calibrate_at_size(const StudyConfig& config, const CalibrationPlan& plan, Store& store,
                              const MeasureFn& measure, int threads, std::ostream* progress);

}  // namespace dpdrng::study::calibration_detail
