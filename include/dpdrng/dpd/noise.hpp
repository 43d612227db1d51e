#pragma once
// Noise sources as the pair loop sees them: raw(p, k) gives the generator's output block for pair p (k is the
// pair's slot in this step's fixed pair order), zeta(block) turns it into ζ. Keyed hashes ignore k; the
// mt19937 reference, a stream, fills one buffer per step in the fixed pair order and reads slot k, so its
// numbers do not depend on the thread count either.
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::dpd {

template <class PN>  // PN = rng::PairNoise<G, S, D>
struct HashNoise {
  using Block = typename PN::Generator::Block;
  static constexpr int kWords = PN::Generator::kWords;
  static constexpr bool kStream = false;
  static constexpr bool kZero = false;
  PN pn;

  void begin_step(std::size_t) {}
  Block raw(const rng::PairInput& p, std::size_t) const { return rng::pair_block<PN::kSeeding>(pn.gen, p, pn.seed); }
  double zeta(const Block& b) const { return rng::draw<PN::kDistribution>(b); }
};

// The reference: two successive std::mt19937 draws per pair slot (high word first, as rng::Mt19937::next64).
template <rng::Distribution D>
struct StreamNoise {
  using Block = std::array<std::uint64_t, 1>;
  static constexpr int kWords = 1;
  static constexpr bool kStream = true;
  static constexpr bool kZero = false;
  rng::Mt19937 mt;
  std::vector<std::uint64_t> buffer;

  explicit StreamNoise(std::uint64_t seed) : mt(seed) {}
  void begin_step(std::size_t slots) {
    buffer.resize(slots);
    for (auto& w : buffer) w = mt.next64();
  }
  Block raw(const rng::PairInput&, std::size_t k) const { return {buffer[k]}; }
  double zeta(const Block& b) const { return rng::draw<D>(b); }
};

// Benchmark baselines (NoiseOverride): the same loop without the generator, or without anything random.
template <rng::Distribution D>
struct UnhashedNoise {
  using Block = std::array<std::uint64_t, 1>;
  static constexpr int kWords = 1;
  static constexpr bool kStream = false;
  static constexpr bool kZero = false;
  void begin_step(std::size_t) {}
  Block raw(const rng::PairInput& p, std::size_t) const { return {std::bit_cast<std::uint64_t>(p.dx) ^ p.step}; }
  double zeta(const Block& b) const { return rng::draw<D>(b); }
};

struct ZeroNoise {
  using Block = std::array<std::uint64_t, 1>;
  static constexpr int kWords = 1;
  static constexpr bool kStream = false;
  static constexpr bool kZero = true;
  void begin_step(std::size_t) {}
  Block raw(const rng::PairInput&, std::size_t) const { return {0}; }
  double zeta(const Block&) const { return 0.0; }
};

}  // namespace dpdrng::dpd
