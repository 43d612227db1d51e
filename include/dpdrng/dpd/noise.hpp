#pragma once
// Noise sources as the pair loop sees them: raw(p, k) gives the generator's output block for pair p (k is the
// pair's slot in this step's fixed pair order), raw2(p, k) the pair's second block (read only under the blocks
// feed), and zetas() turns a batch of blocks into ζ under the feed, a run-time field switched on once per batch.
// Keyed hashes ignore k; the mt19937 reference, a stream, fills one buffer per step in the fixed pair order (a
// second one after it under the blocks feed) and reads slot k, so its numbers do not depend on the thread count
// either.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/seeding.hpp"
#include "dpdrng/rng/stream.hpp"

namespace dpdrng::dpd {

// z[t] = Box–Muller of the words u1(t) and u2(t) for t < m (rng::box_muller_two_words, eight at a time: a loop of
// box_muller calls stays scalar, as std::sqrt may set errno), through buffers of plain words.
template <class U1, class U2>
inline void two_word_zetas(std::size_t m, double* z, U1 u1, U2 u2) {
  constexpr std::size_t kChunk = 128;
  std::uint64_t w1[kChunk], w2[kChunk];
  for (std::size_t c = 0; c < m; c += kChunk) {
    const std::size_t n = std::min(kChunk, m - c);
    for (std::size_t t = 0; t < n; ++t) w1[t] = u1(c + t), w2[t] = u2(c + t);
    rng::box_muller_two_words(w1, w2, n, z + c);
  }
}

// z[t] = ζ of blocks a[t] (and b[t], read under the blocks feed only) for t < m: one switch, then a plain loop.
template <rng::Distribution D, class Block>
inline void feed_zetas(rng::Feed f, const Block* a, const Block* b, double* z, std::size_t m) {
  if constexpr (std::is_same_v<Block, rng::DefectBlock>) {
    // The defect generator: the base's ζ under the feed, then the injected defect (defect.hpp).
    for (std::size_t t = 0; t < m; ++t) z[t] = rng::draw<D>(f, a[t], b[t]);
  } else if constexpr (D == rng::Distribution::uniform) {
    for (std::size_t t = 0; t < m; ++t) z[t] = rng::uniform_unit_variance(a[t]);
  } else {
    switch (f) {
      case rng::Feed::halves:
        if constexpr (std::is_same_v<Block, std::array<std::uint64_t, 1>>) {
          // Sixteen at a time (rng::box_muller_words, the same bits), through a buffer of plain words.
          constexpr std::size_t kChunk = 256;
          std::uint64_t w[kChunk];
          for (std::size_t c = 0; c < m; c += kChunk) {
            const std::size_t n = std::min(kChunk, m - c);
            for (std::size_t t = 0; t < n; ++t) w[t] = a[c + t][0];
            rng::box_muller_words(w, n, z + c);
          }
        } else {
          two_word_zetas(m, z, [a](std::size_t t) { return a[t][0]; }, [a](std::size_t t) { return a[t][1]; });
        }
        return;
      case rng::Feed::blocks:
        two_word_zetas(m, z, [a](std::size_t t) { return a[t][0]; }, [b](std::size_t t) { return b[t][0]; });
        return;
      case rng::Feed::inverse: {
        // The batched Φ⁻¹ (the scalar one's bits, eight lanes at a time) on chunks of uniforms.
        constexpr std::size_t kChunk = 64;
        double u[kChunk];
        for (std::size_t c = 0; c < m; c += kChunk) {
          const std::size_t n = std::min(kChunk, m - c);
          for (std::size_t t = 0; t < n; ++t) u[t] = rng::to_unit_mid(a[c + t][0]);
          rng::inverse_normal(u, z + c, n);
        }
        return;
      }
    }
  }
}

// z[t] for a distribution chosen at run time: one branch per batch, so that a kernel holds the hash loops once
// for both distributions.
template <class Block>
inline void feed_zetas(rng::Distribution d, rng::Feed f, const Block* a, const Block* b, double* z, std::size_t m) {
  if (d == rng::Distribution::gauss)
    feed_zetas<rng::Distribution::gauss>(f, a, b, z, m);
  else
    feed_zetas<rng::Distribution::uniform>(f, a, b, z, m);
}

// A keyed hash G under seeding S (rng::pair_block); the distribution and the feed are run-time fields.
template <class G, rng::Seeding S>
struct HashNoise {
  using Block = typename G::Block;
  static constexpr int kWords = G::kWords;
  static constexpr bool kStream = false;
  static constexpr bool kZero = false;
  static constexpr bool kDistance = S == rng::Seeding::distance;  // raw_batch reads the separations, not the ids
  G gen;
  std::uint64_t seed = 0;
  rng::Feed feed_ = rng::Feed::halves;
  rng::Distribution distribution = rng::Distribution::gauss;

