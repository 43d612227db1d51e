#pragma once
// A sweep of the decomposition check (seeding × generator × rounds × domain grid × distribution) from a small
// TOML file (study/decomposition.toml), and its table. Each (generator, seeding, distribution) runs the
// undecomposed reference once; every domain grid then runs its decomposed copy against it.
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "dpdrng/study/decomposition_run.hpp"

namespace dpdrng::study {

struct DecompSweep {
  std::string name = "decomposition";
  std::string description;
  std::vector<rng::GeneratorSpec> generators;  // one entry per (name, rounds)
  std::vector<dpd::DecompSeeding> seedings;
  std::vector<rng::Distribution> distributions{rng::Distribution::gauss};
  std::vector<dpd::DomainGrid> domains;
  DecompConfig base;  // scene, steps, tests
};

// Unknown keys and bad values are InputErrors naming the key; `origin` names the source in messages.
DecompSweep parse_decomp_sweep(const std::string& toml_text, const std::string& origin);
DecompSweep load_decomp_sweep(const std::string& path);

using SweepProgress = std::function<void(std::size_t done, std::size_t total, const DecompResult& last)>;
std::vector<DecompResult> run_decomp_sweep(const DecompSweep& sweep, const SweepProgress& progress = {});

// One row per result. The Markdown table is the human summary; the CSV carries every column.
std::string decomp_table_markdown(const std::vector<DecompResult>& rows);
std::string decomp_table_csv(const std::vector<DecompResult>& rows);

// Per domain grid, a gnuplot chart: mismatched boundary pairs (%) and momentum drift per bead, clustered by
// seeding with one bar per generator. `data` goes to <name>.dat beside <name>.gp; the script sets no terminal.
struct DecompChart {
  std::string name, data, script;
};
std::vector<DecompChart> decomp_charts(const std::vector<DecompResult>& rows);

// Writes table.md, table.csv, results.json and the charts (.dat, .gp, and .svg when gnuplot is installed)
// under dir, creating it; returns the Markdown. log (optional) hears of gnuplot failures.
std::string write_decomp_outputs(const DecompSweep& sweep, const std::vector<DecompResult>& rows,
                                 const std::string& dir, std::ostream* log);

}  // namespace dpdrng::study
