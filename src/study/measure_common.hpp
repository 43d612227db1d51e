#pragma once
// Pieces the water cell (measure_engine.cpp) and the bilayer cell (measure_bilayer.cpp) share; internal to
// src/study. The engine's two configs and results spell these fields alike, so one template serves both
// without the engine knowing about cells.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study::detail {

// The scene's and the cell's settings common to every scene's engine config: sizes, noise, Δt, steps, pairs.
template <class EngineConfig>
void set_run(EngineConfig& c, const Cell& cell, const SceneParams& s, int threads) {
  c.particles = s.particles;
  c.kT = s.kT;
  c.gamma = cell.gamma > 0 ? cell.gamma : s.gamma;
  c.lambda = s.lambda;
  c.dt = cell.dt;
  c.steps = s.steps_at(cell.dt);
  c.equilibrate = s.equilibrate_at(cell.dt);
  c.pairs = s.pairs;
  c.generator = rng::validated(rng::GeneratorSpec{cell.generator, cell.rounds, rng::kPaperTeaKey});
  c.seeding = cell.seeding;  // ignored by a stream
  c.distribution = cell.distribution;
  c.feed = cell.feed;
  c.seed = cell.seed;
  // The same initial state for every generator of a replica: differences between generators are then not
  // diluted by different starting points (paired comparison).
  c.init_seed = cell.seed;
  c.threads = threads;
  c.series = true;
}

// At most ~`points` samples of a long series, evenly strided: the chart needs the shape, not every step.
std::vector<double> thin(const std::vector<double>& v, std::size_t points);

// cost.run_seconds, cost.step_seconds, cost.ns_per_number, cost.rng_share, cost.particle_steps_per_second and
// (after at least one step) cost.numbers_per_step.
void record_costs(const dpd::Timings& t, std::int64_t steps_done, CellResult& out);

// zeta_autocorrelation_<l> and zeta_shared_bead_correlation, each with _se and _n (none where not measured).
void record_zeta_correlation(const dpd::ZetaCorrelation& z, CellResult& out);

}  // namespace dpdrng::study::detail
