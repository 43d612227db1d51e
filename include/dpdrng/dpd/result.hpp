#pragma once
// What a DPD run returns: status, observables (means with spread and block-average standard errors),
// distributions, timings and the taps for the statistical tests. A run that blows up is data, not a crash:
// status says "unstable at step k: reason" and the observables cover the steps done.
#include <array>
#include <cmath>
#include <cstdint>
#include <iosfwd>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "dpdrng/dpd/pair_forces.hpp"

namespace dpdrng::dpd {

// Blocks (of consecutive samples, or of beads) behind the jackknife errors of the velocity PDF's error rate and
// of D: each such error carries kStatBlocks − 1 degrees of freedom.
inline constexpr std::size_t kStatBlocks = 20;

// With fewer than 2 samples std and the standard errors are NaN: not computable, never 0.
struct Stat {
  double mean = 0, std = 0;
  double sem = 0;      // standard error of the mean of correlated samples, from their integrated autocorrelation time
  double sem_dof = 0;  // degrees of freedom of sem² as a variance estimate
  double std_sem = 0;  // standard error of std, from the autocorrelation time of (x − mean)²
  double std_sem_dof = 0;
  std::size_t n = 0;
};
Stat make_stat(const std::vector<double>& samples);
// The ratio of means ⟨a⟩/⟨b⟩ of paired samples (a_t, b_t), with its standard error by the delta method: the sem
// (autocorrelation included, as make_stat) of the series (a_t − R b_t)/⟨b⟩. n = 0 (none) below 2 samples or
// when ⟨b⟩ is not positive.
Stat make_ratio_stat(const std::vector<double>& a, const std::vector<double>& b);

// A measured quantity with its standard error, or why it has none (then mean and se are NaN).
struct Estimate {
  double mean = NAN, se = NAN;
  std::uint64_t n = 0;         // products (pair-steps) behind it
  std::string not_applicable;  // empty when measured
};

// Correlations of the ζ the force used, on tracked pairs that stay inside r_c (zeta_track.hpp).
struct ZetaCorrelation {
  bool requested = false;                 // WaterConfig::zeta_lags > 0
  std::string not_applicable;             // why nothing was measured (empty when measured)
  std::vector<Estimate> autocorrelation;  // ρ_l = ⟨ζ_t ζ_{t+l}⟩ / ⟨ζ²⟩ of one pair, l = 1…K
  Estimate shared_bead;                   // ⟨ζ_ij ζ_ik⟩ / ⟨ζ²⟩ of two pairs sharing bead i, same step
  std::uint64_t segments = 0;             // tracked pair segments
};

// Velocity components pooled over x, y, z and sampled production steps, against Maxwell–Boltzmann.
struct VelocityPdf {
  std::vector<double> v;                       // bin centres
  std::array<std::vector<double>, 3> pdf;      // measured density per component
  std::vector<double> mb_kT, mb_measured;      // bin-averaged MB density at k_BT and at the measured T
  // Mean over bins with MB probability mass ≥ 1e-3 of |P − P_th| / P_th (the paper's error rate), per
  // component and pooled; tails are left out because their relative error is counting noise.
  std::array<double, 3> error_rate_kT{}, error_rate_measured{};
  double error_rate_kT_mean = 0, error_rate_measured_mean = 0;  // NaN where a rate has no value
  std::string measured_not_applicable;         // why error_rate_measured_mean is NaN
  double error_rate_kT_mean_sem = 0;           // jackknife over the histogram's blocks (NaN with fewer than 2)
  double error_rate_kT_mean_sem_dof = 0;       // blocks with samples − 1
  std::vector<std::vector<double>> jackknife;  // the pooled density with one block left out, per block with samples
  std::size_t samples = 0;                     // velocity components counted per component
};

struct Msd {
  std::vector<double> tau, msd;  // msd(τ) averaged over particles and time origins
  double fit_from = 0, fit_to = 0;
  double diffusion = NAN;        // slope / 6 of a least-squares line over [fit_from, fit_to]; NaN: not_applicable
  double diffusion_sem = NAN;    // jackknife over kStatBlocks groups of beads (NaN with fewer than 2 beads)
  std::string not_applicable;    // why there is no diffusion coefficient
  double diffusion_sem_dof = 0;  // groups − 1
  std::vector<std::vector<double>> jackknife;  // msd with one group of beads left out, per group
};

struct Rdf {
  std::vector<double> r, g;
  std::size_t samples = 0;
  std::vector<std::vector<double>> jackknife;  // g with one block of samples left out, per block that has samples
};

struct Timings {
  double total_s = 0, force_s = 0, per_step_s = 0;
  double particle_steps_per_s = 0;
  // The production steps alone (after equilibration): the steady-state cost, without the start-up transient
  // of a random initial configuration (hot overlaps, unstable first steps).
  double production_s = 0, production_particle_steps_per_s = 0;
  std::uint64_t random_numbers = 0;  // generator calls (all mode: every pair every step)
  std::uint64_t zetas = 0;           // distribution transforms (pairs inside r_c)
  // Over every force evaluation: pairs inside r_c (a ζ = 0 run's too) and the candidate pairs whose separation
  // the pair search computed to find them (all mode: every pair).
  std::uint64_t pairs_in_range = 0, pair_candidates = 0;
  double ns_per_number = 0;          // generator call, calibrated in a batch loop like the pair loop's
  double ns_per_zeta = 0;            // distribution transform (Box–Muller or √3(2u−1))
  // Water: the RNG's share of a step, by difference against ζ = 0 on the final state (rng_share_by_difference).
  double rng_share_estimate = 0;
  std::uint64_t list_builds = 0;
  int threads = 1;
  // The steps run with each team size: a TeamGovernor runs fewer than `threads` while that is faster.
  std::map<int, std::int64_t> steps_by_team;
  std::int64_t team_moves = 0;
};

struct Series {
  std::vector<std::int64_t> step;
  std::vector<double> temperature, pressure, pressure_conservative;
  std::vector<double> px, py, pz;  // total momentum
};

// How a run ended. unstable: it blew up at `step` and its observables mean nothing; disrupted (the bilayer): a
// lipid left the membrane at `step`, the run went on to the end and its observables are data.
enum class RunState { ok, unstable, disrupted };

std::string_view to_string(RunState s);          // "ok", "unstable", "disrupted"
RunState parse_run_state(std::string_view name);  // the inverse; throws InputError for any other name

struct RunStatus {
  RunState state = RunState::ok;
  std::int64_t step = -1;
  std::string detail;  // why, in words

