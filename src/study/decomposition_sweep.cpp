// The decomposition sweep's runs, cell by cell into its store, and its rows read back from the store.
#include "dpdrng/study/decomposition_sweep.hpp"

#include <chrono>
#include <cstdio>
#include <ostream>

#include "dpdrng/study/runner.hpp"

namespace dpdrng::study {

std::vector<DecompResult> run_decomp_cell(const DecompSweep& sw, const DecompCell& cell) {
  std::vector<DecompResult> out;
  for (std::size_t d = 0; d < sw.domains.size(); ++d) {
    DecompConfig c = sw.base;
    c.noise.generator = cell.generator;
    c.noise.seeding = cell.seeding;
    c.noise.distribution = cell.distribution;
    c.domains = sw.domains[d];
    c.reference = d == 0;  // the undecomposed run does not depend on the grid
    DecompResult r = run_decomposition(c);
    if (d > 0) r.has_reference = true, r.reference = out.front().reference, r.randomness = out.front().randomness;
    out.push_back(std::move(r));
  }
  return out;
}

namespace {

void progress_line(std::ostream& o, std::size_t done, std::size_t total, const DecompCell& cell,
                   const std::vector<DecompResult>& rows, double seconds, double eta) {
  std::string mismatch;
  for (const auto& r : rows) {
    char m[64];
    std::snprintf(m, sizeof m, "  %s %.3g %%", r.domains.c_str(), 100 * r.decomposed.boundary.mismatch_fraction());
    mismatch += m;
  }
  char line[512];
  std::snprintf(line, sizeof line, "[decompose] %zu/%zu cells  %-14s %-10s %-7s %6.1fs  mismatched:%s  ETA %s\n",
                done, total, rng::describe(cell.generator).c_str(), to_string(cell.seeding).c_str(),
                std::string(rng::to_string(cell.distribution)).c_str(), seconds, mismatch.c_str(),
                format_duration(eta).c_str());
  o << line << std::flush;
}

}  // namespace

DecompRunSummary run_decomp_sweep(const DecompSweep& sw, const CellStore& store, const DecompRunOptions& options) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  DecompRunSummary sum;
  std::vector<DecompCell> todo;
  const std::vector<DecompCell> cells = decomp_cells(sw);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!in_shard(i, options.shard)) continue;
    ++sum.cells;
    std::string why;
    switch (decomp_cell_state(store, cells[i], &why)) {
      case CellStore::State::stored: ++sum.resumed; break;
      case CellStore::State::missing: todo.push_back(cells[i]); break;
      case CellStore::State::unreadable:
        sum.unreadable.push_back(store.cell_path(cells[i].id()).string());
        if (options.progress)
          *options.progress << "[decompose] warning: " << store.cell_path(cells[i].id()).string() << " is unreadable ("
                            << why << "): computing the cell again\n";
        todo.push_back(cells[i]);
        break;
    }
  }
  if (options.progress && sum.resumed > 0)
    *options.progress << "[decompose] " << sum.resumed << " of " << sum.cells << " cells already stored: resuming\n";
  double busy = 0;
  for (const auto& cell : todo) {
    const auto c0 = clock::now();
    const std::vector<DecompResult> rows = run_decomp_cell(sw, cell);
    save_decomp_cell(store, cell, rows);
    const double seconds = std::chrono::duration<double>(clock::now() - c0).count();
    busy += seconds;
    ++sum.computed;
    if (options.progress)
      progress_line(*options.progress, sum.resumed + sum.computed, sum.cells, cell, rows, seconds,
                    busy / double(sum.computed) * double(todo.size() - sum.computed));
  }
  sum.seconds = std::chrono::duration<double>(clock::now() - t0).count();
  return sum;
}

std::vector<DecompResult> load_decomp_rows(const DecompSweep& sw, const CellStore& store,
                                           std::vector<std::string>* missing) {
  std::vector<DecompResult> rows;
  for (const auto& cell : decomp_cells(sw)) {
    if (decomp_cell_state(store, cell) != CellStore::State::stored) {
      if (missing) missing->push_back(cell.id());
      continue;
    }
    for (auto& r : load_decomp_cell(store, cell)) rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace dpdrng::study
