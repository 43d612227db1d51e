#pragma once
// SplitMix64 (Steele, Lea & Flood, OOPSLA 2014; Vigna's public-domain splitmix64.c): a Weyl sequence
// with increment 0x9e3779b97f4a7c15 through a fixed 64-bit finaliser. It has no round parameter.
#include <array>
#include <bit>
#include <cstdint>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

inline constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;

constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

struct SplitMix64 {
  static constexpr const char* kName = "splitmix64";
  static constexpr int kWords = 1;
  using Block = std::array<std::uint64_t, kWords>;

  TeaKey key = kPaperTeaKey;

  std::uint64_t key64() const { return join32(key[1], key[0]); }
  // The published stream: state = start, call i returns mix(start + (i+1)·γ).
  constexpr Block stream(std::uint64_t start, std::uint64_t i) const {
    return {splitmix64_mix(start + (i + 1) * kGoldenGamma)};
  }
  Block distance(double dx, double, double) const {
    return {splitmix64_mix(std::bit_cast<std::uint64_t>(dx) + key64() * kGoldenGamma)};
  }
  // Two chained mixes so that pair and step do not cancel each other linearly.
  constexpr Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    const std::uint64_t h = splitmix64_mix(join32(j, i) + (seed + 1) * kGoldenGamma);
    return {splitmix64_mix(h ^ (step * kGoldenGamma))};
  }
};

template <>
struct FamilyTraits<Family::splitmix64> {
  template <int>
  using Gen = SplitMix64;
  using CompiledRounds = Rounds<>;
  static constexpr GeneratorInfo kInfo{
      .name = "splitmix64",
      .family = Family::splitmix64,
      .safe_rounds = "fixed finaliser, no round parameter; passes BigCrush (Steele et al. 2014)",
      .description = "SplitMix64: Weyl sequence (gamma 0x9e3779b97f4a7c15) through Stafford's mix13 finaliser",
      .takes_key = false,
      .counter_stream = false};
};

}  // namespace dpdrng::rng
