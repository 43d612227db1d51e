// The fast inner parts of the SP800-22 tests against slow references: the spectral test's DFT moduli against GSL's
// mixed-radix real FFT and a direct O(n^2) DFT, the non-overlapping template counts against the scan written out in
// SP800-22 2.7.4, and the matrix rank against textbook elimination with row swaps (SP800-22 Appendix F.1).
#include <gsl/gsl_fft_real.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng_test::stats_nist_test_nist_internals {

using namespace dpdrng::stats::nist;

namespace {

BitSequence random_bits(std::size_t n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<std::uint8_t> bits(n);
  for (auto& b : bits) b = static_cast<std::uint8_t>(g() >> 63);
  return BitSequence::from_bits(bits);
}

// X_k, k < n/2, re and im interleaved, from GSL's mixed-radix real transform (FFTPACK's halfcomplex layout
// r0 r1 i1 r2 i2 ...).
std::vector<double> gsl_transform(const BitSequence& s) {
  const std::size_t n = s.size();
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = s[i] ? 1.0 : -1.0;
  gsl_fft_real_wavetable* table = gsl_fft_real_wavetable_alloc(n);
  gsl_fft_real_workspace* work = gsl_fft_real_workspace_alloc(n);
  const int status = gsl_fft_real_transform(x.data(), 1, n, table, work);
  gsl_fft_real_workspace_free(work);
  gsl_fft_real_wavetable_free(table);
  EXPECT_EQ(status, 0);
  std::vector<double> X(2 * (n / 2), 0.0);
  if (!X.empty()) X[0] = x[0];
  for (std::size_t k = 1; k < n / 2; ++k) X[2 * k] = x[2 * k - 1], X[2 * k + 1] = x[2 * k];
  return X;
}

std::vector<double> gsl_magnitudes(const BitSequence& s) {
  const std::vector<double> X = gsl_transform(s);
  std::vector<double> mag(X.size() / 2);
  for (std::size_t k = 0; k < mag.size(); ++k) mag[k] = std::hypot(X[2 * k], X[2 * k + 1]);
  return mag;
}

// |X_k|, k < n/2, summed term by term (direct_modulus, itself checked against GSL below).
std::vector<double> direct_magnitudes(const BitSequence& s) {
  std::vector<double> mag(s.size() / 2);
  for (std::size_t k = 0; k < mag.size(); ++k) mag[k] = direct_modulus(s, k);
  return mag;
}

// Parseval: the moduli have RMS sqrt(n), the scale of the transform's rounding.
void expect_same_magnitudes(const std::vector<double>& got, const std::vector<double>& want, std::size_t n) {
  ASSERT_EQ(got.size(), want.size()) << "n=" << n;
  const double tol = 1e-9 * std::sqrt(static_cast<double>(n));
  for (std::size_t k = 0; k < want.size(); ++k) ASSERT_NEAR(got[k], want[k], tol) << "n=" << n << " k=" << k;
}

TEST(FftInternals, MagnitudesAgreeWithGslMixedRadix) {
  // Powers of two, even and odd lengths with small factors, a prime, and SP800-22 Appendix B's 10^6.
  for (std::size_t n : {std::size_t{1} << 16, std::size_t{1} << 20, std::size_t{1000000}, std::size_t{19683},
                        std::size_t{78125}, std::size_t{10007}, std::size_t{48}}) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(n));
    std::vector<double> mag;
    dft_magnitudes(s, mag);
    expect_same_magnitudes(mag, gsl_magnitudes(s), n);
  }
}

TEST(FftInternals, MagnitudesAgreeWithADirectDft) {
  for (std::size_t n = 2; n <= 70; ++n) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(1000 + n));
    std::vector<double> mag;
    dft_magnitudes(s, mag);
    expect_same_magnitudes(mag, direct_magnitudes(s), n);
  }
}

TEST(FftInternals, TheDirectModulusAgreesWithGsl) {
  for (std::size_t n : {std::size_t{4096}, std::size_t{1000}, std::size_t{3}}) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(2000 + n));
    const std::vector<double> want = gsl_magnitudes(s);
    for (std::size_t k = 0; k < want.size(); k += 1 + want.size() / 40)
      EXPECT_NEAR(direct_modulus(s, k), want[k], 1e-9 * std::sqrt(static_cast<double>(n))) << "n=" << n << " k=" << k;
  }
  EXPECT_THROW(direct_modulus(random_bits(8, 1), 8), std::invalid_argument);
}

