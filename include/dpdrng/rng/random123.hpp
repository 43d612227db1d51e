#pragma once
// Philox4x32 and Threefry2x64 from Random123 (Salmon et al., SC'11), the library's own definition.
// With R a compile-time constant, Random123's runtime-rounds functions fold to straight-line code.
#include <Random123/philox.h>
#include <Random123/threefry.h>

#include <array>
#include <bit>
#include <cstdint>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

// Random123 calls 7 rounds the fewest that pass BigCrush, and defaults to 10 for a safety margin.
template <int R = 0>
struct Philox4x32 {
  static constexpr const char* kName = "philox4x32";
  static constexpr int kWords = 2;
  using Block = std::array<std::uint64_t, kWords>;

  TeaKey key = kPaperTeaKey;  // k0, k1 form Philox's 2x32 key
  int rounds = R;

  Block hash(std::uint32_t c0, std::uint32_t c1, std::uint32_t c2, std::uint32_t c3, std::uint32_t k0,
             std::uint32_t k1) const {
    philox4x32_ctr_t c = {{c0, c1, c2, c3}};
    philox4x32_key_t k = {{k0, k1}};
    const philox4x32_ctr_t out = philox4x32_R(R > 0 ? unsigned(R) : unsigned(rounds), c, k);
    return {join32(out.v[1], out.v[0]), join32(out.v[3], out.v[2])};
  }
  Block stream(std::uint64_t start, std::uint64_t i) const {
    const std::uint64_t c = start + i;
    return hash(lo32(c), hi32(c), 0, 0, key[0], key[1]);
  }
  Block distance(double dx, double dy, double) const {
    const auto x = std::bit_cast<std::uint64_t>(dx), y = std::bit_cast<std::uint64_t>(dy);
    return hash(lo32(x), hi32(x), lo32(y), hi32(y), key[0], key[1]);
  }
  // HOOMD's layout: the pair and the step in the counter, the user seed in the key.
  Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    return hash(i, j, lo32(step), hi32(step), key[0] ^ lo32(seed), key[1] ^ hi32(seed));
  }
};

// Random123 calls 13 rounds the fewest that pass BigCrush for Threefry2x64, and defaults to 20.
template <int R = 0>
struct Threefry2x64 {
  static constexpr const char* kName = "threefry2x64";
  static constexpr int kWords = 2;
  using Block = std::array<std::uint64_t, kWords>;

  TeaKey key = kPaperTeaKey;  // (k1:k0, k3:k2) form Threefry's 2x64 key
  int rounds = R;

  Block hash(std::uint64_t c0, std::uint64_t c1, std::uint64_t k0, std::uint64_t k1) const {
    threefry2x64_ctr_t c = {{c0, c1}};
    threefry2x64_key_t k = {{k0, k1}};
    const threefry2x64_ctr_t out = threefry2x64_R(R > 0 ? unsigned(R) : unsigned(rounds), c, k);
    return {out.v[0], out.v[1]};
  }
  std::uint64_t k0() const { return join32(key[1], key[0]); }
  std::uint64_t k1() const { return join32(key[3], key[2]); }
  Block stream(std::uint64_t start, std::uint64_t i) const { return hash(start + i, 0, k0(), k1()); }
  Block distance(double dx, double dy, double) const {
    return hash(std::bit_cast<std::uint64_t>(dx), std::bit_cast<std::uint64_t>(dy), k0(), k1());
  }
  Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    return hash(join32(j, i), step, k0() ^ seed, k1());
  }
};

template <>
struct FamilyTraits<Family::philox4x32> {
  template <int R>
  using Gen = Philox4x32<R>;
  using CompiledRounds = Rounds<7, 10>;
  static constexpr GeneratorInfo kInfo{
      .name = "philox4x32",
      .family = Family::philox4x32,
      .default_rounds = 10,
      .min_rounds = 1,
      .max_rounds = 16,
      .safe_rounds = "Salmon et al. (SC'11): 7 rounds pass BigCrush, 10 (the default) adds a safety margin",
      .description = "Philox4x32-R from Random123: 128-bit counter, 64-bit key, 128-bit output"};
};

template <>
struct FamilyTraits<Family::threefry2x64> {
  template <int R>
  using Gen = Threefry2x64<R>;
  using CompiledRounds = Rounds<13, 20>;
  static constexpr GeneratorInfo kInfo{
      .name = "threefry2x64",
      .family = Family::threefry2x64,
      .default_rounds = 20,
      .min_rounds = 1,
      .max_rounds = 32,
      .safe_rounds = "Salmon et al. (SC'11): 13 rounds pass BigCrush, 20 (the default) adds a safety margin",
      .description = "Threefry2x64-R from Random123: 128-bit counter, 128-bit key, 128-bit output"};
};

}  // namespace dpdrng::rng
