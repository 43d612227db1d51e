// The bit-sequence type and readers, "not applicable" instead of bogus P-values, known-bad inputs that must
// fail, a good generator that must pass at the rate alpha predicts, and the second-level assessment.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdio>
#include <sstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/bitstream.hpp"
#include "dpdrng/stats/nist/tests.hpp"
#include "nist_test_util.hpp"

namespace dpdrng_test::stats_nist_test_nist_inputs {

using namespace dpdrng::stats::nist;

namespace {

TEST(NistBitSequence, FromWordsLeIsTheFileReadInRawMode) {
  const std::uint64_t words[] = {0x0123456789abcdefull, 0xfedcba9876543210ull};
  std::uint8_t bytes[16];
  for (int w = 0; w < 2; ++w)
    for (int b = 0; b < 8; ++b) bytes[8 * w + b] = static_cast<std::uint8_t>(words[w] >> (8 * b));  // little endian
  const BitSequence a = BitSequence::from_words_le(words);
  const BitSequence b = BitSequence::from_bytes(bytes);
  ASSERT_EQ(a.size(), 128u);
  for (std::size_t i = 0; i < 128; ++i) EXPECT_EQ(a[i], b[i]) << i;
  // First byte in the file is 0xef: bits 1110 1111, most significant first.
  EXPECT_EQ(a.bits_at(0, 8), 0xefu);
}

TEST(NistBitSequence, AsciiSkipsEverythingButZeroAndOne) {
  const BitSequence s = BitSequence::from_ascii("1 0\n1x1\t0,2");
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s.bits_at(0, 5), 0b10110u);
}

TEST(NistBitSequence, SliceWrapAndCounts) {
  std::vector<std::uint8_t> v(200);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = (i * 7 + i / 3) % 2;
  const BitSequence s = BitSequence::from_bits(v);
  const BitSequence t = s.slice(13, 150);
  for (std::size_t i = 0; i < 150; ++i) ASSERT_EQ(t[i], v[13 + i] != 0);
  const BitSequence w = s.wrapped(70);
  for (std::size_t i = 0; i < 270; ++i) ASSERT_EQ(w[i], v[i % 200] != 0);
  std::size_t ones = 0;
  for (std::size_t i = 5; i < 5 + 131; ++i) ones += v[i];
  EXPECT_EQ(s.count_ones(5, 131), ones);
}

TEST(NistBitStream, ReadsAsciiAndRawAndSplitsStreams) {
  std::istringstream ascii("0101 1111\n0000");
  const BitSequence a = read_bits(ascii, BitFormat::ascii);
  EXPECT_EQ(a.size(), 12u);
  std::istringstream raw(std::string("\xa5\x0f", 2));
  const BitSequence r = read_bits(raw, BitFormat::raw);
  ASSERT_EQ(r.size(), 16u);
  EXPECT_EQ(r.bits_at(0, 16), 0xa50fu);
  const auto parts = split_streams(r, 2, 8);
  EXPECT_EQ(parts[1].bits_at(0, 8), 0x0fu);
  EXPECT_THROW(split_streams(r, 3, 8), dpdrng::InputError);
}

TEST(NistApplicability, ShortInputIsNotApplicableWithTheMinimumSize) {
  const BitSequence s = BitSequence::from_ascii("0110101101");
  const TestResult lr = longest_run(s);
  EXPECT_FALSE(lr.applicable);
  EXPECT_EQ(lr.min_bits, 128u);
  EXPECT_TRUE(std::isnan(lr.p()));
  EXPECT_EQ(rank(s).min_bits, 1024u);
  EXPECT_EQ(universal(s).min_bits, 387840u);
  EXPECT_FALSE(linear_complexity(s).applicable);
  EXPECT_FALSE(overlapping_template(s).applicable);
  // 2.14.4 / 2.15.4: J = 3 cycles, the reference refuses (and so do we), every state reported n/a.
  const TestResult re = random_excursions(s);
  EXPECT_FALSE(re.applicable);
  EXPECT_EQ(re.values.size(), 8u);
  EXPECT_NE(re.reason.find("cycles"), std::string::npos);
  EXPECT_EQ(random_excursions_variant(s).values.size(), 18u);
  // The battery goes on: the cheap tests still give P-values.
  const auto all = run_battery(s);
  EXPECT_EQ(all.size(), 15u);
  EXPECT_TRUE(all[0].applicable);
  EXPECT_NEAR(all[0].p(), 0.527089, 1e-6);  // 2.1.4's sequence differs; this one has S = 2 as well
}

std::size_t bits_for_scale() { return testing_::small_scale() ? (std::size_t{1} << 18) : (std::size_t{1} << 20); }

// How many P-values of the battery fall below 1e-4: a random sequence gives about 0.02 of 188.
int strong_failures(const BitSequence& s) {
  int count = 0;
  for (const auto& r : run_battery(s))
    for (const auto& v : r.values) count += r.applicable && v.p < 1e-4;
  return count;
}

TEST(NistKnownBad, AllZerosFails) {
  const BitSequence s(bits_for_scale());
  EXPECT_LT(frequency(s).p(), 1e-10);
  EXPECT_GE(strong_failures(s), 10);
}

TEST(NistKnownBad, AlternatingBitsFail) {
  std::vector<std::uint64_t> w(bits_for_scale() / 64, 0xaaaaaaaaaaaaaaaaull);
  const BitSequence s = BitSequence::from_words_le(w);
  EXPECT_NEAR(frequency(s).p(), 1.0, 1e-12);  // perfectly balanced
  EXPECT_LT(runs(s).p(), 1e-10);              // but far too many runs
  EXPECT_GE(strong_failures(s), 10);
}

TEST(NistKnownBad, CounterFails) {
  std::vector<std::uint64_t> w(bits_for_scale() / 64);
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = i;
  EXPECT_GE(strong_failures(BitSequence::from_words_le(w)), 10);
}

TEST(NistKnownBad, RanduFails) {
  // RANDU, x <- 65539 x mod 2^31 from x = 1, each output written as a 32-bit little-endian word.
  std::vector<std::uint64_t> w(bits_for_scale() / 64);
  std::uint32_t x = 1;
  for (auto& word : w) {
    x = static_cast<std::uint32_t>((65539ull * x) & 0x7fffffffu);
    const std::uint64_t lo = x;
    x = static_cast<std::uint32_t>((65539ull * x) & 0x7fffffffu);
    word = lo | (std::uint64_t{x} << 32);
  }
  EXPECT_GE(strong_failures(BitSequence::from_words_le(w)), 5);
}

std::vector<BitSequence> good_sequences(int k, std::size_t bits) {
  dpdrng::rng::GeneratorSpec spec;
  spec.name = "philox4x32";
  spec = dpdrng::rng::validated(spec);
  std::vector<BitSequence> out;
  std::vector<std::uint64_t> buf(bits / 64);
  for (int i = 0; i < k; ++i) {
    dpdrng::rng::fill_stream(spec, 12345, static_cast<std::uint64_t>(i) * buf.size(), buf);
    out.push_back(BitSequence::from_words_le(buf));
  }
  return out;
}

TEST(NistGoodGenerator, PassRateMatchesAlphaWithFixedSeeds) {
  const int k = testing_::small_scale() ? 4 : 16;
  const auto seqs = good_sequences(k, bits_for_scale());
  const auto results = run_battery(seqs);
  int total = 0, below = 0;
  for (const auto& per_seq : results)
    for (const auto& r : per_seq)
      for (const auto& v : r.values)
        if (r.applicable) ++total, below += v.p < 0.01;
  // Binomial(total, 0.01) within 5 standard deviations (the seeds are fixed: this is deterministic).
  const double mean = 0.01 * total, sd = std::sqrt(total * 0.01 * 0.99);
  EXPECT_NEAR(below, mean, 5 * sd) << below << " of " << total << " P-values below 0.01";
  EXPECT_EQ(strong_failures(seqs[0]), 0);
}

TEST(NistBattery, ResultsDoNotDependOnTheThreadCount) {
  const auto seqs = good_sequences(4, std::size_t{1} << 16);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = run_battery(seqs);
  omp_set_num_threads(2);
  const auto two = run_battery(seqs);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i)
    for (std::size_t t = 0; t < one[i].size(); ++t)
      for (std::size_t v = 0; v < one[i][t].values.size(); ++v) {
        const double a = one[i][t].values[v].p, b = two[i][t].values[v].p;
        EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b)));
      }
}