// A transform off by less than the band gives the count of the exact moduli: here GSL's transform with the modulus
// nearest the threshold pushed to the other side of it, by as much as it lay from it.
TEST(FftInternals, ModuliInsideTheBandAreCountedOnTheDirectSum) {
  const std::size_t n = 4096;
  const BitSequence s = random_bits(n, 77);
  std::vector<double> X = gsl_transform(s);
  const std::vector<double> mag = gsl_magnitudes(s);
  const double T = std::sqrt(2.995732274 * static_cast<double>(n));
  std::size_t nearest = 0, truth = 0;
  for (std::size_t k = 0; k < mag.size(); ++k) {
    truth += mag[k] < T;
    if (std::fabs(mag[k] - T) < std::fabs(mag[nearest] - T)) nearest = k;
  }
  const double gap = std::fabs(mag[nearest] - T);
  ASSERT_GT(gap, 0.0);
  const double scale = (2 * T - mag[nearest]) / mag[nearest];
  X[2 * nearest] *= scale, X[2 * nearest + 1] *= scale;
  EXPECT_EQ(spectral_peaks_below(s, X.data(), T, 2 * gap), truth);
  // Without a band the pushed modulus is counted where the transform put it.
  const std::size_t moved = mag[nearest] < T ? truth - 1 : truth + 1;
  EXPECT_EQ(spectral_peaks_below(s, X.data(), T, 0.0), moved);
  // At 2^20 bits the band is a hundred times the bound on a double-precision FFT's error (c = 5 in Higham's).
  EXPECT_NEAR(spectral_band(std::size_t{1} << 20) / (5 * 20 * 0x1p-53 * 0x1p20), 100.0, 5.0);
}

// The test compares squared moduli with the smallest square whose root reaches the threshold: the same count as
// the moduli against the threshold (SP800-22 2.6, N1).
TEST(FftInternals, PeakCountIsTheModuliBelowTheThreshold) {
  for (std::size_t n : {std::size_t{1} << 16, std::size_t{100003}, std::size_t{1000}}) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(n + 1));
    std::vector<double> mag;
    dft_magnitudes(s, mag);
    const double T = std::sqrt(2.995732274 * static_cast<double>(n));
    double below = 0;
    for (double m : mag) below += m < T;
    EXPECT_EQ(fft(s).parameters[2].second, below) << "n=" << n;
  }
}

// Serial and Approximate Entropy read the battery's one table of pattern counts where both run: the same results
// as each test counting its own patterns, and the larger table's prefix sums are its counts.
TEST(PatternCountsInternals, TheSharedTableGivesEachTestItsOwnCounts) {
  // Lengths where SP800-22's rules admit both tests at their defaults (m = 16 needs n >= 2^19).
  for (std::size_t n : {std::size_t{1} << 20, std::size_t{(1 << 19) + 12345}}) {
    const BitSequence s = random_bits(n, static_cast<unsigned>(3000 + n));
    using T = dpdrng::stats::nist::Test;
    const std::vector<T> both = {T::Serial, T::ApproximateEntropy};
    const std::vector<TestResult> got = run_battery(s, Parameters{}, both);
    const TestResult alone[2] = {serial(s), approximate_entropy(s)};
    for (int t = 0; t < 2; ++t) {
      ASSERT_EQ(got[t].values.size(), alone[t].values.size());
      for (std::size_t v = 0; v < alone[t].values.size(); ++v) {
        EXPECT_EQ(got[t].values[v].statistic, alone[t].values[v].statistic) << "n=" << n;
        EXPECT_EQ(got[t].values[v].p, alone[t].values[v].p) << "n=" << n;
      }
    }
    const PatternCounts c16 = pattern_counts(s, 16), c11 = pattern_counts(s, 11);
    const TestResult from16 = approximate_entropy(s, 10, &c16);
    EXPECT_EQ(from16.values[0].p, approximate_entropy(s, 10, &c11).values[0].p);
    EXPECT_EQ(from16.values[0].p, alone[1].values[0].p);
    EXPECT_THROW(serial(s, 16, &c11), std::invalid_argument);
  }
}

// The battery on many sequences gives every sequence the same results on one thread as on several.
TEST(BatteryInternals, TheThreadCountChangesNoResult) {
  std::vector<BitSequence> seqs;
  for (unsigned k = 0; k < 6; ++k) seqs.push_back(random_bits(std::size_t{1} << 14, 4000 + k));
  const auto one = run_battery(seqs, Parameters{}, {}, 1), two = run_battery(seqs, Parameters{}, {}, 2);
  ASSERT_EQ(one.size(), seqs.size());
  ASSERT_EQ(two.size(), seqs.size());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < seqs.size(); ++i) {
    ASSERT_EQ(one[i].size(), two[i].size());
    for (std::size_t t = 0; t < one[i].size(); ++t)
      for (std::size_t v = 0; v < one[i][t].values.size(); ++v) {
        const double a = one[i][t].values[v].p, b = two[i][t].values[v].p;
        EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << "sequence " << i << " test " << t;
        compared += !std::isnan(a);
      }
  }
  EXPECT_GT(compared, 100u);
}

// SP800-22 2.7.4: slide a window over the block; on a match count it and move on m bits, otherwise one bit.
std::size_t scan_count(const BitSequence& s, std::size_t start, std::size_t M, std::uint32_t t, int m) {
  std::size_t count = 0;
  for (std::size_t j = 0; j + m <= M;) {
    if (s.bits_at(start + j, static_cast<unsigned>(m)) == t) {
      ++count;
      j += static_cast<std::size_t>(m);
    } else {
      ++j;
    }
  }
  return count;
}

