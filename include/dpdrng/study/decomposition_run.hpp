#pragma once
// A decomposition check of the water scene, from a config to a result with no I/O (the CLI and the sweep call
// it). The engine supplies the decomposed forces (dpd/decomposition.hpp); the runs and the tests of their noise
// are study work. Two runs from the same start: the undecomposed reference (one domain per axis: minimum images,
// the engine's numbers) and the decomposed run, both driven by the engine's integrator with DecomposedForces as
// the force callback. The boundary bookkeeping is taken on the first force evaluation (a snapshot) and summed
// over the decomposed run; the reference run's noise feeds the statistical tests (what a seeding costs in
// randomness does not depend on the decomposition).
//
//   study::DecompConfig c;
//   c.domains = dpd::parse_domains("2,2,1");
//   c.noise.generator = rng::validated({"tea32", 1});
//   c.noise.seeding = dpd::parse_decomp_seeding("grid:32");
//   study::DecompResult r = study::run_decomposition(c);
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/decomposition.hpp"
#include "dpdrng/dpd/result.hpp"

namespace dpdrng::study {

struct DecompConfig {
  // Scene and integrator (particles, density, a, rc, kT, gamma, lambda, dt, steps, equilibrate, init_seed,
  // sample_every, max_temperature, min_distance). Its generator/seeding/pairs fields are not used.
  dpd::WaterConfig water;
  dpd::DomainGrid domains{{2, 1, 1}};
  dpd::DecompNoise noise;
  bool reference = true;   // also run undecomposed, for the observables and the randomness tests
  int chi2_every = 100;    // χ² on every pair's word at every chi2_every-th production step (0 = none)
  int ttest_pairs = 32;    // pairs (i, i+1), i = 0.., whose word series get the lag-1 t-test (0 = none)
  double alpha = 0.01;

  void validate() const;  // throws InputError naming the field
};

// One run's observables.
struct DecompRun {
  dpd::RunStatus status;
  std::int64_t steps_done = 0;
  dpd::Stat temperature, pressure;
  double diffusion = 0, diffusion_sem = 0;
  double momentum_drift = 0;        // max over steps of |P(t) − P(0)| per bead (as run_water)
  double momentum_final = 0;        // |P(end) − P(0)| per bead
  double com_kinetic_share = 0;     // ½ N |v_com|² / (½ Σ v²) at the end: the heat the drift put in
  dpd::BoundaryStats boundary;           // summed over the run's force evaluations
  double seconds = 0;
};

// What the seeding costs in randomness, measured on the reference run's raw words (word 0 → [0,1)). A figure
// over no test (--chi2-every 0, --ttest-pairs 0) is NaN, "not applicable" (null in JSON), never 0 or 1.
struct RandomnessCost {
  std::size_t chi2_tests = 0, chi2_pass = 0;  // one step's N(N−1)/2 words each, Sturges bins, α
  double chi2_min_p = NAN;
  std::size_t lag1_tests = 0, lag1_pass = 0;  // one pair's production-step series each
  double lag1_max_abs_r = NAN;
  double cross_pair_r = NAN, cross_pair_p = NAN;  // pair slot p vs p+1 at the same step, pooled
  std::string cross_pair_verdict = "n/a";
  double duplicates_per_step = 0;             // pairs whose word equals another pair's word at the same step
  double chi2_pass_fraction() const { return chi2_tests ? double(chi2_pass) / chi2_tests : NAN; }
  double lag1_pass_fraction() const { return lag1_tests ? double(lag1_pass) / lag1_tests : NAN; }
};

struct DecompResult {
  std::string generator, seeding, distribution, domains;
  std::string feed = "halves";
  std::size_t particles = 0;
  double box_length = 0;
  dpd::BoundaryStats snapshot;  // the first force evaluation of the decomposed run (the initial configuration)
  DecompRun decomposed;
  bool has_reference = false;
  DecompRun reference;
  RandomnessCost randomness;
};

DecompResult run_decomposition(const DecompConfig& cfg);

nlohmann::json to_json(const dpd::BoundaryStats& b);
nlohmann::json to_json(const DecompResult& r);

}  // namespace dpdrng::study
