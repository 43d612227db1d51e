#pragma once
// The reference: MT19937 (Matsumoto & Nishimura 1998), the 32-bit original the paper names, as std::mt19937
// (the same sequence as GSL's gsl_rng_mt19937 for the same 32-bit seed). It is a stream, not a hash: it cannot
// be keyed by a pair, so the engine draws its numbers in a fixed pair order once per step.
#include <cstdint>
#include <random>

#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

struct Mt19937 {
  static constexpr const char* kName = "mt19937";
  static constexpr int kWords = 1;

  std::mt19937 engine;

  explicit Mt19937(std::uint64_t seed = 5489u) : engine(static_cast<std::uint32_t>(seed ^ (seed >> 32))) {}
  // Two successive 32-bit draws, the first as the high word.
  std::uint64_t next64() {
    const std::uint32_t hi = engine();
    return join32(hi, engine());
  }
};

}  // namespace dpdrng::rng
