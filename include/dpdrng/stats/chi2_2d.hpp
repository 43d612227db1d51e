#pragma once
// χ² test of uniformity on the unit square, k × k equal cells: the joint distribution of the two uniforms that
// Box–Muller combines. Tests on one uniform at a time (χ², lag-1 t) cannot see a dependence between the two.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

struct Chi2Grid {
  std::size_t n = 0;  // pairs
  int bins = 0;       // k per axis
  double expected = 0;                  // n / k² per cell
  std::vector<std::uint64_t> counts;    // row-major, counts[i·k + j] for u1 in bin i, u2 in bin j
  double statistic = 0;                 // Σ (n_ij − N)² / N
  int dof = 0;                          // k² − 1
  double p_value = 1;                   // chi2_upper_tail (chi2.hpp)
  double alpha = 0.01;
  Verdict verdict = Verdict::not_applicable;
  std::string reason;
};

// u1[i], u2[i] in [0,1): throws InputError for different lengths, NaN, a value outside [0,1), k < 2 or alpha
// outside (0,1). Fewer than 5 expected per cell: not applicable with the reason.
Chi2Grid chi2_2d(std::span<const double> u1, std::span<const double> u2, int bins, double alpha = 0.01);

// How a stream of 64-bit words becomes pairs: the two 32-bit halves of each word (u1 = low·2^-32, u2 = high·2^-32,
// as Box–Muller takes a one-word block), or consecutive words (u1 from word 2i, u2 from word 2i + 1, 53 bits each;
// an odd last word is left out).
enum class WordPairing { halves, words };
WordPairing parse_word_pairing(std::string_view name);  // throws InputError
std::string_view to_string(WordPairing p);
void pair_words(std::span<const std::uint64_t> words, WordPairing how, std::vector<double>& u1,
                std::vector<double>& u2);

}  // namespace dpdrng::stats
