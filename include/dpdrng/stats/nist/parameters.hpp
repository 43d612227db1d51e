#pragma once
// The tunable parameters of the SP800-22 tests and their validity. A parameter outside its range is the caller's
// mistake, not a property of the data, so it is never reported as "not applicable": check_parameters() names it
// before any work, and a test function handed one throws std::invalid_argument with the same words.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dpdrng/stats/nist/result.hpp"

namespace dpdrng::stats::nist {

// Every tunable parameter, defaulting to the reference's (sts-2.1.2 assess.c) values.
struct Parameters {
  int block_frequency_M = 128;
  int non_overlapping_m = 9;
  int non_overlapping_blocks = 8;                    // N
  std::vector<std::uint32_t> non_overlapping_templates;  // empty = every aperiodic m-bit template
  int overlapping_m = 9;
  int overlapping_M = 1032;
  int overlapping_K = 5;
  int universal_L = 0;  // 0 = chosen from n as the reference does
  int universal_Q = 0;  // 0 = 10 * 2^L
  int approximate_entropy_m = 10;
  int serial_m = 16;
  int linear_complexity_M = 500;
};

// A bad parameter: `field` is the Parameters member, `value` its value, `reason` the rule in words.
struct ParameterProblem {
  std::string field;
  long long value = 0;
  std::string reason;
};

// Each test's rule; nullopt when the parameters are valid.
std::optional<ParameterProblem> check_block_frequency(int M);
std::optional<ParameterProblem> check_non_overlapping(int m, std::span<const std::uint32_t> templates, int blocks);
std::optional<ParameterProblem> check_overlapping(int m, int M, int K);
std::optional<ParameterProblem> check_universal(int L, int Q);
std::optional<ParameterProblem> check_approximate_entropy(int m);
std::optional<ParameterProblem> check_serial(int m);
std::optional<ParameterProblem> check_linear_complexity(int M);

// The rules of test t on the parameters it uses (tests without parameters: always valid). check_validity: where
// the test's mathematics holds (the check_* above; the test functions throw outside it). check_recommended: the
// ranges SP800-22 rev1a recommends in its "Input Size Recommendation" subsections (x.7), outside which the
// reference distribution is not the statistic's (a test that passes everything or fails everything); the test
// functions do not enforce these, so that the spec's small worked examples (x.8) still run. check_parameters:
// both, what the tool checks before it reads any input.
std::optional<ParameterProblem> check_validity(Test t, const Parameters& p);
std::optional<ParameterProblem> check_recommended(Test t, const Parameters& p);
std::optional<ParameterProblem> check_parameters(Test t, const Parameters& p);

// The length rules of SP800-22 rev1a's x.7 subsections that depend on n, the sequence length: the reason in words
// when n bits are too few for test t with these parameters, nullopt when the rule holds. A result
// that breaks one is "not applicable: <reason>" (run_test applies it).
struct LengthProblem {
  std::string reason;
  std::size_t min_bits = 0;  // the smallest n that satisfies the rule
};
std::optional<LengthProblem> check_length(Test t, const Parameters& p, std::size_t n);

// Whether an m-bit template is aperiodic: no proper prefix equals the suffix of the same length (SP800-22 rev1a
// 2.7: the non-overlapping test counts aperiodic templates; a periodic one's occurrences are not the Poisson-like
// counts its variance assumes).
bool is_aperiodic(std::uint32_t t, int m);
// The smallest of the overlapping test's K + 1 class probabilities for m, M (templates.cpp, beside the classes).
double min_overlapping_class(int m, int M, int K);

// Throws std::invalid_argument("<field> = <value>: <reason>") when there is a problem.
void require_valid(const std::optional<ParameterProblem>& problem);

}  // namespace dpdrng::stats::nist
