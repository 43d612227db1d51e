#pragma once
// The 15 tests of NIST SP800-22 rev1a as pure functions, with the reference suite's (sts-2.1.2) defaults.
//
// Where the reference code differs from the printed text, these follow the code, because its numbers are the
// ones everybody compares with; each such choice is named at the function and collected in
// docs/nist-conventions.md. P-values come from GSL (incomplete gamma, erfc, normal CDF).
// A parameter outside its rule (parameters.hpp) throws std::invalid_argument; a sequence too short for valid
// parameters gives "not applicable" with the bits needed.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "dpdrng/stats/nist/bitseq.hpp"
#include "dpdrng/stats/nist/parameters.hpp"
#include "dpdrng/stats/nist/result.hpp"

namespace dpdrng::stats::nist {

// 2.1  P = erfc(|S_n| / sqrt(2n)).
TestResult frequency(const BitSequence& s);

// 2.2  Blocks of M bits (the reference's default 128); the n mod M leftover bits are discarded.
TestResult block_frequency(const BitSequence& s, int M = 128);

// 2.13  Forward then reverse ("backward"). The summation bounds use C integer division of n by z, truncating
// toward zero, exactly as the reference writes (-n/z+1)/4 etc.; the printed floor() differs for some n.
TestResult cumulative_sums(const BitSequence& s);

// 2.3  When the frequency prerequisite |pi - 1/2| >= 2/sqrt(n) fails, the reference reports P = 0 (a failure,
// not "not applicable"), and so do we.
TestResult runs(const BitSequence& s);

// 2.4  M = 8, 128 or 10^4 chosen from n as the reference does (n < 6272, n < 750000, otherwise), with the
// reference's class probabilities (its 4-digit table for M = 10^4). Needs n >= 128.
TestResult longest_run(const BitSequence& s);

// 2.5  32x32 matrices, rows of 32 consecutive bits. Needs at least one matrix (1024 bits).
TestResult rank(const BitSequence& s);
// Rank over GF(2) of a 32x32 bit matrix, one row per word (what the test counts).
int binary_rank32(std::array<std::uint32_t, 32> rows);

// 2.6  Threshold sqrt(ln(1/0.05) n) (the reference's 2.995732274 n), N0 = 0.95 n/2, variance n 0.95 0.05 / 4,
// peaks counted among the first n/2 magnitudes including the DC term, as the reference does.
TestResult fft(const BitSequence& s);
// The moduli |X_0| .. |X_{n/2-1}| of the DFT of x_i = 2 s_i - 1 (what the test counts), into mag.
void dft_magnitudes(const BitSequence& s, std::vector<double>& mag);
// The test's N1 from a transform X of s (X_0 .. X_{n/2-1}, re and im interleaved): the moduli below T, where
// those within `band` of T are recomputed term by term (direct_modulus). While the transform's error stays under
// the band, the count is the same whatever plan, SIMD or library computed X.
std::size_t spectral_peaks_below(const BitSequence& s, const double* X, double T, double band);
// |X_k| of the DFT of x_i = 2 s_i - 1, k < n, summed term by term in long double: slow (a sine and a cosine a
// bit), and its roundings depend on n and k alone.
double direct_modulus(const BitSequence& s, std::size_t k);
// The band spectral_peaks_below is given for n bits: far above a double-precision FFT's error.
double spectral_band(std::size_t n);
// How the test transforms n bits: "FFTW wisdom (FFTW_PATIENT)" where the shipped plan applies, else
// "FFTW_ESTIMATE".
std::string fft_plan(std::size_t n);
// FFTW's wisdom for the test's transform of n bits, planned afresh with FFTW_PATIENT (about a minute at 2^20):
// the text shipped in src/stats/nist/fft_wisdom.cpp.
std::string fft_patient_wisdom(std::size_t n);

// The aperiodic (unbordered) m-bit templates in increasing numeric order, first bit most significant: the
// order of the reference's templates/template<m> files (148 templates for m = 9).
std::vector<std::uint32_t> aperiodic_templates(int m);

// 2.7  N = 8 blocks, every aperiodic m-bit template (or the given ones), one P-value per template.
TestResult non_overlapping_template(const BitSequence& s, int m = 9, std::span<const std::uint32_t> templates = {},
                                    int blocks = 8);

// 2.8  Template of m ones, blocks of M = 1032, K = 5 classes; class probabilities from the reference's Pr(u, eta)
// (the corrected formula of rev1a, not the hard-coded table it overwrites).
TestResult overlapping_template(const BitSequence& s, int m = 9, int M = 1032, int K = 5);

// 2.9  L and Q = 10 * 2^L chosen from n by the reference's table (L = 6 from n = 387840 on); L = 0 means "as the
// reference". The variance table and Coron's c(L, K) correction as in the reference.
TestResult universal(const BitSequence& s, int L = 0, int Q = 0);

// The counts of every m-bit pattern at the n start positions of s read circularly (1 <= m <= 24), which Serial
// (m) and Approximate Entropy (m + 1) are computed from. On a circle every k-bit window is the prefix of exactly
// one m-bit window, so one table of the larger m gives both tests their counts.
struct PatternCounts {
  int m = 0;
  std::vector<std::uint32_t> counts;  // [pattern], first bit most significant
};
PatternCounts pattern_counts(const BitSequence& s, int m);

// 2.12  Circular (wrap-around) counting of m- and (m+1)-bit blocks, chi^2 = 2n(ln 2 - ApEn). `counts`, when given,
// are s's pattern counts of at least m + 1 bits.
TestResult approximate_entropy(const BitSequence& s, int m = 10, const PatternCounts* counts = nullptr);

// 2.14  States -4..-1, 1..4; not applicable when the walk has fewer than max(500, 0.005 sqrt(n)) cycles.
TestResult random_excursions(const BitSequence& s);

// 2.15  States -9..-1, 1..9; same applicability rule.
TestResult random_excursions_variant(const BitSequence& s);

// 2.11  Circular counting, two P-values (del psi^2 and del^2 psi^2). `counts`, when given, are s's pattern counts
// of at least m bits.
TestResult serial(const BitSequence& s, int m = 16, const PatternCounts* counts = nullptr);

// 2.10  Blocks of M bits (default 500), Berlekamp-Massey per block, the reference's rounded class probabilities.
TestResult linear_complexity(const BitSequence& s, int M = 500);

// Linear complexity of bits [start, start+len) (Berlekamp-Massey over GF(2)), one block at a time.
int berlekamp_massey(const BitSequence& s, std::size_t start, std::size_t len);
// Linear complexities of the n/M consecutive M-bit blocks; 64 blocks at a time, bit-sliced (what the test uses).
std::vector<int> block_linear_complexities(const BitSequence& s, int M);

}  // namespace dpdrng::stats::nist