  rng::Feed feed() const { return feed_; }
  void begin_step(std::size_t) {}
  Block raw(const rng::PairInput& p, std::size_t) const { return rng::pair_block<S>(gen, p, seed); }
  Block raw2(const rng::PairInput& p, std::size_t) const {
    return rng::pair_block<S>(gen, rng::second_input(p), seed);
  }
  void zetas(const Block* a, const Block* b, double* z, std::size_t m) const {
    feed_zetas(distribution, feed_, a, b, z, m);
  }

  // A generator with batch members (a plug-in behind a function pointer) takes a whole batch of pairs per call.
  static constexpr bool kBatch = requires(const G& g, const double* d, const std::uint32_t* u, Block* out) {
    g.distance_batch(d, d, d, std::size_t{}, out);
    g.pair_step_batch(u, u, std::uint64_t{}, std::uint64_t{}, std::size_t{}, out);
  };
  // The blocks of n canonical pairs, or their second blocks (second_input's map: (dy, dz, dx), ~step).
  void raw_batch(const std::uint32_t* i, const std::uint32_t* j, const double* dx, const double* dy,
                 const double* dz, std::uint64_t step, std::size_t n, Block* out, bool second) const {
    if constexpr (S == rng::Seeding::distance) {
      if (second)
        gen.distance_batch(dy, dz, dx, n, out);
      else
        gen.distance_batch(dx, dy, dz, n, out);
    } else {
      gen.pair_step_batch(i, j, second ? ~step : step, seed, n, out);
    }
  }
};

// The reference: two successive std::mt19937 draws per pair slot (high word first, as rng::Mt19937::next64);
// under the blocks feed the step's second buffer follows the first in the stream.
template <rng::Distribution D>
struct StreamNoise {
  using Block = std::array<std::uint64_t, 1>;
  static constexpr int kWords = 1;
  static constexpr bool kStream = true;
  static constexpr bool kZero = false;
  rng::Mt19937 mt;
  rng::Feed feed_ = rng::Feed::halves;
  std::vector<std::uint64_t> buffer, buffer2;

  StreamNoise(std::uint64_t seed, rng::Feed feed) : mt(seed), feed_(feed) {}
  rng::Feed feed() const { return feed_; }
  // Every slot's words of the step, untempered: a slot is tempered when a pair reads it (~1 in 20 in the paper's
  // fluid, every one on a tapped step).
  void begin_step(std::size_t slots) {
    buffer.resize(slots);
    mt.fill64_untempered(buffer.data(), slots);
    if (feed_ != rng::Feed::blocks) return;
    buffer2.resize(slots);
    mt.fill64_untempered(buffer2.data(), slots);
  }
  Block raw(const rng::PairInput&, std::size_t k) const { return {rng::Mt19937::temper64(buffer[k])}; }
  Block raw2(const rng::PairInput&, std::size_t k) const { return {rng::Mt19937::temper64(buffer2[k])}; }
  void zetas(const Block* a, const Block* b, double* z, std::size_t m) const { feed_zetas<D>(feed_, a, b, z, m); }
};

// Benchmark baselines (NoiseOverride): the same loop without the generator, or without anything random.
template <rng::Distribution D>
struct UnhashedNoise {
  using Block = std::array<std::uint64_t, 1>;
  static constexpr int kWords = 1;
  static constexpr bool kStream = false;
  static constexpr bool kZero = false;
  rng::Feed feed_ = rng::Feed::halves;

  rng::Feed feed() const { return feed_; }
  void begin_step(std::size_t) {}
  Block raw(const rng::PairInput& p, std::size_t) const { return {std::bit_cast<std::uint64_t>(p.dx) ^ p.step}; }
  Block raw2(const rng::PairInput& p, std::size_t k) const { return raw(rng::second_input(p), k); }
  void zetas(const Block* a, const Block* b, double* z, std::size_t m) const { feed_zetas<D>(feed_, a, b, z, m); }
};

struct ZeroNoise {
  using Block = std::array<std::uint64_t, 1>;
  static constexpr int kWords = 1;
  static constexpr bool kStream = false;
  static constexpr bool kZero = true;
  rng::Feed feed() const { return rng::Feed::halves; }
  void begin_step(std::size_t) {}
  Block raw(const rng::PairInput&, std::size_t) const { return {0}; }
  Block raw2(const rng::PairInput&, std::size_t) const { return {0}; }
  void zetas(const Block*, const Block*, double* z, std::size_t m) const {
    for (std::size_t t = 0; t < m; ++t) z[t] = 0.0;
  }
};

}  // namespace dpdrng::dpd
