#pragma once
// dpd::run_water: the paper's water scene (Okada, Brumby & Yasuoka 2021) and its variations, from a
// WaterConfig to a RunResult, with no I/O. This is the API the study driver and the CLI call.
//
//   dpd::WaterConfig cfg;                       // the paper's defaults
//   cfg.generator = rng::validated({"tea32", 1});
//   cfg.taps.raw_steps = {500};                 // one step's 32 640 numbers for the χ² test
//   cfg.taps.pairs = {{0, 1}};                  // the 9 500 numbers pair (0,1) gets, for the lag-1 t-test
//   dpd::RunResult r = dpd::run_water(cfg);     // throws InputError for a bad config
//
// Steps: force evaluation 0 is the start; step k = 1..steps moves the beads and evaluates forces (and draws
// numbers) with step number k. Production steps are k > equilibrate (the paper: 9 500 of 10 000).
#include <functional>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/result.hpp"

namespace dpdrng::dpd {

struct RunHooks {
  // Called about every 2 % of the steps (for progress bars); not called for short runs.
  std::function<void(std::int64_t step, std::int64_t steps)> progress;
  // Called after every completed step (equilibration included) with the state at its end: positions
  // wrapped, velocities v(t+Δt), forces of that step. For tests and custom observables; costs nothing unset.
  std::function<void(std::int64_t step, const System& s)> observe;
  // Called with the pairs inside r_c of each step of cfg.taps.in_range that passed the guards, in step order.
  std::function<void(const InRangeTap& tap)> in_range;
  // Called with each raw tap (cfg.taps.raw_steps) as soon as its step's forces are done, while its words are in
  // cache. Returning true takes it: it is not kept in RunResult::taps.raw and its storage serves the next raw
  // step. Unset, or returning false: the tap is kept.
  std::function<bool(const RawTap& tap)> raw;
};

RunResult run_water(const WaterConfig& cfg, const RunHooks& hooks = {});

}  // namespace dpdrng::dpd
