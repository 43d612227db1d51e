#pragma once
// Internal to the CLI: bench dpd beside LAMMPS. Each scene of the table (the cells scene, and the paper's 256-bead
// fluid that dpdrng runs with all pairs and LAMMPS with its neighbour list) runs in dpdrng's engine (tea32(1)), in LAMMPS with
// its own pair_style dpd and in LAMMPS with pair_style dpd/hash tea32 1 (distance seeding, the run's distribution
// and feed), one after the other in each of --repeat rounds, so that a load that comes and goes meets all three.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/study/lammps_bench.hpp"

namespace dpdrng::cli::bench_dpd_lammps {

// The reason for "not applicable" when LAMMPS was not looked for or not found.
inline constexpr const char* kNotBuilt = "LAMMPS not built";
inline constexpr const char* kDisabled = "--no-lammps";

// Where lmp_dpdrng is: --lammps PATH (InputError unless executable), else build/lammps/lmp_dpdrng under the
// working folder, else PATH. nullopt: not looked for (--no-lammps) or not found; `why` then says which.
std::optional<std::string> locate(const std::string& explicit_path, bool disabled, std::string& why);

struct Side {
  std::string label;           // the scene: "cells scene", "all-pairs scene"
  std::string launcher;        // empty: not run
  std::string not_applicable;  // the reason when there are no LAMMPS figures
  std::string own_style, hash_style;
  study::lammps::Scene scene;
  int threads = 1;
  std::vector<double> dpdrng_s, own_s, hash_s;  // each round's production wall time
  double dpdrng_ps = 0, own_ps = 0, hash_ps = 0;  // particle-steps/s of the median times
  bool measured() const { return not_applicable.empty(); }
};

// The scene of `cfg` (the cells or the all-pairs scene with tea32(1)), called `label`, in LAMMPS, `repeat` rounds, each: `dpdrng_round()` (returns
// the production seconds of dpdrng's run), then pair_style dpd, then pair_style dpd/hash. A LAMMPS run that fails
// leaves the figures not applicable with LAMMPS's reason; dpdrng's own results stand.
Side measure(const std::string& label, const std::string& launcher, const dpd::WaterConfig& cfg,
             const std::string& distribution,
             const std::string& feed, int threads, int repeat, const std::function<double()>& dpdrng_round);

// A Side that was not measured, for `why`.
Side not_applicable(const std::string& label, const std::string& why);

void print(const Side& side);
nlohmann::json to_json(const Side& side);

}  // namespace dpdrng::cli::bench_dpd_lammps
