// Regressions for what fuzzing found (fuzz/fuzz_nist; its input is kept in fuzz/corpus/nist/finding-*) and for what
// the sweep below found beside it: every P-value the battery reports as applicable lies in [0, 1], on any short
// input.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng_test::stats_nist_test_nist_fuzz_findings {

using namespace dpdrng::stats::nist;

namespace {

BitSequence constant(std::size_t n, bool one) { return BitSequence::from_bits(std::vector<std::uint8_t>(n, one)); }

}  // namespace

// Runs on a constant sequence of at most 16 bits passes the frequency prerequisite (|pi - 1/2| = 1/2 is not
// above 2/sqrt(n)) and divides by pi(1 - pi) = 0: erfc(inf) came out NaN. The reference's cephes_erfc gives 0.
TEST(NistFuzzFindings, RunsOnAShortConstantSequenceIsZeroNotNaN) {
  for (std::size_t n = 2; n <= 16; ++n)
    for (const bool one : {false, true}) {
      const TestResult r = runs(constant(n, one));
      ASSERT_TRUE(r.applicable) << n;
      EXPECT_EQ(r.p(), 0.0) << n << (one ? " ones" : " zeros");
    }
}

// z = 1 (every partial sum within +-1, e.g. 0101...): the reference's sums give P up to 1.10 for n <= 52; every
// non-empty walk reaches |S| = 1, so the exact P-value is 1. From n = 53 on the sums agree with 1.
TEST(NistFuzzFindings, CumulativeSumsOfAWalkWithinOneIsOne) {
  for (std::size_t n = 2; n <= 60; n += 2) {
    std::vector<std::uint8_t> alternating(n);
    for (std::size_t i = 0; i < n; ++i) alternating[i] = i % 2;
    const TestResult r = cumulative_sums(BitSequence::from_bits(alternating));
    EXPECT_EQ(r.values[0].statistic, 1.0) << n;
    EXPECT_EQ(r.p(0), 1.0) << n;
  }
}

// fuzz_nist, after the fix above: 928 bits whose walk stays within +-5 gave P = 1 + 2^-52 (GSL's normal CDF
// rounds the truncated sums just past 1). Walks of saw teeth z up and z down, for every length near it.
TEST(NistFuzzFindings, CumulativeSumsNeverRoundsPastOne) {
  for (int z = 2; z <= 8; ++z)
    for (std::size_t n = 2 * z; n <= 1200; ++n) {
      std::vector<std::uint8_t> saw(n);
      for (std::size_t i = 0; i < n; ++i) saw[i] = (i / z) % 2 == 0;
      const TestResult r = cumulative_sums(BitSequence::from_bits(saw));
      for (const auto& v : r.values) ASSERT_TRUE(v.p >= 0.0 && v.p <= 1.0) << "z " << z << " n " << n << ": " << v.p;
    }
}

TEST(NistFuzzFindings, EveryApplicablePValueOfShortInputsIsAProbability) {
  for (std::size_t n = 1; n <= 200; ++n) {
    std::vector<std::uint8_t> alternating(n), thirds(n);
    for (std::size_t i = 0; i < n; ++i) alternating[i] = i % 2, thirds[i] = i % 3 == 0;
    for (const BitSequence& s : {constant(n, false), constant(n, true), BitSequence::from_bits(alternating),
                                 BitSequence::from_bits(thirds)})
      for (const TestResult& r : run_battery(s)) {
        if (!r.applicable) continue;
        for (const auto& v : r.values)
          EXPECT_TRUE(v.p >= 0.0 && v.p <= 1.0) << test_name(r.test) << " " << v.variant << " n = " << n << ": " << v.p;
      }
  }
}

}  // namespace dpdrng_test::stats_nist_test_nist_fuzz_findings
