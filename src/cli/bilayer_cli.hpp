#pragma once
// The bilayer scene's CLI glue, shared by `dpdrng simulate-bilayer` and `dpdrng simulate --scene bilayer`.
#include <string>

#include "dpdrng/dpd/bilayer.hpp"

namespace dpdrng::cli {

// Runs the scene and prints the human table or (json) the JSON record; series_dir: profile.csv, series.csv
// and order.csv there.
void run_bilayer_scene(const dpd::BilayerConfig& cfg, bool json, bool quiet, const std::string& series_dir);

}  // namespace dpdrng::cli
