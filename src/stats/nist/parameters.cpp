#include "dpdrng/stats/nist/parameters.hpp"

#include <stdexcept>

#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {

std::optional<ParameterProblem> check_parameters(Test t, const Parameters& p) {
  switch (t) {
    case Test::BlockFrequency: return check_block_frequency(p.block_frequency_M);
    case Test::NonOverlappingTemplate:
      return check_non_overlapping(p.non_overlapping_m, p.non_overlapping_templates, p.non_overlapping_blocks);
    case Test::OverlappingTemplate: return check_overlapping(p.overlapping_m, p.overlapping_M, p.overlapping_K);
    case Test::Universal: return check_universal(p.universal_L, p.universal_Q);
    case Test::ApproximateEntropy: return check_approximate_entropy(p.approximate_entropy_m);
    case Test::Serial: return check_serial(p.serial_m);
    case Test::LinearComplexity: return check_linear_complexity(p.linear_complexity_M);
    default: return std::nullopt;
  }
}

void require_valid(const std::optional<ParameterProblem>& problem) {
  if (problem)
    throw std::invalid_argument(problem->field + " = " + std::to_string(problem->value) + ": " + problem->reason);
}

}  // namespace dpdrng::stats::nist
