#pragma once
// TEA (Wheeler & Needham 1994) as Okada, Brumby & Yasuoka (PLoS ONE 2021) use it: 32TEA(n) and 64TEA(n).
#include <array>
#include <bit>
#include <cstdint>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

inline constexpr std::uint32_t kTeaDelta = 0x9E3779B9u;

// One Feistel cycle on words of type W; the paper uses the same shifts, delta and key for 64-bit words.
template <class W>
constexpr void tea_cycle(W& x0, W& x1, W& sum, const std::array<W, 4>& k) {
  sum += W(kTeaDelta);
  x0 += ((x1 << 4) + k[0]) ^ ((x1 >> 5) + k[1]) ^ (x1 + sum);
  x1 += ((x0 << 4) + k[2]) ^ ((x0 >> 5) + k[3]) ^ (x0 + sum);
}

// Compile-time round count: the loop unrolls, so a hot loop pays for the hash alone.
template <int R, class W>
constexpr void tea_encrypt(W& x0, W& x1, const std::array<W, 4>& k) {
  W sum = 0;
  for (int r = 0; r < R; ++r) tea_cycle(x0, x1, sum, k);
}

template <class W>
constexpr void tea_encrypt(W& x0, W& x1, const std::array<W, 4>& k, int rounds) {
  W sum = 0;
  for (int r = 0; r < rounds; ++r) tea_cycle(x0, x1, sum, k);
}

// R > 0: rounds fixed at compile time; R == 0: `rounds` chosen at run time (any 1..64).
template <int R>
struct RoundCount {
  static constexpr int value(int) { return R; }
};

// 32TEA(n): one 64-bit seed, low word -> x0, high word -> x1; output (x1' << 32) | x0'.
template <int R = 0>
struct Tea32 {
  static constexpr const char* kName = "tea32";
  static constexpr int kWords = 1;
  using Block = std::array<std::uint64_t, kWords>;

  TeaKey key = kPaperTeaKey;
  int rounds = R;

  constexpr std::uint64_t hash(std::uint64_t seed, const TeaKey& k) const {
    std::uint32_t x0 = lo32(seed), x1 = hi32(seed);
    if constexpr (R > 0)
      tea_encrypt<R>(x0, x1, k);
    else
      tea_encrypt(x0, x1, k, rounds);
    return join32(x1, x0);
  }
  constexpr std::uint64_t hash(std::uint64_t seed) const { return hash(seed, key); }

  constexpr Block stream(std::uint64_t start, std::uint64_t i) const { return {hash(start + i)}; }
  // The paper's seeding: the IEEE-754 bits of the x component of r_ij = r_j - r_i.
  Block distance(double dx, double, double) const { return {hash(std::bit_cast<std::uint64_t>(dx))}; }
  // A 64-bit block holds only the pair, so step and seed go into the key (TEA's key schedule is trivial).
  constexpr Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    const TeaKey k{key[0] ^ lo32(step), key[1] ^ hi32(step), key[2] ^ lo32(seed), key[3] ^ hi32(seed)};
    return {hash(join32(j, i), k)};
  }
};

// 64TEA(n): the same cycle on 64-bit words; two inputs, two outputs "a" and "b".
template <int R = 0>
struct Tea64 {
  static constexpr const char* kName = "tea64";
  static constexpr int kWords = 2;
  using Block = std::array<std::uint64_t, kWords>;
  using Key64 = std::array<std::uint64_t, 4>;

  TeaKey key = kPaperTeaKey;
  int rounds = R;

  constexpr Block hash(std::uint64_t x0, std::uint64_t x1, const Key64& k) const {
    if constexpr (R > 0)
      tea_encrypt<R>(x0, x1, k);
    else
      tea_encrypt(x0, x1, k, rounds);
    return {x0, x1};
  }
  constexpr Key64 key64() const { return {key[0], key[1], key[2], key[3]}; }

  constexpr Block stream(std::uint64_t start, std::uint64_t i) const { return hash(start + i, 0, key64()); }
  Block distance(double dx, double dy, double) const {
    return hash(std::bit_cast<std::uint64_t>(dx), std::bit_cast<std::uint64_t>(dy), key64());
  }
  constexpr Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    Key64 k = key64();
    k[2] ^= seed;
    return hash(join32(j, i), step, k);
  }
};

// The studies' round counts, compiled as constants for both TEA families.
using TeaCompiledRounds = Rounds<1, 2, 3, 4, 5, 6, 8, 16, 32>;

template <>
struct FamilyTraits<Family::tea32> {
  template <int R>
  using Gen = Tea32<R>;
  using CompiledRounds = TeaCompiledRounds;
  static constexpr GeneratorInfo kInfo{
      .name = "tea32",
      .family = Family::tea32,
      .default_rounds = 32,
      .min_rounds = 1,
      .max_rounds = 64,
      .safe_rounds =
          "Wheeler & Needham (1994) recommend 32 cycles (64 Feistel rounds); the paper asks whether 1 will do",
      .description =
          "32TEA(n): 64-bit seed split into two 32-bit words (low -> x0), n TEA cycles, joined (x1'<<32)|x0'"};
};

template <>
struct FamilyTraits<Family::tea64> {
  template <int R>
  using Gen = Tea64<R>;
  using CompiledRounds = TeaCompiledRounds;
  static constexpr GeneratorInfo kInfo{
      .name = "tea64",
      .family = Family::tea64,
      .default_rounds = 32,
      .min_rounds = 1,
      .max_rounds = 64,
      .safe_rounds = "no published analysis; the paper's 64-bit variant of TEA's cycle",
      .description = "64TEA(n): TEA's cycle on 64-bit words, inputs (x0, x1), outputs a and b"};
};

}  // namespace dpdrng::rng
