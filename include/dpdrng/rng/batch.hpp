#pragma once
// Batched hashing: many independent calls at once, bit-identical to calling the scalar hash one by one
// (tests/rng/test_batch.cpp checks every generator and round count).
//
// The scalar hash is a chain of dependent operations, so one call at a time leaves most of the core idle.
// Here a block of calls shares one SIMD register per state word (16 lanes of 32 bits, or 8 of 64), all rounds
// run on registers, and the cost per output approaches (operations per round × rounds) / lanes.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "dpdrng/rng/random123.hpp"
#include "dpdrng/rng/simd.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng::rng {

namespace batch_detail {
using simd::u32x16;
using simd::u64x8;

// 16 counters start + c .. start + c + 15 as low and high 32-bit words (the carry crosses into the high word).
inline void split_counters(std::uint64_t first, u32x16& lo, u32x16& hi) {
  constexpr u32x16 iota{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  lo = lo32(first) + iota;
  hi = hi32(first) + u32x16{};
  if (lo32(first) > 0xffffffffu - 15) hi -= reinterpret_cast<u32x16>(lo < lo32(first));  // true lanes: all ones
}

// 16 (x1:x0) pairs joined into 64-bit words, little-endian order: the low word of each pair comes first.
inline void join_store(std::uint64_t* out, const u32x16& x0, const u32x16& x1) { simd::join_words(out, x0, x1); }
}  // namespace batch_detail

// 32TEA(n) in counter mode: out[c] = g.stream(start, first + c)[0] for c < out.size().
template <int R>
void stream_batch(const Tea32<R>& g, std::uint64_t start, std::uint64_t first, std::span<std::uint64_t> out) {
  using namespace batch_detail;
  std::size_t c = 0;
  for (; c + 32 <= out.size(); c += 32) {
    u32x16 a0, a1, b0, b1;
    split_counters(start + first + c, a0, a1);
    split_counters(start + first + c + 16, b0, b1);
    tea_rounds2<R>(a0, a1, b0, b1, g.key, g.rounds);
    join_store(out.data() + c, a0, a1);
    join_store(out.data() + c + 16, b0, b1);
  }
  for (; c + 16 <= out.size(); c += 16) {
    u32x16 x0, x1;
    split_counters(start + first + c, x0, x1);
    tea_rounds<R>(x0, x1, g.key, g.rounds);
    join_store(out.data() + c, x0, x1);
  }
  for (; c < out.size(); ++c) out[c] = g.stream(start, first + c)[0];
}

// 32TEA(n) on arbitrary seeds (e.g. a batch of pairs' dx bits): out[c] = g.hash(seeds[c]).
template <int R>
void hash_batch(const Tea32<R>& g, std::span<const std::uint64_t> seeds, std::span<std::uint64_t> out) {
  using namespace batch_detail;
  std::size_t c = 0;
  for (; c + 16 <= seeds.size(); c += 16) {
    u32x16 x0, x1;
    simd::split_words(seeds.data() + c, x0, x1);
    tea_rounds<R>(x0, x1, g.key, g.rounds);
    join_store(out.data() + c, x0, x1);
  }
  for (; c < seeds.size(); ++c) out[c] = g.hash(seeds[c]);
}

// 64TEA(n) in counter mode: out[2c], out[2c+1] = a, b of g.stream(start, first + c); out.size() must be even.
template <int R>
void stream_batch(const Tea64<R>& g, std::uint64_t start, std::uint64_t first, std::span<std::uint64_t> out) {
  using namespace batch_detail;
  constexpr u64x8 iota{0, 1, 2, 3, 4, 5, 6, 7};
  const std::array<std::uint64_t, 4> k = g.key64();
  const std::size_t calls = out.size() / 2;
  auto store_ab = [&](std::size_t call, const u64x8& a, const u64x8& b) { simd::store_pairs(out.data() + 2 * call, a, b); };
  std::size_t c = 0;
  for (; c + 16 <= calls; c += 16) {
    u64x8 a0 = (start + first + c) + iota, a1 = u64x8{};
    u64x8 b0 = (start + first + c + 8) + iota, b1 = u64x8{};
    tea_rounds2<R>(a0, a1, b0, b1, k, g.rounds);
    store_ab(c, a0, a1);
    store_ab(c + 8, b0, b1);
  }
  for (; c + 8 <= calls; c += 8) {
    u64x8 x0 = (start + first + c) + iota, x1 = u64x8{};
    tea_rounds<R>(x0, x1, k, g.rounds);
    store_ab(c, x0, x1);
  }
  for (; c < calls; ++c) {
    const auto b = g.stream(start, first + c);
    out[2 * c] = b[0];
    out[2 * c + 1] = b[1];
  }
}

// SplitMix64's published stream: out[c] = mix(start + (first + c + 1)·γ).
inline void stream_batch(const SplitMix64&, std::uint64_t start, std::uint64_t first, std::span<std::uint64_t> out) {
  using batch_detail::u64x8;
  constexpr u64x8 iota{1, 2, 3, 4, 5, 6, 7, 8};
  std::size_t c = 0;
  for (; c + 8 <= out.size(); c += 8) {
    u64x8 z = start + ((first + c) + iota) * kGoldenGamma;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    simd::store(out.data() + c, z ^ (z >> 31));
  }
  for (; c < out.size(); ++c) out[c] = splitmix64_mix(start + (first + c + 1) * kGoldenGamma);
}

// Philox4x32-R (Salmon et al. 2011) in counter mode, eight calls at once: each 32-bit counter word sits in a
// 64-bit lane so that one 32×32→64 multiply gives both halves of the product.
template <int R>
void stream_batch(const Philox4x32<R>& g, std::uint64_t start, std::uint64_t first, std::span<std::uint64_t> out) {
  using batch_detail::u64x8;
  constexpr u64x8 iota{0, 1, 2, 3, 4, 5, 6, 7};
  constexpr std::uint64_t m0 = 0xD2511F53u, m1 = 0xCD9E8D57u, low = 0xffffffffu;
  const int rounds = R > 0 ? R : g.rounds;
  const std::size_t calls = out.size() / 2;
  std::size_t c = 0;
  for (; c + 8 <= calls; c += 8) {
    const u64x8 ctr = (start + first + c) + iota;
    u64x8 x0 = ctr & low, x1 = ctr >> 32, x2 = u64x8{}, x3 = u64x8{};
    std::uint64_t k0 = g.key[0], k1 = g.key[1];
    for (int r = 0; r < rounds; ++r) {
      if (r > 0) {
        k0 = (k0 + 0x9E3779B9u) & low;
        k1 = (k1 + 0xBB67AE85u) & low;
      }
      const u64x8 p0 = x0 * m0, p1 = x2 * m1;
      x0 = (p1 >> 32) ^ x1 ^ k0;
      x1 = p1 & low;
      x2 = (p0 >> 32) ^ x3 ^ k1;
      x3 = p0 & low;
    }
    const u64x8 w0 = (x1 << 32) | x0, w1 = (x3 << 32) | x2;
    simd::store(out.data() + 2 * c, __builtin_shufflevector(w0, w1, 0, 8, 1, 9, 2, 10, 3, 11));
    simd::store(out.data() + 2 * c + 8, __builtin_shufflevector(w0, w1, 4, 12, 5, 13, 6, 14, 7, 15));
  }
  for (; c < calls; ++c) {
    const auto b = g.stream(start, first + c);
    out[2 * c] = b[0];
    out[2 * c + 1] = b[1];
  }
}

// Threefry2x64-R (Salmon et al. 2011) in counter mode, eight calls at once; the key is injected every 4 rounds.
template <int R>
void stream_batch(const Threefry2x64<R>& g, std::uint64_t start, std::uint64_t first,
                  std::span<std::uint64_t> out) {
  using batch_detail::u64x8;
  constexpr u64x8 iota{0, 1, 2, 3, 4, 5, 6, 7};
  constexpr int rot[8] = {16, 42, 12, 31, 16, 32, 24, 21};
  const int rounds = R > 0 ? R : g.rounds;
  const std::uint64_t ks[3] = {g.k0(), g.k1(), 0x1BD11BDAA9FC1A22ull ^ g.k0() ^ g.k1()};
  const std::size_t calls = out.size() / 2;
  std::size_t c = 0;
  for (; c + 8 <= calls; c += 8) {
    u64x8 x0 = (start + first + c) + iota + ks[0], x1 = u64x8{} + ks[1];
    // Unrolled, the rotation counts become immediates (one vprolq each) and the injections lose their branch.
#pragma GCC unroll 32
    for (int r = 0; r < rounds; ++r) {
      const int n = rot[r % 8];
      x0 += x1;
      x1 = (x1 << n) | (x1 >> (64 - n));
      x1 ^= x0;
      if (r % 4 == 3) {
        const int s = (r + 1) / 4;
        x0 += ks[s % 3];
        x1 += ks[(s + 1) % 3] + std::uint64_t(s);
      }
    }
    simd::store(out.data() + 2 * c, __builtin_shufflevector(x0, x1, 0, 8, 1, 9, 2, 10, 3, 11));
    simd::store(out.data() + 2 * c + 8, __builtin_shufflevector(x0, x1, 4, 12, 5, 13, 6, 14, 7, 15));
  }
  for (; c < calls; ++c) {
    const auto b = g.stream(start, first + c);
    out[2 * c] = b[0];
    out[2 * c + 1] = b[1];
  }
}

// Any other keyed hash: call by call, in a loop the compiler may still vectorise.
template <class G>
void stream_batch(const G& g, std::uint64_t start, std::uint64_t first, std::span<std::uint64_t> out) {
  constexpr std::size_t W = G::kWords;
  for (std::size_t c = 0; c < out.size() / W; ++c) {
    const auto b = g.stream(start, first + c);
    for (std::size_t w = 0; w < W; ++w) out[W * c + w] = b[w];
  }
}

}  // namespace dpdrng::rng