  static RunStatus unstable(std::int64_t step, std::string why) { return {RunState::unstable, step, std::move(why)}; }
  static RunStatus disrupted(std::int64_t step, std::string why) { return {RunState::disrupted, step, std::move(why)}; }
  bool ok() const { return state == RunState::ok; }
  // What records and output carry: "ok", "unstable at step k: <detail>" or "disrupted at step k: <detail>".
  std::string text() const;
};
std::ostream& operator<<(std::ostream& o, const RunStatus& s);

struct RunResult {
  RunStatus status;
  bool ok() const { return status.ok(); }
  std::int64_t steps_done = 0;
  std::string generator, seeding, distribution, pairs;
  std::string feed = "halves";
  std::string integrator = "mvv";
  std::size_t particles = 0;
  double box_length = 0;

  Stat temperature;                            // k_BT from Σv²/(3N−3)
  Stat pressure, pressure_conservative;        // ρk_BT_kin + W/(3V)
  std::array<Stat, 3> pressure_diag, pressure_conservative_diag;
  std::array<Stat, 3> temperature_diag;       // k_BT_α = Σ v_α²/(N − 1): their mean is k_BT
  // ⟨Σ|∇_i U|²⟩ / ⟨Σ ∇_i²U⟩ over the conservative U, on the production steps that sample the velocity PDF
  // (every sample_every-th; n = 0: none)
  Stat configurational_temperature;
  Stat zeta_weighted_second_moment;            // Σ w_R²ζ² / Σ w_R² per step, as a ratio of means (n = 0: none)
  ZetaCorrelation zeta_correlation;
  double momentum_drift = 0;                   // max over steps of |P(t) − P(0)|, per bead
  std::array<double, 3> momentum_final{};

  VelocityPdf velocity_pdf;
  Msd msd;
  Rdf rdf;
  Series series;
  Taps taps;
  Timings timings;
  ZetaSums zeta;  // every ζ of the production steps' pairs inside r_c (none for a benchmark baseline)
};

// Scalars only unless `arrays` (then also pdf, msd, g(r), series; taps never: they are for the tests).
nlohmann::json to_json(const RunResult& r, bool arrays);

// Pieces every scene's JSON record shares, so that the water and bilayer records spell them alike.
nlohmann::json to_json(const Stat& s);           // {mean, std, sem, n}
nlohmann::json timings_json(const Timings& t);   // the whole-run timings (not the production-only figures)
nlohmann::json to_json(const ZetaSums& z);       // {n, s1, s2, s3, s4}: the power sums Σζ^k
nlohmann::json mean_se_json(const Stat& s);      // {mean, se}; null when n = 0
nlohmann::json to_json(const Estimate& e);       // {mean, se, n}; null when not applicable
nlohmann::json to_json(const ZetaCorrelation& z);
void put_mean_sem(nlohmann::json& j, const std::string& key, const Stat& s);   // key_mean, key_sem
void put_value_sem(nlohmann::json& j, const std::string& key, const Stat& s);  // key (the mean), key_sem
// The run blew up, and its observables mean nothing.
inline bool blew_up(const RunStatus& status) { return status.state == RunState::unstable; }
// For a run that blew up: every key of a JSON record except `kept` (labels, timings, diagnostics) becomes null.
void null_observables(nlohmann::json& j, std::initializer_list<const char*> kept);
// status, steps_done, the noise labels, pair mode and bead count of any scene's result.
template <class Result>
void put_run_labels(nlohmann::json& j, const Result& r) {
  j["status"] = r.status.text();
  j["steps_done"] = r.steps_done;
  j["generator"] = r.generator;
  // A plug-in's identity beside its path: the name it gives itself and its library's digest.
  if (rng::is_plugin(r.generator)) {
    const rng::LoadedPlugin& p = rng::load_plugin(r.generator);
    j["plugin"] = {{"name", p.name}, {"file", p.file}, {"sha256", p.sha256}};
  }
  j["seeding"] = r.seeding;
  j["distribution"] = r.distribution;
  j["feed"] = r.feed;
  j["pairs"] = r.pairs;
  j["particles"] = r.particles;
}

}  // namespace dpdrng::dpd