// A fake battery result with the given P-values for one single-valued test.
std::vector<std::vector<TestResult>> column(const std::vector<double>& ps) {
  std::vector<std::vector<TestResult>> out;
  for (double p : ps) {
    TestResult r;
    r.test = Test::Frequency;
    r.values.push_back({"-", 0, p});
    out.push_back({r});
  }
  return out;
}

TEST(NistAssessment, ProportionAndUniformity) {
  // 1000 sequences, P-values evenly spread: uniform, 990 pass (1 - alpha exactly).
  std::vector<double> ps;
  for (int i = 0; i < 1000; ++i) ps.push_back((i + 0.5) / 1000);
  const auto rows = assess(column(ps));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].sample_size, 1000);
  EXPECT_EQ(rows[0].passed, 990);
  EXPECT_NEAR(rows[0].uniformity_p, 1.0, 1e-12);
  // (0.99 - 3 sqrt(0.99 * 0.01 / 1000)) * 1000 = 980.56: the reference truncates to 980, exact needs 981.
  EXPECT_EQ(rows[0].reference_min_pass, 980);
  EXPECT_NEAR(rows[0].proportion_low, 0.98056, 1e-5);
  EXPECT_TRUE(rows[0].ok());
  // Exactly 980 passing: the reference accepts, the exact bound does not.
  std::vector<double> worse(ps);
  for (int i = 10; i < 20; ++i) worse[i] = 0.001;
  const auto r2 = assess(column(worse));
  EXPECT_EQ(r2[0].passed, 980);
  EXPECT_TRUE(r2[0].reference_proportion_ok);
  EXPECT_FALSE(r2[0].proportion_ok);
  // All in one bin: uniformity fails.
  const auto r3 = assess(column(std::vector<double>(100, 0.55)));
  EXPECT_LT(r3[0].uniformity_p, 1e-4);
  EXPECT_FALSE(r3[0].ok());
}

TEST(NistAssessment, RandomExcursionsCountOnlyApplicableSequences) {
  auto results = column({0.5, 0.6, 0.7});
  results[1][0].applicable = false;
  results[1][0].values[0].p = NAN;
  const auto rows = assess(results);
  EXPECT_EQ(rows[0].sample_size, 2);
  EXPECT_EQ(rows[0].passed, 2);
}

}  // namespace

}  // namespace dpdrng_test::stats_nist_test_nist_inputs
