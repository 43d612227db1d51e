#pragma once
// The stability study's view of its cells ([sweep] integrators; study/stability.toml): a method is an integrator
// with a generator and its noise (distribution and feed); each method is run at every Δt of the sweep. One point
// per method × Δt holds how many replicas stayed stable, how and when the others blew up, and the accuracy of the
// stable ones against k_BT = 1, the literature pressure and the smallest-Δt MT19937 runs. A point whose replicas
// all blew up keeps its row: it has no accuracy, and says so.
#include <filesystem>
#include <string>
#include <vector>

#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/report.hpp"

namespace dpdrng::study {

// Conservative-virial pressure of the water scene (ρ = 3, a = 25, r_c = 1) at k_BT = 1: Allen & Tildesley's DPD
// example (examples repository, python_examples/GUIDE.md "DPD program"), 23.636(2) with Shardlow's scheme and
// 23.635(3) with the Lowe thermostat, both of which hold k_BT = 1 exactly (tests/dpd/test_physics.cpp).
inline constexpr double kWaterPressureConservative = 23.64;

struct StabilityPoint {
  std::string integrator;  // Cell::integrator ("mvv:0.5", "shardlow"; empty: MVV at the scene's λ)
  std::string generator;   // Cell::label(): "mt19937", "tea32(1)", …
  std::string noise;       // Cell::noise(): "gauss", "gauss-blocks", …
  double gamma = 0;        // Cell::gamma: a reference_gammas value, 0 for the scene's γ
  bool reference = false;  // the reference generator's cells
  double dt = 0;
  std::size_t replicas = 0, stable = 0;  // stable: no blow-up within the run
  long first_blowup_step = -1;  // earliest step at which a replica blew up (-1: none did)
  std::string reason;           // that replica's reason, without the "unstable at step k: " prefix
  // Replica means over the stable replicas, NaN when none is stable.
  // ⟨k_BT⟩ and ⟨T_conf⟩ with 95 % half-widths whose variance of one replica is pooled over every method at the
  // same integrator, Δt and γ (the point's own spread alone when it is larger than that pool's).
  double temperature = NAN, temperature_ci = NAN;
  double temperature_conf = NAN, temperature_conf_ci = NAN;
  double pressure_conservative = NAN;
  double diffusion = NAN;
  double temperature_error = NAN;    // |⟨k_BT⟩ − 1|
  double pressure_error = NAN;       // |P_c − 23.64| / 23.64
  double pressure_ref_error = NAN;   // |P_c − P_c,ref| / P_c,ref (the reference at the smallest Δt)
  double diffusion_error = NAN;      // |D − D_ref| / D_ref
  double rdf_error = NAN;            // mean relative deviation of g(r) from g_ref(r) where g_ref ≥ 0.1
  // Wall seconds of a step (median over the stable replicas) and per unit of simulated time (step seconds / Δt).
  double step_seconds = NAN, seconds_per_time = NAN;

