#include "simulate_physics.hpp"

#include <iomanip>
#include <sstream>
#include <vector>

#include "dpdrng/stats/noise_power.hpp"

namespace dpdrng::cli {
namespace simulate_physics {
namespace {

stats::Measured measured(const dpd::Stat& s) { return {s.mean, s.sem, s.sem_dof > 0 ? s.sem_dof : INFINITY}; }

std::string pm(const dpd::Stat& s, int digits = 6) {
  if (s.n == 0) return "n/a";
  std::ostringstream o;
  o << std::setprecision(digits) << s.mean << " ± " << std::setprecision(2) << s.sem;
  return o.str();
}

std::string pm(const dpd::Estimate& e) {
  if (!e.not_applicable.empty()) return "n/a (" + e.not_applicable + ")";
  std::ostringstream o;
  o << std::setprecision(3) << e.mean << " ± " << std::setprecision(2) << e.se;
  return o.str();
}

// s padded with spaces to `width` columns (UTF-8: continuation bytes take no column, unlike std::setw's count).
std::string pad(const std::string& s, std::size_t width) {
  std::size_t cols = 0;
  for (const char c : s) cols += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return s + std::string(width > cols ? width - cols : 1, ' ');
}

// The main observables of a water run, by name and unit.
struct Observable {
  std::string name, unit;
  dpd::Stat stat;
};
std::vector<Observable> main_observables(const dpd::RunResult& r) {
  std::vector<Observable> v = {{"k_BT (kinetic)", "ε", r.temperature},
                               {"k_BT (configurational)", "ε", r.configurational_temperature},
                               {"pressure", "ε/r_c³", r.pressure}};
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) v.push_back({std::string("k_BT_") + axes[a], "ε", r.temperature_diag[a]});
  for (int a = 0; a < 3; ++a)
    v.push_back({std::string("P_") + axes[a] + axes[a], "ε/r_c³", r.pressure_diag[a]});
  if (dpd::blew_up(r.status))
    for (Observable& x : v) x.stat = dpd::Stat{};  // a run that blew up has no observables
  return v;
}

}  // namespace
}  // namespace simulate_physics

using namespace simulate_physics;

std::string physics_lines(const dpd::RunResult& r) {
  std::ostringstream o;
  o << "k_BT configurational   " << pm(r.configurational_temperature)
    << " ε (Rugh: <Σ|∇U|²>/<Σ∇²U>, conservative U)\n";
  o << "k_BT x, y, z           " << pm(r.temperature_diag[0]) << ", " << pm(r.temperature_diag[1]) << ", "
    << pm(r.temperature_diag[2]) << " ε\n";
  o << "pressure xx, yy, zz    " << pm(r.pressure_diag[0]) << ", " << pm(r.pressure_diag[1]) << ", "
    << pm(r.pressure_diag[2]) << " ε/r_c³\n";
  o << "zeta <w²ζ²>/<w²>       " << pm(r.zeta_weighted_second_moment) << " (w = 1 − r/r_c; dimensionless)\n";
  const dpd::ZetaCorrelation& c = r.zeta_correlation;
  if (c.requested) {
    o << "zeta autocorrelation   ";
    if (!c.not_applicable.empty()) {
      o << "n/a (" << c.not_applicable << ")\n";
    } else {
      for (std::size_t l = 0; l < c.autocorrelation.size(); ++l)
        o << (l ? "; " : "") << "lag " << l + 1 << ": " << pm(c.autocorrelation[l]);
      o << " (steps; " << c.segments << " pair segments inside r_c)\n"
        << "zeta shared-bead corr. " << pm(c.shared_bead) << " (pairs ij, ik at one step)\n";
    }
  }
  return o.str();
}

std::string reference_note(const dpd::RunResult& r) {
  if (r.generator == "mt19937") return "";
  return "note                   this run's error mixes the noise's and the integrator's: only a comparison with\n"
         "                       the reference at the same settings (--compare mt19937) separates them\n";
}

std::string compare_lines(const dpd::RunResult& variant, const dpd::RunResult& reference) {
  const auto v = main_observables(variant), ref = main_observables(reference);
  std::ostringstream o;
  o << "\ncomparison: " << variant.generator << " − " << reference.generator
    << " at the same feed, seeding, integrator, Δt and initial state (95 % CI; independent runs)\n";
  o << pad("observable", 24) << pad(variant.generator, 22) << pad(reference.generator, 22) << "shift [95 % CI]\n";
  for (std::size_t k = 0; k < v.size(); ++k) {
    o << pad(v[k].name, 24) << pad(pm(v[k].stat), 22) << pad(pm(ref[k].stat), 22);
    if (v[k].stat.n == 0 || ref[k].stat.n == 0) {
      o << "n/a\n";
      continue;
    }
    const stats::Shift s = stats::independent_shift(measured(v[k].stat), measured(ref[k].stat));
    o << std::setprecision(4) << std::showpos << s.delta << " [" << s.low << ", " << s.high << "]" << std::noshowpos
      << " " << v[k].unit << "\n";
  }
  return o.str();
}

nlohmann::json compare_shifts_json(const dpd::RunResult& variant, const dpd::RunResult& reference) {
  const auto v = main_observables(variant), ref = main_observables(reference);
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t k = 0; k < v.size(); ++k) {
    nlohmann::json e = {{"observable", v[k].name}, {"unit", v[k].unit}};
    if (v[k].stat.n == 0 || ref[k].stat.n == 0) {
      e["shift"] = nullptr;
      e["not_applicable"] = "not applicable: a run without this observable";
    } else {
      const stats::Shift s = stats::independent_shift(measured(v[k].stat), measured(ref[k].stat));
      e["shift"] = {{"mean", s.delta}, {"se", s.se}, {"dof", s.dof}, {"ci95", {s.low, s.high}}};
    }
    j.push_back(e);
  }
  return j;
}

}  // namespace dpdrng::cli
