// Squares (rng/squares.hpp; Widynski, arXiv:2004.06278). Known answers for the author's first published key
// 0xc58efd154ce32f6d (keys.h of the reference code at squaresrng.wixsite.com/rand): the paper prints no outputs,
// so the values were computed by an independent transcription of the published squares32 and squares64 in
// arbitrary-precision integers (Python, every product reduced mod 2^64), not by this code.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <set>

#include "dpdrng/rng/squares.hpp"

namespace dpdrng_test::rng_test_squares {

using namespace dpdrng::rng;

struct Kat {
  std::uint64_t ctr;
  std::uint32_t out32;
  std::uint64_t out64;
};
constexpr Kat kKats[] = {{0, 0x8352d815u, 0x8352d81514c3f20full},
                         {1, 0x4d645c71u, 0x4d645c710dea443cull},
                         {2, 0x5f664b34u, 0x5f664b34b649cc78ull},
                         {3, 0x5502129eu, 0x5502129ef0e4b900ull},
                         {123456789, 0xc7614a88u, 0xc7614a8831fbb0afull},
                         {0xffffffffffffffffull, 0x89d8c127u, 0x89d8c127f819498bull}};

TEST(KatSquares, PublishedAlgorithmWithTheAuthorsFirstKey) {
  for (const Kat& k : kKats) {
    EXPECT_EQ(squares32(k.ctr, kSquaresKey), k.out32) << k.ctr;
    EXPECT_EQ(squares64(k.ctr, kSquaresKey), k.out64) << k.ctr;
  }
  static_assert(squares64(0, kSquaresKey) == 0x8352d81514c3f20full, "constexpr, as the other generators");
}

// squares64 is squares32's fourth round kept whole, XOR the fifth round's high half: its high word is squares32.
TEST(Squares, HighWordOfSquares64IsSquares32) {
  for (std::uint64_t c = 0; c < 1000; ++c)
    EXPECT_EQ(squares64(c * 0x9e3779b97f4a7c15ull, kSquaresKey) >> 32,
              squares32(c * 0x9e3779b97f4a7c15ull, kSquaresKey));
}

// The family's seedings as squares.hpp states them.
TEST(Squares, FamilySeedings) {
  const Squares64 g;
  EXPECT_EQ(g.stream(0, 3)[0], squares64(3, kSquaresKey));
  EXPECT_EQ(g.stream(1ull << 40, 5)[0], squares64((1ull << 40) + 5, kSquaresKey));
  EXPECT_EQ(g.distance(-0.25, 1.0, 2.0)[0], squares64(std::bit_cast<std::uint64_t>(-0.25), kSquaresKey));
  const std::uint64_t offset = squares64(7, kSquaresKey) ^ (11 * 0x9e3779b97f4a7c15ull);
  EXPECT_EQ(g.pair_step(3, 9, 7, 11)[0], squares64(((9ull << 32) | 3) ^ offset, kSquaresKey));
}

// Pair-step seeding: for one step and seed the pairs' counters differ (an XOR with a constant keeps (j:i) distinct),
// so their blocks collide only as two 64-bit hash outputs may; among 44 850 pairs none does, and a step or a
// seed apart changes every block.
TEST(Squares, PairStepBlocksOfOneStepAreDistinct) {
  const Squares64 g;
  std::set<std::uint64_t> seen;
  std::size_t pairs = 0, same_next_step = 0, same_next_seed = 0;
  for (std::uint32_t j = 1; j < 300; ++j)
    for (std::uint32_t i = 0; i < j; ++i, ++pairs) {
      const std::uint64_t w = g.pair_step(i, j, 1000, 42)[0];
      seen.insert(w);
      same_next_step += w == g.pair_step(i, j, 1001, 42)[0];
      same_next_seed += w == g.pair_step(i, j, 1000, 43)[0];
    }
  EXPECT_EQ(seen.size(), pairs);
  EXPECT_EQ(same_next_step, 0u);
  EXPECT_EQ(same_next_seed, 0u);
}

}  // namespace dpdrng_test::rng_test_squares
