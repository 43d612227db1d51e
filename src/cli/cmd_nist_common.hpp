#pragma once
// Input and output options shared by `dpdrng nist` and its per-test subcommands.
#include <CLI/CLI.hpp>
#include <functional>
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
  // A per-test subcommand takes the input options given to `dpdrng nist` before the test's name
  // (`dpdrng nist --format raw runs -i F`); an option given on both sides is an InputError.
  void inherit(const CLI::App& parent, const CLI::App& sub);
  // The option checks that need no input (run before any work); throws InputError.
  void check() const;
  // Reads and splits the input; throws InputError with the reason.
  std::vector<stats::nist::BitSequence> load() const;
  std::string source() const { return input == "-" ? "<stdin>" : input; }
};

// Throws InputError naming the flag of a bad parameter of any of `tests`; `flag` maps a Parameters field name
// to the option that sets it.
void check_nist_parameters(const std::vector<stats::nist::Test>& tests, const stats::nist::Parameters& p,
                           const std::function<std::string(const std::string& field)>& flag);

// Prints per-sequence results (TSV, JSON or the finalAnalysisReport) with the second-level assessment.
void print_nist(const NistInput& in, const std::vector<std::vector<stats::nist::TestResult>>& results,
                const nlohmann::json& parameters);

}  // namespace dpdrng::cli
