#pragma once
// TEA (Wheeler & Needham 1994) as Okada, Brumby & Yasuoka (PLoS ONE 2021) use it: 32TEA(n) and 64TEA(n).
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/simd.hpp"
#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

inline constexpr std::uint32_t kTeaDelta = 0x9E3779B9u;

// One Feistel cycle whose round sum is already advanced, on words or SIMD lanes V of words W (a key of plain
// words); the paper uses the same shifts, delta and key for 64-bit words.
template <class V, class W>
constexpr void tea_feistel(V& x0, V& x1, W sum, const std::array<W, 4>& k) {
  x0 += ((x1 << 4) + k[0]) ^ ((x1 >> 5) + k[1]) ^ (x1 + sum);
  x1 += ((x0 << 4) + k[2]) ^ ((x0 >> 5) + k[3]) ^ (x0 + sum);
}

template <class W>
constexpr void tea_cycle(W& x0, W& x1, W& sum, const std::array<W, 4>& k) {
  sum += W(kTeaDelta);
  tea_feistel(x0, x1, sum, k);
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

// The cycles on SIMD lanes, each lane bit for bit tea_encrypt's; R > 0: R rounds, R == 0: `rounds`. The batched
// paths keep a state in registers across all rounds.
template <int R, class V, class W>
inline void tea_rounds(V& x0, V& x1, const std::array<W, 4>& k, int rounds) {
  const int n = R > 0 ? R : rounds;
  W sum = 0;
  for (int r = 0; r < n; ++r) sum += W(kTeaDelta), tea_feistel(x0, x1, sum, k);
}

// Two independent blocks in one loop body: a TEA cycle is a chain of ~8 dependent operations, so one block
// alone leaves the SIMD ports waiting on latency; two side by side keep them busy.
template <int R, class V, class W>
inline void tea_rounds2(V& a0, V& a1, V& b0, V& b1, const std::array<W, 4>& k, int rounds) {
  const int n = R > 0 ? R : rounds;
  W sum = 0;
  for (int r = 0; r < n; ++r) sum += W(kTeaDelta), tea_feistel(a0, a1, sum, k), tea_feistel(b0, b1, sum, k);
}

// A batch of n calls on SIMD lanes V of words W, each lane bit for bit the scalar call's: two registers side by
// side while they fill (tea_rounds2), then one; the last calls, fewer than a register, as one register on a
// zero-padded copy of their inputs from kPadRounds rounds on (a scalar call pays its whole chain's latency: at 32
// rounds the pair loop's batches of ~100 pairs spent as long on their tails as on the rest), call by call below.
// load(a, b, x0, x1) reads a register's calls from a[0..) and b[0..); store(out, x0, x1) writes their blocks;
// scalar(c) is call c's block.
inline constexpr int kPadRounds = 8;

template <int R, class V, class W, class A, class B, class Block, class Load, class Store, class Scalar>
void tea_lanes(const std::array<W, 4>& k, int rounds, const A* a, const B* b, std::size_t n, Block* out, Load load,
               Store store, Scalar scalar) {
  constexpr std::size_t L = sizeof(V) / sizeof(W);
  std::size_t c = 0;
  for (; c + 2 * L <= n; c += 2 * L) {
    V a0, a1, b0, b1;
    load(a + c, b + c, a0, a1), load(a + c + L, b + c + L, b0, b1);
    tea_rounds2<R>(a0, a1, b0, b1, k, rounds);
    store(out + c, a0, a1), store(out + c + L, b0, b1);
  }
  const auto one = [&](const A* pa, const B* pb, Block* po) {
    V x0, x1;
    load(pa, pb, x0, x1);
    tea_rounds<R>(x0, x1, k, rounds);
    store(po, x0, x1);
  };
  for (; c + L <= n; c += L) one(a + c, b + c, out + c);
  const std::size_t m = n - c;
  if (m > 0 && (R > 0 ? R : rounds) >= kPadRounds) {
    A pa[L] = {};
    B pb[L] = {};
    Block po[L];
    std::copy_n(a + c, m, pa), std::copy_n(b + c, m, pb);
    one(pa, pb, po);
    std::copy_n(po, m, out + c);
    return;
  }
  for (; c < n; ++c) out[c] = scalar(c);
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
    return {hash(join32(j, i), step_key(step, seed))};
  }
  constexpr TeaKey step_key(std::uint64_t step, std::uint64_t seed) const {
    return {key[0] ^ lo32(step), key[1] ^ hi32(step), key[2] ^ lo32(seed), key[3] ^ hi32(seed)};
  }

  // Many pairs per call, each block distance()'s or pair_step()'s bit for bit, sixteen to a SIMD register: the
  // pair loop hashes a batch of pairs per call when a generator has these (noise.hpp, HashNoise::kBatch).
  void distance_batch(const double* dx, const double*, const double*, std::size_t n, Block* out) const {
    static_assert(sizeof(Block) == sizeof(std::uint64_t), "blocks are stored as plain words");
    tea_lanes<R, simd::u32x16>(
        key, rounds, dx, dx, n, out,
        [](const double* x, const double*, simd::u32x16& x0, simd::u32x16& x1) { simd::split_words(x, x0, x1); },
        [](Block* o, const simd::u32x16& x0, const simd::u32x16& x1) { simd::join_words(o, x0, x1); },
        [&](std::size_t c) { return distance(dx[c], 0.0, 0.0); });
  }
  void pair_step_batch(const std::uint32_t* i, const std::uint32_t* j, std::uint64_t step, std::uint64_t seed,
                       std::size_t n, Block* out) const {
    tea_lanes<R, simd::u32x16>(
        step_key(step, seed), rounds, i, j, n, out,
        [](const std::uint32_t* pi, const std::uint32_t* pj, simd::u32x16& x0, simd::u32x16& x1) {
          x0 = simd::load<simd::u32x16>(pi), x1 = simd::load<simd::u32x16>(pj);
        },
        [](Block* o, const simd::u32x16& x0, const simd::u32x16& x1) { simd::join_words(o, x0, x1); },
        [&](std::size_t c) { return pair_step(i[c], j[c], step, seed); });
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
    return hash(join32(j, i), step, seed_key(seed));
  }
  constexpr Key64 seed_key(std::uint64_t seed) const {
    Key64 k = key64();
    k[2] ^= seed;
    return k;
  }

  // Many pairs per call, each block distance()'s or pair_step()'s bit for bit, eight to a SIMD register (see
  // Tea32's).
  void distance_batch(const double* dx, const double* dy, const double*, std::size_t n, Block* out) const {
    static_assert(sizeof(Block) == 2 * sizeof(std::uint64_t), "blocks are stored as plain words");
    tea_lanes<R, simd::u64x8>(
        key64(), rounds, dx, dy, n, out,
        [](const double* x, const double* y, simd::u64x8& x0, simd::u64x8& x1) {
          x0 = simd::load<simd::u64x8>(x), x1 = simd::load<simd::u64x8>(y);
        },
        [](Block* o, const simd::u64x8& x0, const simd::u64x8& x1) { simd::store_pairs(o, x0, x1); },
        [&](std::size_t c) { return distance(dx[c], dy[c], 0.0); });
  }
  void pair_step_batch(const std::uint32_t* i, const std::uint32_t* j, std::uint64_t step, std::uint64_t seed,
                       std::size_t n, Block* out) const {
    tea_lanes<R, simd::u64x8>(
        seed_key(seed), rounds, i, j, n, out,
        [step](const std::uint32_t* pi, const std::uint32_t* pj, simd::u64x8& x0, simd::u64x8& x1) {
          for (int l = 0; l < 8; ++l) x0[l] = join32(pj[l], pi[l]);
          x1 = simd::u64x8{} + step;
        },
        [](Block* o, const simd::u64x8& x0, const simd::u64x8& x1) { simd::store_pairs(o, x0, x1); },
        [&](std::size_t c) { return pair_step(i[c], j[c], step, seed); });
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
