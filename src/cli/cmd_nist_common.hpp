#pragma once
// Input and output options shared by `dpdrng nist` and its per-test subcommands.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/bitstream.hpp"

namespace dpdrng::cli {

struct NistInput {
  std::string input;
  std::string format = "ascii";
  std::size_t streams = 0;  // 0: one stream of all the input
  std::size_t stream_bits = 0;
  double alpha = 0.01;
  bool tsv = false;
  bool json = false;

  void add_to(CLI::App& app);
  // Reads and splits the input; throws InputError with the reason.
  std::vector<stats::nist::BitSequence> load() const;
  std::string source() const { return input == "-" ? "<stdin>" : input; }
};

// Prints per-sequence results (TSV, JSON or the finalAnalysisReport) with the second-level assessment.
void print_nist(const NistInput& in, const std::vector<std::vector<stats::nist::TestResult>>& results,
                const nlohmann::json& parameters);

}  // namespace dpdrng::cli