// One block: chi^2 = ((W - lambda) / sigma)^2, computed as the test does, from the scan's count W.
TEST(NonOverlappingTemplateInternals, OneBlockCountsMatchTheSpecScan) {
  for (int m : {2, 3, 4, 9, 10}) {
    const BitSequence s = random_bits(50000 + static_cast<std::size_t>(m), static_cast<unsigned>(m));
    const std::size_t M = s.size();
    const auto templates = aperiodic_templates(m);
    const TestResult r = non_overlapping_template(s, m, templates, 1);
    const double lambda = (M - m + 1) / std::pow(2, m);
    const double varW = M * (1.0 / std::pow(2.0, m) - (2.0 * m - 1.0) / std::pow(2.0, 2.0 * m));
    for (std::size_t t = 0; t < templates.size(); ++t) {
      const double W = static_cast<double>(scan_count(s, 0, M, templates[t], m));
      EXPECT_DOUBLE_EQ(r.values[t].statistic, std::pow((W - lambda) / std::sqrt(varW), 2))
          << "m=" << m << " template " << r.values[t].variant;
    }
  }
}

// Distinct unbordered templates are counted from a histogram of window values; a bordered template in the list
// (all zeros) forces the restarting scan for every template, a repeated one the most general scan. All three
// must give the same statistic for the templates they share, block by block.
TEST(NonOverlappingTemplateInternals, HistogramAgreesWithTheRestartingScans) {
  for (int m : {2, 3, 5, 9, 10}) {
    for (int blocks : {1, 8, 13}) {
      const BitSequence s = random_bits(100003, static_cast<unsigned>(m * 100 + blocks));
      const auto unbordered = aperiodic_templates(m);
      auto with_bordered = unbordered;
      with_bordered.push_back(0);
      auto with_repeat = unbordered;
      with_repeat.push_back(unbordered.front());
      const TestResult fast = non_overlapping_template(s, m, unbordered, blocks);
      const TestResult restarting = non_overlapping_template(s, m, with_bordered, blocks);
      const TestResult general = non_overlapping_template(s, m, with_repeat, blocks);
      for (std::size_t t = 0; t < unbordered.size(); ++t) {
        ASSERT_EQ(fast.values[t].statistic, restarting.values[t].statistic) << "m=" << m << " blocks=" << blocks;
        ASSERT_EQ(fast.values[t].statistic, general.values[t].statistic) << "m=" << m << " blocks=" << blocks;
      }
    }
  }
}

// A bordered template's matches can overlap, and the restart then skips some: 11 in 111 counts once.
TEST(NonOverlappingTemplateInternals, BorderedTemplateRestartsAfterAMatch) {
  const BitSequence s = BitSequence::from_ascii("0111011110");
  EXPECT_EQ(scan_count(s, 0, s.size(), 0b11, 2), 3u);
  const std::uint32_t t[] = {0b11, 0b01};
  const TestResult r = non_overlapping_template(s, 2, t, 1);
  const double lambda = 9 / 4.0, varW = 10 * (1 / 4.0 - 3 / 16.0);
  EXPECT_DOUBLE_EQ(r.values[0].statistic, std::pow((3 - lambda) / std::sqrt(varW), 2));
  EXPECT_DOUBLE_EQ(r.values[1].statistic, std::pow((2 - lambda) / std::sqrt(varW), 2));
}

// SP800-22 Appendix F.1's forward elimination: for each column, swap a row holding it into place, clear it below.
int rank_with_swaps(std::array<std::uint32_t, 32> rows) {
  int rank = 0;
  for (int col = 31; col >= 0 && rank < 32; --col) {
    const std::uint32_t bit = std::uint32_t{1} << col;
    int pivot = rank;
    while (pivot < 32 && !(rows[pivot] & bit)) ++pivot;
    if (pivot == 32) continue;
    std::swap(rows[rank], rows[pivot]);
    for (int i = rank + 1; i < 32; ++i)
      if (rows[i] & bit) rows[i] ^= rows[rank];
    ++rank;
  }
  return rank;
}

// Random matrices (ranks 32, 31, 30 mostly) and products of a 32 x r and an r x 32 matrix (rank at most r).
TEST(RankInternals, AgreesWithEliminationWithSwaps) {
  std::mt19937_64 g(7);
  std::array<int, 33> seen{};
  for (int trial = 0; trial < 4000; ++trial) {
    const int r = trial % 33;
    std::array<std::uint32_t, 32> rows{};
    if (trial % 2 == 0) {
      for (auto& row : rows) row = static_cast<std::uint32_t>(g());
    } else {
      std::array<std::uint32_t, 32> basis{};
      for (int k = 0; k < r; ++k) basis[k] = static_cast<std::uint32_t>(g());
      for (auto& row : rows) {
        const std::uint64_t pick = g();
        for (int k = 0; k < r; ++k)
          if ((pick >> k) & 1) row ^= basis[k];
      }
    }
    const int want = rank_with_swaps(rows);
    ASSERT_EQ(binary_rank32(rows), want) << "trial " << trial;
    ++seen[want];
  }
  // The products reach every rank from 0 to 32.
  for (int r = 0; r <= 32; ++r) EXPECT_GT(seen[r], 0) << "rank " << r;
}

}  // namespace

}  // namespace dpdrng_test::stats_nist_test_nist_internals
