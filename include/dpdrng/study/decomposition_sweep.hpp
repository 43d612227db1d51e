#pragma once
// A sweep of the decomposition check (seeding × generator × rounds × domain grid × distribution) from a small
// TOML file (study/decomposition.toml), run cell by cell into the cell store (decomposition_cell.hpp), and its table
// made from the stored cells. Each (generator, seeding, distribution) cell runs the undecomposed reference once;
// every domain grid then runs its decomposed copy against it.
#include <iosfwd>
#include <string>
#include <vector>

#include "dpdrng/study/decomposition_run.hpp"
#include "dpdrng/study/decomposition_cell.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng::study {

struct DecompSweep {
  std::string name = "decomposition";
  std::string description;
  std::vector<rng::GeneratorSpec> generators;  // one entry per (name, rounds)
  std::vector<dpd::DecompSeeding> seedings;
  std::vector<rng::Distribution> distributions{rng::Distribution::gauss};
  std::vector<dpd::DomainGrid> domains;
  DecompConfig base;  // scene, steps, tests
  std::string source_text;  // the TOML as given
  std::string hash;         // of canonical(): a store refuses cells of another sweep

  // Everything that decides the results (not the name or description), as JSON with a fixed key order.
  nlohmann::json canonical() const;
};

// Unknown keys and bad values are InputErrors naming the key; `origin` names the source in messages.
DecompSweep parse_decomp_sweep(const std::string& toml_text, const std::string& origin);
DecompSweep load_decomp_sweep(const std::string& path);

// The rows of one cell, computed: one per domain grid, in the sweep's order, sharing one reference run.
std::vector<DecompResult> run_decomp_cell(const DecompSweep& sweep, const DecompCell& cell);

struct DecompRunOptions {
  Shard shard{};
  std::ostream* progress = nullptr;  // cells done/total, each cell's mismatch and the ETA; nullptr = silent
};
struct DecompRunSummary {
  std::size_t cells = 0;    // in this shard
  std::size_t resumed = 0;  // already stored, not recomputed
  std::size_t computed = 0;
  std::vector<std::string> unreadable;  // cell files found unreadable and computed again
  double seconds = 0;
};
// Runs the shard's cells that the store does not hold, saving each as soon as it finishes. A cell file that
// exists but cannot be read is named in a warning on the progress stream and computed again.
DecompRunSummary run_decomp_sweep(const DecompSweep& sweep, const CellStore& store, const DecompRunOptions& options);

// Every row of the sweep, in its order, read from the store; the ids of cells not stored (or unreadable) go to
// *missing, and their rows are left out.
std::vector<DecompResult> load_decomp_rows(const DecompSweep& sweep, const CellStore& store,
                                           std::vector<std::string>* missing);

// One row per result. The Markdown table is the human summary; the CSV carries every column.
std::string decomp_table_markdown(const std::vector<DecompResult>& rows);
std::string decomp_table_csv(const std::vector<DecompResult>& rows);

// Writes table.md, table.csv, results.json and, per domain grid, two charts under charts/ (mismatched boundary
// pairs in % and momentum drift per bead, clustered by seeding with one bar per generator: data files and
// gnuplot scripts, SVG and PNG when gnuplot is installed) under dir, creating it; returns the Markdown. log
// (optional) hears of gnuplot failures.
std::string write_decomp_outputs(const DecompSweep& sweep, const std::vector<DecompResult>& rows,
                                 const std::string& dir, std::ostream* log);

}  // namespace dpdrng::study
