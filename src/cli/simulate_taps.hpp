#pragma once
// `dpdrng simulate --tap-words FILE --tap-zeta FILE --tap-steps A:B`: the numbers the force used, for the
// statistical tests and external batteries. Per production step A..B (default: every production step, the
// steps of the run's zeta block), the pairs inside r_c (the pairs whose ζ entered the force) in the canonical
// order (i, j), i < j, ascending by bead index: their generator words (raw little-endian uint64; the block's
// words, then under the blocks feed the second block's) and their ζ (raw little-endian float64). A step that
// blew up is not written (as in the zeta block). Each file has a JSON sidecar FILE.json; data files and sidecars
// are written under hidden temporary names and renamed once all are whole.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "dpdrng/common/output.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/water.hpp"

namespace dpdrng::cli {

struct TapOptions {
  std::string words, zeta;  // files; empty: not written
  std::string steps;        // "A:B"; empty: every production step

  void add_to(CLI::App& app);
  bool any() const { return !words.empty() || !zeta.empty(); }
  // The first tap option given ("--tap-words", …), or "".
  std::string given() const;
  // Checks the options against the run's config, before any work (InputError naming the flag), and sets
  // cfg.taps' production steps to tap.
  void apply(dpd::WaterConfig& cfg) const;
  // Checks that the files can be created (InputError naming the flag): once the run may begin to write.
  void check_paths() const;
};

// Writes the taps of one run step by step (steps() hands out the hook) and commits them after it.
class TapWriter {
 public:
  TapWriter(const TapOptions& options, const dpd::WaterConfig& cfg);
  ~TapWriter();
  // The hook for dpd::RunHooks::in_range.
  void step(const dpd::InRangeTap& tap);
  // The sidecars from the run's labels, then every file synced and renamed.
  void commit(const dpd::RunResult& r);

 private:
  struct Output;
  nlohmann::json sidecar(const dpd::RunResult& r, const Output& o) const;
  dpd::WaterConfig cfg_;
  std::vector<std::unique_ptr<Output>> outputs_;
  std::vector<std::uint64_t> pairs_per_step_;
  std::int64_t last_step_ = -1;
  int words_per_pair_ = 0;
};

}  // namespace dpdrng::cli
