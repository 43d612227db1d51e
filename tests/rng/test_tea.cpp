// Known answers for TEA and the paper's 32TEA/64TEA split and join.
#include <gtest/gtest.h>

#include <bit>

#include "dpdrng/rng/tea.hpp"

namespace dpdrng_test::rng_test_tea {

using namespace dpdrng::rng;

// Wheeler & Needham's reference code, 32 cycles, zero key and zero plaintext -> 41ea3a0a 94baa940
// (the widely quoted TEA test vector, e.g. in the Crypto++ and Bouncy Castle TEA test files).
TEST(Tea, ZeroKeyZeroPlaintext32Cycles) {
  std::uint32_t x0 = 0, x1 = 0;
  tea_encrypt<32>(x0, x1, std::array<std::uint32_t, 4>{0, 0, 0, 0});
  EXPECT_EQ(x0, 0x41ea3a0au);
  EXPECT_EQ(x1, 0x94baa940u);
}

TEST(Tea, RuntimeRoundsMatchCompileTimeRounds) {
  for (int r : {1, 2, 3, 8, 32}) {
    Tea32<0> dyn;
    dyn.rounds = r;
    std::uint64_t expect = 0;
    switch (r) {
      case 1: expect = Tea32<1>{}.hash(0x0123456789abcdefull); break;
      case 2: expect = Tea32<2>{}.hash(0x0123456789abcdefull); break;
      case 3: expect = Tea32<3>{}.hash(0x0123456789abcdefull); break;
      case 8: expect = Tea32<8>{}.hash(0x0123456789abcdefull); break;
      case 32: expect = Tea32<32>{}.hash(0x0123456789abcdefull); break;
    }
    EXPECT_EQ(dyn.hash(0x0123456789abcdefull), expect) << "rounds " << r;
  }
}

// The paper's 32TEA: low word of the seed is x0, high word x1, output (x1' << 32) | x0'.
TEST(Tea, Tea32SplitsLowWordIntoX0AndJoinsX1High) {
  const std::uint64_t seed = std::bit_cast<std::uint64_t>(-0.731);
  std::uint32_t x0 = static_cast<std::uint32_t>(seed), x1 = static_cast<std::uint32_t>(seed >> 32);
  tea_encrypt<1>(x0, x1, kPaperTeaKey);
  EXPECT_EQ(Tea32<1>{}.distance(-0.731, 5.0, 7.0)[0], (std::uint64_t{x1} << 32) | x0);
}

// One TEA cycle written out by hand from docs/design.md's round equations, on 64-bit words.
TEST(Tea, Tea64OneCycleByHand) {
  const std::uint64_t dx = std::bit_cast<std::uint64_t>(0.25), dy = std::bit_cast<std::uint64_t>(-1.5);
  std::uint64_t x0 = dx, x1 = dy, sum = 0x9E3779B9ull;
  x0 += ((x1 << 4) + 3) ^ ((x1 >> 5) + 4) ^ (x1 + sum);
  x1 += ((x0 << 4) + 5) ^ ((x0 >> 5) + 6) ^ (x0 + sum);
  const auto ab = Tea64<1>{}.distance(0.25, -1.5, 0.0);
  EXPECT_EQ(ab[0], x0);
  EXPECT_EQ(ab[1], x1);
}

}  // namespace dpdrng_test::rng_test_tea
