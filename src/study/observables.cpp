#include "dpdrng/study/observables.hpp"

#include <stdexcept>

namespace dpdrng::study {
namespace observable_table {

constexpr const char* kEnergy = "k_BT";
constexpr const char* kPressure = "k_BT/r_c³";

// Margins: the temperature and pressure to half a percent (a thermostat's error a DPD user notices; the paper's
// worst generators shift T by several percent), diffusion to 3 % (its run-to-run spread is over ten times T's),
// T's fluctuation to 2 %, each diagonal component of the pressure tensor to 0.5 % (isotropy: a noise whose
// variance depends on the pair's direction shifts them apart), the configurational temperature to 0.5 % (as T:
// the noise moves both, the integrator only the kinetic one), each kinetic temperature component to 1 % (a third
// of the degrees of freedom: √3 times the scalar's spread). Curves bin by bin: the velocity PDF to 5 % in
// every bin above 1 % of its peak (the tails' counting noise), g(r) to 2 % outside the core, the MSD to 3 % (as D).
// The membrane's density profiles leave out bins below a tenth of their peak (the bulk water for tails).
std::vector<Observable> make() {
  using B = BudgetTarget;
  const auto shift = [](const char* key, const char* sem, const char* unit, const char* label, const char* margin_key,
                        double margin, B budget = B::none) {
    return Observable{.name = key, .key = key, .sem = sem, .unit = unit, .label = label, .rule = Rule::shift,
                      .scenes = kWater, .margin_key = margin_key, .margin = margin, .budget = budget};
  };
  const auto paired = [](const char* name, const char* key, const char* sem, const char* unit, const char* label,
                         const char* what, B budget = B::none) {
    return Observable{.name = name, .key = key, .sem = sem, .unit = unit, .label = label, .rule = Rule::paired,
                      .scenes = kBilayer, .what = what, .budget = budget};
  };
  const auto curve = [](const char* name, const char* key, const char* jackknife, const char* unit, const char* label,
                        Scene scene, double threshold, bool relative, double weight, const char* margin_key,
                        double margin) {
    return Observable{.name = name, .key = key, .sem = nullptr, .unit = unit, .label = label, .rule = Rule::curve,
                      .scenes = scene, .margin_key = margin_key, .margin = margin, .jackknife = jackknife,
                      .threshold = threshold, .relative_threshold = relative, .weight_exponent = weight};
  };
  // The kinetic temperature's row first: kinetic_temperature() is the table's first row.
  return {
      shift("temperature_mean", "temperature_sem", kEnergy, "T", "temperature", 0.005, B::kT),
      shift("temperature_std", "temperature_std_sem", kEnergy, "T fluctuation", "temperature_std", 0.02),
      shift("pressure_mean", "pressure_sem", kPressure, "P", "pressure", 0.005),
      shift("diffusion_coefficient", "diffusion_sem", "r_c²/τ", "D", "diffusion", 0.03),
      shift("pressure_xx", "pressure_xx_sem", kPressure, "P_xx", "pressure_components", 0.005),
      shift("pressure_yy", "pressure_yy_sem", kPressure, "P_yy", "pressure_components", 0.005),
      shift("pressure_zz", "pressure_zz_sem", kPressure, "P_zz", "pressure_components", 0.005),
      shift("temperature_conf_mean", "temperature_conf_sem", kEnergy, "T_conf", "temperature_conf", 0.005, B::kT),
      shift("temperature_x_mean", "temperature_x_sem", kEnergy, "T_x", "temperature_components", 0.01, B::kT),
      shift("temperature_y_mean", "temperature_y_sem", kEnergy, "T_y", "temperature_components", 0.01, B::kT),
      shift("temperature_z_mean", "temperature_z_sem", kEnergy, "T_z", "temperature_components", 0.01, B::kT),
      curve("vpdf_vs_mt", "vpdf/p", "vpdf/jackknife", "1/√(k_BT/m)", "v-PDF vs MT", kWater, 0.01, true, 0.5, "vpdf",
            0.05),
      curve("rdf_vs_mt", "rdf/g", "rdf/jackknife", "1", "g(r) vs MT", kWater, 0.1, false, 0.5, "rdf", 0.02),
      curve("msd_vs_mt", "msd/msd", "msd/jackknife", "r_c²", "MSD vs MT", kWater, 0.0, false, 1.0, "msd", 0.03),
      paired("temperature", "temperature_mean", "temperature_sem", kEnergy, "T", "kinetic temperature k_BT", B::kT),
      paired("temperature_x", "temperature_x_mean", "temperature_x_sem", kEnergy, "T_x",
             "kinetic temperature of the x components", B::kT),
      paired("temperature_y", "temperature_y_mean", "temperature_y_sem", kEnergy, "T_y",
             "kinetic temperature of the y components", B::kT),
      paired("temperature_z", "temperature_z_mean", "temperature_z_sem", kEnergy, "T_z",
             "kinetic temperature of the z components (normal to the membrane)", B::kT),
      paired("pressure_xx", "pressure_xx_mean", "pressure_xx_sem", kPressure, "P_xx", "pressure tensor P_xx"),
      paired("pressure_yy", "pressure_yy_mean", "pressure_yy_sem", kPressure, "P_yy", "pressure tensor P_yy"),
      paired("pressure_zz", "pressure_zz_mean", "pressure_zz_sem", kPressure, "P_zz",
             "pressure tensor P_zz (normal to the membrane)"),
      paired("pressure_xx_minus_yy", "pressure_xx_minus_yy_mean", "pressure_xx_minus_yy_sem", kPressure, "P_xx − P_yy",
             "in-plane anisotropy P_xx − P_yy (0 by symmetry about z)", B::zero),
      paired("tension", "tension_mean", "tension_sem", "k_BT/r_c²", "Σ", "tension L_z[P_zz − (P_xx+P_yy)/2]"),
      paired("thickness", "thickness_mean", "thickness_sem", "r_c", "thickness", "head-density peak to peak"),
      paired("tail_order", "tail_order_mean", "tail_order_sem", "1", "order", "tail order P2 against z"),
      curve("head_profile_vs_mt", "profile/head", nullptr, "r_c⁻³", "head profile", kBilayer, 0.1, true, 0.5, "", 0),
      curve("tail_profile_vs_mt", "profile/tail", nullptr, "r_c⁻³", "tail profile", kBilayer, 0.1, true, 0.5, "", 0),
      curve("water_profile_vs_mt", "profile/water", nullptr, "r_c⁻³", "water profile", kBilayer, 0.1, true, 0.5, "",
            0),
  };
}

std::vector<Observable> select(Rule rule, Scene scene) {
  std::vector<Observable> out;
  for (const auto& o : observables())
    if (o.rule == rule && (o.scenes & scene)) out.push_back(o);
  return out;
}

bool ends_with(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// The units of the numbers a cell stores besides the table's rows, by the start of their names (the longest
// listed start wins); a statistic of a quantity (_mean, _std, _sem, _se) has the quantity's unit.
struct UnitRule {
  const char* start;
  const char* unit;
};
constexpr UnitRule kUnitRules[] = {
    {"temperature", kEnergy},  {"pressure", kPressure},          {"tension", "k_BT/r_c²"},
    {"thickness", "r_c"},      {"head_separation", "r_c"},       {"box_z", "r_c"},
    {"diffusion", "r_c²/τ"},   {"momentum_drift", "√(m k_BT)"},  {"tail_order", "1"},
    {"order_by_bond", "1"},    {"zeta", "1"},                    {"vpdf_error_mb", "1"},
    {"chi2", "1"},             {"ttest", "1"},                   {"corr.", "1"},
    {"nist", "1"},             {"lipids_out", "1"},              {"steps_done", "1"},
    {"unstable_step", "1"},    {"seconds", "s"},                 {"cell.dt", "τ"},
    {"cost.ns_per_number", "ns"}, {"cost.bonded_seconds", "s"}, {"cost.step_seconds", "s"},    {"cost.run_seconds", "s"},
    {"cost.rng_share", "1"},   {"cost.particle_steps_per_second", "1/s"}, {"cost.numbers_per_step", "1"},
    {"series/step", "1"},      {"series/temperature", kEnergy},  {"series/tension", "k_BT/r_c²"},
    {"profile/z", "r_c"},      {"profile/", "r_c⁻³"},            {"rdf/r", "r_c"},
    {"rdf/", "1"},             {"msd/tau", "τ"},                 {"msd/", "r_c²"},
    {"vpdf/v", "√(k_BT/m)"},   {"vpdf/", "1/√(k_BT/m)"},
};

// Counts by the end of their names (tests' trials and passes, sample counts) or whole.
constexpr const char* kCountEnds[] = {".trials", ".passed", ".bins", ".steps", ".not_applicable", ".n", "_n"};
constexpr const char* kCounts[] = {"steps_done",   "lipids_out_max", "nist.bits",   "nist.columns",
                                   "nist.failed_columns", "nist.failed_columns_exact", "nist.sequences",
                                   "unstable_step", "series/step",  "nist/passed", "nist/passed_exact",
                                   "nist/applicable", "nist/ok",    "nist/ok_exact", "nist/histogram"};

}  // namespace observable_table

const std::vector<Observable>& observables() {
  static const std::vector<Observable> table = observable_table::make();
  return table;
}

const std::vector<Observable>& scalar_observables() {
  static const auto v = observable_table::select(Rule::shift, kWater);
  return v;
}
const std::vector<Observable>& curve_observables() {
  static const auto v = observable_table::select(Rule::curve, kWater);
  return v;
}
const std::vector<Observable>& bilayer_observables() {
  static const auto v = observable_table::select(Rule::paired, kBilayer);
  return v;
}
const std::vector<Observable>& bilayer_curves() {
  static const auto v = observable_table::select(Rule::curve, kBilayer);
  return v;
}

std::vector<Observable> budget_observables(Scene scene) {
  std::vector<Observable> out;
  for (const auto& o : observables())
    if (o.budget != BudgetTarget::none && (o.scenes & scene)) out.push_back(o);
  return out;
}

const Observable& kinetic_temperature() { return observables().front(); }

bool is_kinetic_temperature(std::string_view comparison) {
  const Observable& t = kinetic_temperature();
  for (const auto& o : observables())
    if (o.name == comparison && std::string_view(o.key) == t.key) return true;
  return false;
}

const Observable& observable_row(std::string_view name) {
  for (const auto& o : observables())
    if (o.name == name) return o;
  throw std::out_of_range("no observable " + std::string(name));
}

std::vector<MarginDefault> margin_defaults() {
  std::vector<MarginDefault> m;
  const auto add = [&](const char* key, double margin, const char* name) {
    for (const auto& d : m)
      if (d.key == key) return;  // observables that share a key share its margin
    m.push_back({key, margin, name});
  };
  for (const auto& s : scalar_observables()) add(s.margin_key, s.margin, s.name);
  for (const auto& c : curve_observables()) add(c.margin_key, c.margin, c.name);
  return m;
}

std::string observable_label(const std::string& name) {
  for (const auto& o : observables())
    if (name == o.name && o.rule != Rule::paired) return o.label;
  return name;
}

std::string unit_of(std::string_view key) {
  using namespace observable_table;
  for (const auto& o : observables())
    if (key == o.key || (o.sem && key == o.sem) || (o.jackknife && key == o.jackknife)) return o.unit;
  if (ends_with(key, "_dof") || ends_with(key, "_n")) return "1";
  const UnitRule* best = nullptr;
  for (const auto& r : kUnitRules)
    if (key.starts_with(r.start) && (!best || std::string_view(r.start).size() > std::string_view(best->start).size()))
      best = &r;
  return best ? best->unit : "";
}

bool is_count(std::string_view key) {
  using namespace observable_table;
  for (const char* c : kCounts)
    if (key == c) return true;
  for (const char* e : kCountEnds)
    if (ends_with(key, e)) return true;
  return false;
}

}  // namespace dpdrng::study
