#pragma once
// Runs the cells of a study (or of one shard) that the store does not hold yet, in parallel across cells,
// saving each as soon as it finishes. A cell file that exists but cannot be read is named in a warning on the
// progress stream and computed again. The measurement is passed in, so tests can count and fake it.
#include <functional>
#include <iosfwd>

#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/store.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng::study {

// `threads` is the thread budget this cell may use inside (1 when cells run side by side).
using MeasureFn = std::function<CellResult(const Cell&, const StudyConfig&, int threads)>;

struct RunOptions {
  Shard shard{};
  int threads = 1;                    // cells run concurrently, one thread each
  std::ostream* progress = nullptr;   // cells done/total and ETA; nullptr = silent
};

struct RunSummary {
  std::size_t cells = 0;      // in this shard
  std::size_t resumed = 0;    // already stored, not recomputed
  std::size_t computed = 0;
  std::size_t unstable = 0;
  std::size_t disrupted = 0;  // bilayer runs that lost a lipid
  std::size_t failed = 0;
  std::vector<std::string> unreadable;  // cell files found unreadable and computed again
  double seconds = 0;
};

std::string format_duration(double seconds);  // "42s", "3m05s", "2h10m": the ETA of progress lines

RunSummary run_study(const StudyConfig& config, Store& store, const RunOptions& options, const MeasureFn& measure);

}  // namespace dpdrng::study
