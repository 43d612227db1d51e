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
  double dt = 0;
  std::size_t replicas = 0, stable = 0;
  long first_blowup_step = -1;  // earliest step at which a replica blew up (-1: none did)
  std::string reason;           // that replica's reason, without the "unstable at step k: " prefix
  // Replica means over the stable replicas, NaN when none is stable.
  double temperature = NAN, temperature_ci = NAN;  // ⟨k_BT⟩ and its 95 % half-width (replica_mean)
  double pressure_conservative = NAN;
  double diffusion = NAN;
  double temperature_error = NAN;  // |⟨k_BT⟩ − 1|
  double pressure_error = NAN;     // |P_c − 23.64| / 23.64
  double diffusion_error = NAN;    // |D − D_ref| / D_ref
  double rdf_error = NAN;          // mean relative deviation of g(r) from g_ref(r) where g_ref ≥ 0.1
  // Wall seconds per unit of simulated time: median over the stable replicas of step seconds / Δt (NaN: none).
  double seconds_per_time = NAN;

  std::string method() const;  // "mvv:0.5 tea32(1) gauss-blocks"
  bool all_blew_up() const { return replicas > 0 && stable == 0; }
};

struct StabilityAnalysis {
  std::vector<StabilityPoint> points;  // methods in sweep order, Δt ascending within each
  // The reference of D and g(r): MT19937 cells at the smallest Δt, every integrator's stable replicas pooled.
  double reference_dt = NAN;
  std::size_t reference_cells = 0;
  double reference_diffusion = NAN;
  std::vector<double> reference_rdf;
};

StabilityAnalysis analyse_stability(const StudyConfig& config, const std::vector<CellResult>& cells);

// Per method: the largest Δt whose |⟨k_BT⟩ − 1| is below `tolerance` with every replica stable at it and at
// every smaller Δt (NaN when none); and the smallest Δt at which a replica blew up (NaN when none did).
double largest_accurate_dt(const StabilityAnalysis& a, const std::string& method, double tolerance);
double first_unstable_dt(const StabilityAnalysis& a, const std::string& method);

std::string stability_csv(const StabilityAnalysis& a);
std::string stability_map_markdown(const StabilityAnalysis& a);  // Δt × method → stable/replicas, step, reason
std::string frontier_markdown(const StabilityAnalysis& a);       // per method: largest Δt within 1 %, 3 %; blow-up Δt
std::string accuracy_markdown(const StabilityAnalysis& a);       // every point: accuracy and cost
// Accuracy against cost per unit simulated time (one curve per method; blown-up points drawn on the top edge) and
// the fraction stable against Δt; returns the chart names made.
std::vector<std::string> write_stability_charts(const StabilityAnalysis& a, const std::filesystem::path& dir,
                                                std::ostream* log);
std::filesystem::path write_stability_report(const StudyConfig& config, const std::vector<CellResult>& cells,
                                             const std::filesystem::path& study_dir, const ReportOptions& options);

}  // namespace dpdrng::study
