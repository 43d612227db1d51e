#pragma once
// The stability check the water and the bilayer runs share; internal to src/dpd.
#include <cmath>
#include <cstdint>
#include <sstream>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/result.hpp"

namespace dpdrng::dpd::detail {

// The first reason the state after `step` cannot go on as a simulation, or ok. Config: any scene's config with
// kT, rc, max_temperature and min_distance.
template <class Config>
RunStatus check_state(const Config& cfg, std::int64_t step, double T, const ForceSums& f) {
  std::ostringstream why;
  if (!std::isfinite(T) || !std::isfinite(f.virial[0] + f.virial[1] + f.virial[2]))
    return RunStatus::unstable(step, "non-finite velocities or forces");
  if (T > cfg.max_temperature * cfg.kT) {
    why << "temperature runaway (k_BT = " << T << " > " << cfg.max_temperature << " x " << cfg.kT << ")";
    return RunStatus::unstable(step, why.str());
  }
  // The pair loop starts min_r2 at r_c^2 and lowers it only for pairs inside r_c: r_c^2 itself means that no pair
  // was found, not that one sits at r_c.
  if (f.min_r2 < cfg.rc * cfg.rc && f.min_r2 < cfg.min_distance * cfg.min_distance) {
    why << "beads closer than " << cfg.min_distance << " (r = " << std::sqrt(f.min_r2) << ")";
    return RunStatus::unstable(step, why.str());
  }
  return {};
}

}  // namespace dpdrng::dpd::detail