  std::string method() const;  // "mvv:0.5 tea32(1) gauss-blocks", "mvv:0.65 mt19937 gauss γ4.5"
  bool all_blew_up() const { return replicas > 0 && stable == 0; }
};

struct StabilityAnalysis {
  std::vector<StabilityPoint> points;  // methods in sweep order, Δt ascending within each
  // The reference of P, D and g(r): MT19937 cells at the smallest Δt and the scene's γ, under the first feed,
  // every integrator's stable replicas pooled.
  double reference_dt = NAN;
  std::size_t reference_cells = 0;
  double reference_pressure = NAN;
  double reference_diffusion = NAN;
  std::vector<double> reference_rdf;
  std::vector<std::string> cpus;  // the cost.cpu notes of the cells, each once
};

StabilityAnalysis analyse_stability(const StudyConfig& config, const std::vector<CellResult>& cells);
std::vector<std::string> stability_methods(const StabilityAnalysis& a);  // each point's method once, in order

// Which temperature a frontier reads: the kinetic one, or the configurational one (PNHLN's thermostat acts on the
// momenta and pins the kinetic temperature, so its error shows in the configurational one).
enum class Thermometer { kinetic, configurational };
const char* to_string(Thermometer t);

// A method's accuracy frontier from the 95 % CIs of its replica mean: `inside` is the largest Δt whose CI lies
// inside 1 ± tolerance with every replica stable; `outside` the smallest Δt above it whose CI lies wholly outside
// or at which a replica blew up (without an `inside`, the smallest such Δt). The frontier lies in the bracket
// (inside, outside]; Δt between them have CIs that straddle the band's edge. `outside_below` lists the Δt below
// `inside` whose CI lies wholly outside: an accurate Δt above an inaccurate one is a cancellation, not accuracy.
struct Frontier {
  double inside = NAN, outside = NAN;
  std::vector<double> outside_below;
};
Frontier accuracy_frontier(const StabilityAnalysis& a, const std::string& method, Thermometer t, double tolerance);
std::string bracket_text(const Frontier& f);  // "0.03 – 0.04", "none – 0.01", "1 – none in the sweep"

// Per method: the smallest Δt at which a replica blew up (NaN when none did).
double first_unstable_dt(const StabilityAnalysis& a, const std::string& method);

// One integrator ranked: the reference generator under the first feed at the scene's γ, by its ±1 % frontier
// (configurational for PNHLN, kinetic for the others), then by the cost per unit of simulated time at the
// frontier's `inside` Δt.
struct IntegratorRank {
  std::string integrator, method;
  Thermometer ranked_by = Thermometer::kinetic;
  Frontier kinetic, configurational;
  double step_seconds = NAN;       // median over the method's stable points of their median step seconds
  double relative_step_cost = NAN; // step_seconds / that of the first GW-MVV integrator of the sweep
  double seconds_per_time = NAN;   // step_seconds / the ranked frontier's inside Δt
  double jdpd_factor = NAN;        // Jdpd's published relative cost of the scheme (NaN: not sourced)
};
std::vector<IntegratorRank> rank_integrators(const StabilityAnalysis& a, double tolerance);
// Jdpd's relative cost per step of a scheme spelt as in [sweep] integrators; NaN when it publishes none.
double jdpd_cost_factor(const std::string& integrator);

// The crossing of noise error and integrator error: every point of an integrator that draws pair noise, at the
// scene's γ. For a variant, noise_shift = ⟨k_BT⟩ − the reference's ⟨k_BT⟩ at the same integrator, feed and Δt
// and integrator_error = the reference's ⟨k_BT⟩ − 1, each with the 95 % half-width √(h₁² + h₂²) of its two
// replica means (h of the reference alone for integrator_error). They cancel when both are resolved (CI clear
// of 0) with opposite signs: "full" when the variant's CI of k_BT contains 1, "partial" otherwise.
struct CrossingRow {
  std::string integrator, generator, noise;
  bool reference = false;
  double dt = 0;
  double temperature = NAN, temperature_ci = NAN, temperature_conf = NAN, temperature_conf_ci = NAN;
  double noise_shift = NAN, noise_shift_ci = NAN;            // NaN for the reference's own rows
  double integrator_error = NAN, integrator_error_ci = NAN;
  std::string cancellation;  // "full", "partial", "none"; "not applicable: …" for reference rows and blow-ups
};
std::vector<CrossingRow> crossing_rows(const StabilityAnalysis& a);

std::string stability_csv(const StabilityAnalysis& a);
std::string frontier_csv(const StabilityAnalysis& a, double tolerance);
std::string ranking_csv(const std::vector<IntegratorRank>& r);
std::string crossing_csv(const std::vector<CrossingRow>& rows);
std::string stability_map_markdown(const StabilityAnalysis& a);  // Δt × method → stable/replicas, step, reason
std::string frontier_markdown(const StabilityAnalysis& a, double tolerance);  // per method: both brackets
std::string ranking_markdown(const std::vector<IntegratorRank>& r, double tolerance);
std::string crossing_markdown(const std::vector<CrossingRow>& rows);
std::string accuracy_markdown(const StabilityAnalysis& a);       // every point: accuracy and cost
// The friction series beside the scene's γ: per reference_gammas method, its k_BT and T_conf brackets and those of
// the same integrator and noise with the reference at the scene's γ ("" when the study has no such series).
std::string gamma_series_markdown(const StabilityAnalysis& a, double tolerance);
// Accuracy against cost per unit simulated time (one curve per method; blown-up points drawn on the top edge), the
// integrators' panel (cost against signed temperature error with CIs), the crossing (k_BT and T_conf against Δt
// per integrator) and the fraction stable against Δt; returns the chart names made.
std::vector<std::string> write_stability_charts(const StabilityAnalysis& a, double tolerance,
                                                const std::filesystem::path& dir,
                                                std::ostream* log);
std::filesystem::path write_stability_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                                             const std::filesystem::path& study_dir, const ReportOptions& options);

}  // namespace dpdrng::study
