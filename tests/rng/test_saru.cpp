// Saru (rng/saru.hpp). No published known-answer vectors exist: neither the CPC 2013 paper nor HOOMD-blue's
// tests (hoomd/test/random_numbers_test.cc checks distribution moments only) print outputs for given seeds. So
// these tests check what the definition fixes: its constants' stated properties, the branch-free Weyl step
// against the general modular form HOOMD's advanceAnyWeyl() states, HOOMD's pair seeding (symmetric, seed and
// step entering as one sum), outputs against an independent transcription, and χ² uniformity of the streams.
#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "dpdrng/rng/saru.hpp"
#include "dpdrng/rng/stream.hpp"

namespace dpdrng_test::rng_test_saru {

using namespace dpdrng::rng;
namespace sd = dpdrng::rng::saru_detail;

namespace {

// The LCG x → A·x + C mod 2^32 has full period iff C is odd and A ≡ 1 mod 4 (Hull–Dobell), as Saru's header
// claims; the Weyl period 3666320093 is said to be prime.
TEST(Saru, ConstantsHaveTheirStatedProperties) {
  EXPECT_EQ(sd::kLcgC % 2, 1u);
  EXPECT_EQ(sd::kLcgA % 4, 1u);
  const std::uint64_t p = sd::kWeylPeriod;
  EXPECT_EQ(p, 3666320093u);
  for (std::uint64_t d = 2; d * d <= p; ++d) ASSERT_NE(p % d, 0u) << d;
}

// HOOMD states one Weyl step as y + Δ, or y + Δ − P when y − offset > P − Δ (Δ = P + offset mod 2^32); our step
// adds offset and P masked by y's sign bit. Both must agree on every state a seeding and stepping reaches.
TEST(Saru, WeylStepIsTheModularAddOfTheGeneralForm) {
  constexpr std::uint32_t P = sd::kWeylPeriod, O = sd::kWeylOffset, delta = P + O;
  std::mt19937_64 pick(1);
  for (int n = 0; n < 20000; ++n) {
    const std::uint64_t w = pick();
    sd::State s = sd::seed3(static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(w >> 32), n);
    for (int k = 0; k < 8; ++k) {
      const std::uint32_t y = s.y;
      const std::uint32_t general = y + (y - O > P - delta ? delta - P : delta);
      sd::next(s);
      ASSERT_EQ(s.y, general) << std::hex << y;
    }
  }
}

// Outputs from a second, independent transcription of the definition (Python, arbitrary-precision integers
// masked to 32 bits, sign fill done by hand), so that C++ promotion or shift mistakes cannot hide:
// word = (u2 << 32) | u1, the first two outputs after seeding.
TEST(Saru, MatchesIndependentTranscription) {
  EXPECT_EQ(sd::two_outputs(sd::seed2(0, 0)), 0x9b57eeb9b41a5db3ull);
  EXPECT_EQ(sd::two_outputs(sd::seed2(1, 0)), 0xccb082f8919536ddull);
  EXPECT_EQ(sd::two_outputs(sd::seed2(0x12345678u, 0x9abcdef0u)), 0x3127d1c457686cb5ull);
  EXPECT_EQ(sd::two_outputs(sd::seed3(0, 0, 0)), 0x0bd29ec6328bf5e8ull);
  EXPECT_EQ(sd::two_outputs(sd::seed3(1, 2, 3)), 0x46bbc0caaffbf576ull);
  EXPECT_EQ(sd::two_outputs(sd::seed3(7, 11, 1042)), 0x62daa19c33d6014eull);
  sd::State s = sd::seed3(1, 2, 3);
  const std::array<std::uint32_t, 4> expect{0xaffbf576u, 0x46bbc0cau, 0x8abbfdd8u, 0x0e7e7776u};
  for (std::uint32_t e : expect) EXPECT_EQ(sd::next(s), e);
}

TEST(Saru, CounterModeSeedsWithTheCountersHalves) {
  const Saru g;
  EXPECT_EQ(g.stream(0, 0)[0], 0x9b57eeb9b41a5db3ull);
  EXPECT_EQ(g.stream(0x9abcdef012345670ull, 8)[0], 0x3127d1c457686cb5ull);
}

// HOOMD v2: Saru(min(i, j), max(i, j), seed + timestep). Symmetric in i, j; the seed and the step enter only
// through their 32-bit sum (so runs whose seed differs by k are the same runs shifted by k steps).
TEST(Saru, PairSeedingIsHoomds) {
  const Saru g;
  EXPECT_EQ(g.pair_step(3, 17, 100, 7)[0], g.pair_step(17, 3, 100, 7)[0]);
  EXPECT_EQ(g.pair_step(3, 17, 100, 7)[0], sd::two_outputs(sd::seed3(3, 17, 107)));
  EXPECT_EQ(g.pair_step(3, 17, 100, 7)[0], g.pair_step(3, 17, 7, 100)[0]);
  EXPECT_EQ(g.pair_step(3, 17, 1ull << 32, 0)[0], g.pair_step(3, 17, 0, 0)[0]);  // 32-bit sum
  EXPECT_NE(g.pair_step(3, 17, 100, 7)[0], g.pair_step(3, 18, 100, 7)[0]);
}

// χ² of a byte of the output word against 256 equally likely values; fixed seeds, so deterministic. A correct
// generator lands inside (1e-6, 1 − 1e-6) of the χ²(255) distribution; a stuck or biased byte lands far out.
void expect_uniform_bytes(const std::vector<std::uint64_t>& words, const char* what) {
  for (int shift : {0, 24, 32, 56}) {
    std::array<double, 256> count{};
    for (std::uint64_t w : words) count[(w >> shift) & 0xff] += 1;
    const double e = static_cast<double>(words.size()) / 256;
    double chi2 = 0;
    for (double c : count) chi2 += (c - e) * (c - e) / e;
    const double p = gsl_cdf_chisq_Q(chi2, 255);
    EXPECT_GT(p, 1e-6) << what << " byte at bit " << shift << " chi2 " << chi2;
    EXPECT_LT(p, 1 - 1e-6) << what << " byte at bit " << shift << " chi2 " << chi2;
  }
}

TEST(Saru, StreamsPassByteChiSquare) {
  GeneratorSpec s;
  s.name = "saru";
  s = validated(s);
  std::vector<std::uint64_t> words(1 << 18);
  fill_stream(s, 0, 0, words);  // consecutive counters: seeds differ in a few low bits
  expect_uniform_bytes(words, "counter stream");
  const Saru g;
  std::size_t k = 0;
  for (std::uint32_t i = 0; i < 512; ++i)
    for (std::uint32_t j = i + 1; j < i + 513; ++j) words[k++] = g.pair_step(i, j, 1000, 1)[0];
  expect_uniform_bytes(words, "pair-step over neighbouring pairs");
  for (k = 0; k < words.size(); ++k) words[k] = g.pair_step(5, 9, k, 1)[0];
  expect_uniform_bytes(words, "pair-step over steps");
}

}  // namespace

}  // namespace dpdrng_test::rng_test_saru
