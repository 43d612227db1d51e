#pragma once
// The bilayer scene's CLI glue, shared by `dpdrng simulate-bilayer` and `dpdrng simulate --scene bilayer`.
#include <CLI/CLI.hpp>
#include <string>

#include "dpdrng/cli/options.hpp"
#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/config.hpp"

namespace dpdrng::cli {

// Runs the scene and prints the human table or (json) the JSON record; series_dir: profile.csv, series.csv
// and order.csv there.
void run_bilayer_scene(const dpd::BilayerConfig& cfg, bool json, bool quiet, const std::string& series_dir);

// `dpdrng simulate --scene bilayer`: the options of `simulate` that the user set explicitly (sub.count > 0)
// override the scene's defaults; the water defaults do not leak in. --particles, --density, --a and --rc are
// fixed by the scene (InputError if given). The warm-up is min(1 000, equilibrate) steps at dt 0.005.
void simulate_bilayer(const CLI::App& sub, const dpd::WaterConfig& w, const RunOptions& o);

}  // namespace dpdrng::cli
