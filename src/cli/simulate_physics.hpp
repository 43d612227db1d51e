#pragma once
// `dpdrng simulate`'s physics read-out beyond T and P: the configurational temperature, the per-component
// temperatures and pressures, the noise's effective power and correlation, and the comparison of a run with a
// reference generator at the same settings (--compare).
#include <nlohmann/json.hpp>
#include <string>

#include "dpdrng/dpd/result.hpp"

namespace dpdrng::cli {

// Human lines, with units.
std::string physics_lines(const dpd::RunResult& r);
// For a generator other than the reference: only a comparison at the same settings separates the errors.
std::string reference_note(const dpd::RunResult& r);
// Both runs' main observables side by side, with each shift variant − reference and its 95 % CI (independent
// runs: the standard errors add in quadrature).
std::string compare_lines(const dpd::RunResult& variant, const dpd::RunResult& reference);
nlohmann::json compare_shifts_json(const dpd::RunResult& variant, const dpd::RunResult& reference);

}  // namespace dpdrng::cli
