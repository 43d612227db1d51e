#include "dpdrng/stats/nist/parameters.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dpdrng/common/numbers.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {

namespace {

// ⌊log2 n⌋ for n >= 1.
int floor_log2(std::size_t n) { return n == 0 ? -1 : static_cast<int>(std::bit_width(n)) - 1; }

// The overlapping test's expected count of m-bit windows of ones per block, λ = (M - m + 1) / 2^m.
double overlap_lambda(int m, int M) { return static_cast<double>(M - m + 1) / std::ldexp(1.0, m); }

// A bit count computed in double (tiny class probabilities make it astronomical), held to what size_t holds.
std::size_t saturated_length(double bits) {
  constexpr double kLimit = 1.8e19;  // just below 2^64
  return bits >= 0 && bits < kLimit ? static_cast<std::size_t>(bits) : std::numeric_limits<std::size_t>::max();
}

}  // namespace

bool is_aperiodic(std::uint32_t t, int m) {
  for (int k = 1; k < m; ++k) {
    const std::uint32_t mask = (std::uint32_t{1} << k) - 1;
    if ((t >> (m - k)) == (t & mask)) return false;  // the first k bits equal the last k bits
  }
  return true;
}

std::optional<ParameterProblem> check_recommended(Test t, const Parameters& p) {
  switch (t) {
    case Test::BlockFrequency:
      if (p.block_frequency_M < 20)
        return ParameterProblem{"block_frequency_M", p.block_frequency_M,
                                "must be at least 20 (SP800-22 rev1a 2.2.7: M >= 20)"};
      return std::nullopt;
    case Test::NonOverlappingTemplate:
      for (const std::uint32_t tpl : p.non_overlapping_templates)
        if (!is_aperiodic(tpl, p.non_overlapping_m))
          return ParameterProblem{"non_overlapping_templates", tpl,
                                  "is periodic (a prefix equals its suffix): SP800-22 rev1a 2.7 counts aperiodic "
                                  "templates only"};
      return std::nullopt;
    case Test::OverlappingTemplate: {
      if (p.overlapping_m != 9 && p.overlapping_m != 10)
        return ParameterProblem{"overlapping_m", p.overlapping_m,
                                "must be 9 or 10 (SP800-22 rev1a 2.8.7: \"NIST recommends m = 9 or m = 10\")"};
      const double lambda = overlap_lambda(p.overlapping_m, p.overlapping_M);
      // λ ≈ 2 is the spec's wording; about a factor of two either way is allowed (m = 10 at the reference's
      // M = 1032 gives λ = 0.999).
      if (!(lambda >= 0.9 && lambda <= 4.0))
        return ParameterProblem{"overlapping_M", p.overlapping_M,
                                "gives lambda = (M - m + 1) / 2^m = " + format_g(lambda) +
                                    ", outside 0.9..4 (SP800-22 rev1a 2.8.7: lambda ~ 2)"};
      return std::nullopt;
    }
    case Test::LinearComplexity:
      if (p.linear_complexity_M < 500 || p.linear_complexity_M > 5000)
        return ParameterProblem{"linear_complexity_M", p.linear_complexity_M,
                                "must be within 500..5000 (SP800-22 rev1a 2.10.7: 500 <= M <= 5000)"};
      return std::nullopt;
    default: return std::nullopt;
  }
}

std::optional<LengthProblem> check_length(Test t, const Parameters& p, std::size_t n) {
  const int lg = floor_log2(n);
  switch (t) {
    case Test::ApproximateEntropy:
      if (p.approximate_entropy_m >= lg - 5)
        return LengthProblem{"m = " + std::to_string(p.approximate_entropy_m) + " needs m < floor(log2 n) - 5 = " +
                                 std::to_string(lg - 5) + " (SP800-22 rev1a 2.12.7)",
                             std::size_t{1} << std::min(p.approximate_entropy_m + 6, 62)};
      return std::nullopt;
    case Test::Serial:
      if (p.serial_m >= lg - 2)
        return LengthProblem{"m = " + std::to_string(p.serial_m) + " needs m < floor(log2 n) - 2 = " +
                                 std::to_string(lg - 2) + " (SP800-22 rev1a 2.11.7)",
                             std::size_t{1} << std::min(p.serial_m + 3, 62)};
      return std::nullopt;
    case Test::OverlappingTemplate: {
      // N * min(pi_i) > 5 (SP800-22 rev1a 2.8.7), with the class probabilities of these parameters.
      const std::size_t N = n / static_cast<std::size_t>(p.overlapping_M);
      const double min_pi = min_overlapping_class(p.overlapping_m, p.overlapping_M, p.overlapping_K);
      if (!(static_cast<double>(N) * min_pi > 5))
        return LengthProblem{"N = " + std::to_string(N) + " blocks of M bits give N * min(pi_i) = " +
                                 format_g(static_cast<double>(N) * min_pi) +
                                 ", not above 5 (SP800-22 rev1a 2.8.7)",
                             saturated_length((std::floor(5 / min_pi) + 1) * double(p.overlapping_M))};
      return std::nullopt;
    }
    case Test::LinearComplexity: {
      const std::size_t N = n / static_cast<std::size_t>(p.linear_complexity_M);
      if (N < 200)
        return LengthProblem{"N = " + std::to_string(N) +
                                 " blocks of M bits, fewer than 200 (SP800-22 rev1a 2.10.7: N >= 200)",
                             200 * static_cast<std::size_t>(p.linear_complexity_M)};
      return std::nullopt;
    }
    default: return std::nullopt;
  }
}

std::optional<ParameterProblem> check_parameters(Test t, const Parameters& p) {
  if (auto problem = check_validity(t, p)) return problem;
  return check_recommended(t, p);
}

std::optional<ParameterProblem> check_validity(Test t, const Parameters& p) {
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
