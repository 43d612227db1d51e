#include "dpdrng/study/observables.hpp"

namespace dpdrng::study {

// Margins: the temperature and pressure to half a percent (a thermostat's error a DPD user notices; the paper's
// worst generators shift T by several percent), diffusion to 3 % (its run-to-run spread is over ten times T's),
// T's fluctuation to 2 %, each diagonal component of the pressure tensor to 0.5 % (isotropy: a noise whose
// variance depends on the pair's direction shifts them apart), the configurational temperature to 0.5 % (as T:
// the noise moves both, the integrator only the kinetic one), each kinetic temperature component to 1 % (a third
// of the degrees of freedom: √3 times the scalar's spread). Curves bin by bin: the velocity PDF to 5 % in
// every bin above 1 % of its peak (the tails' counting noise), g(r) to 2 % outside the core, the MSD to 3 % (as D).
const std::vector<ScalarSpec>& scalar_observables() {
  static const std::vector<ScalarSpec> s = {
      {"temperature_mean", "temperature_sem", "temperature", 0.005, "T"},
      {"temperature_std", "temperature_std_sem", "temperature_std", 0.02, "T fluctuation"},
      {"pressure_mean", "pressure_sem", "pressure", 0.005, "P"},
      {"diffusion_coefficient", "diffusion_sem", "diffusion", 0.03, "D"},
      {"pressure_xx", "pressure_xx_sem", "pressure_components", 0.005, "P_xx"},
      {"pressure_yy", "pressure_yy_sem", "pressure_components", 0.005, "P_yy"},
      {"pressure_zz", "pressure_zz_sem", "pressure_components", 0.005, "P_zz"},
      {"temperature_conf_mean", "temperature_conf_sem", "temperature_conf", 0.005, "T_conf"},
      {"temperature_x_mean", "temperature_x_sem", "temperature_components", 0.01, "T_x"},
      {"temperature_y_mean", "temperature_y_sem", "temperature_components", 0.01, "T_y"},
      {"temperature_z_mean", "temperature_z_sem", "temperature_components", 0.01, "T_z"},
  };
  return s;
}

// The velocity PDF's tails (below 1 % of its peak) and g(r) inside the core (below 0.1) are counting noise.
const std::vector<CurveSpec>& curve_observables() {
  static const std::vector<CurveSpec> c = {
      {"vpdf_vs_mt", "vpdf/p", "vpdf/jackknife", 0.01, true, 0.5, "vpdf", 0.05, "v-PDF vs MT"},
      {"rdf_vs_mt", "rdf/g", "rdf/jackknife", 0.1, false, 0.5, "rdf", 0.02, "g(r) vs MT"},
      {"msd_vs_mt", "msd/msd", "msd/jackknife", 0.0, false, 1.0, "msd", 0.03, "MSD vs MT"},
  };
  return c;
}

// Bins where the density is below a tenth of its peak (the empty core for water, the bulk water for tails) are
// left out.
const std::vector<CurveSpec>& bilayer_curves() {
  static const std::vector<CurveSpec> c = {
      {"head_profile_vs_mt", "profile/head", nullptr, 0.1, true, 0.5, "", 0, "head profile"},
      {"tail_profile_vs_mt", "profile/tail", nullptr, 0.1, true, 0.5, "", 0, "tail profile"},
      {"water_profile_vs_mt", "profile/water", nullptr, 0.1, true, 0.5, "", 0, "water profile"},
  };
  return c;
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
  for (const auto& s : scalar_observables())
    if (name == s.name) return s.label;
  for (const auto& c : curve_observables())
    if (name == c.name) return c.label;
  for (const auto& c : bilayer_curves())
    if (name == c.name) return c.label;
  return name;
}

}  // namespace dpdrng::study
