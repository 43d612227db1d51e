#pragma once
// The reference: MT19937 (Matsumoto & Nishimura 1998), the 32-bit original the paper names, with the sequence
// of std::mt19937 (and of GSL's gsl_rng_mt19937) for the same 32-bit seed. It is a stream, not a hash: it
// cannot be keyed by a pair, so the engine draws its numbers in a fixed pair order once per step, some 65 000
// draws a step in the paper's fluid; fill() regenerates the state 624 words at a time and tempers whole runs
// of it in loops the compiler vectorises, where a draw at a time costs a call, a bounds check and a branch.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "dpdrng/rng/words.hpp"

namespace dpdrng::rng {

class Mt19937Engine {
 public:
  static constexpr int kN = 624, kM = 397;

  explicit Mt19937Engine(std::uint32_t seed = 5489u) {
    s_[0] = seed;
    for (int i = 1; i < kN; ++i) s_[i] = 1812433253u * (s_[i - 1] ^ (s_[i - 1] >> 30)) + std::uint32_t(i);
  }
  std::uint32_t operator()() {
    if (next_ == kN) twist();
    return temper(s_[next_++]);
  }
  // The next n draws, as n calls would give them.
  void fill(std::uint32_t* out, std::size_t n) {
    while (n > 0) {
      if (next_ == kN) twist();
      const std::size_t k = std::min(n, std::size_t(kN - next_));
      const std::uint32_t* from = s_.data() + next_;
      for (std::size_t t = 0; t < k; ++t) out[t] = temper(from[t]);
      next_ += int(k), out += k, n -= k;
    }
  }
  void discard(unsigned long long n) {
    while (n > 0) {
      if (next_ == kN) twist();
      const auto k = std::min(n, static_cast<unsigned long long>(kN - next_));
      next_ += int(k), n -= k;
    }
  }

 private:
  static std::uint32_t temper(std::uint32_t y) {
    y ^= y >> 11;
    y ^= (y << 7) & 0x9d2c5680u;
    y ^= (y << 15) & 0xefc60000u;
    return y ^ (y >> 18);
  }
  static std::uint32_t mix(std::uint32_t upper, std::uint32_t lower, std::uint32_t far) {
    const std::uint32_t y = (upper & 0x80000000u) | (lower & 0x7fffffffu);
    return far ^ (y >> 1) ^ ((y & 1u) * 0x9908b0dfu);
  }
  // The recurrence over the whole state in three loops, each free of a wrap-around index: words below
  // kN − kM read words kM ahead (not yet replaced), the others words kN − kM behind (already replaced), as
  // the one-word-at-a-time definition has them.
  void twist() {
    std::uint32_t* s = s_.data();
    for (int i = 0; i < kN - kM; ++i) s[i] = mix(s[i], s[i + 1], s[i + kM]);
    for (int i = kN - kM; i < kN - 1; ++i) s[i] = mix(s[i], s[i + 1], s[i + kM - kN]);
    s[kN - 1] = mix(s[kN - 1], s[0], s[kM - 1]);
    next_ = 0;
  }
  std::array<std::uint32_t, kN> s_{};
  int next_ = kN;
};

struct Mt19937 {
  static constexpr const char* kName = "mt19937";
  static constexpr int kWords = 1;

  Mt19937Engine engine;

  explicit Mt19937(std::uint64_t seed = 5489u) : engine(static_cast<std::uint32_t>(seed ^ (seed >> 32))) {}
  // Two successive 32-bit draws, the first as the high word.
  std::uint64_t next64() {
    const std::uint32_t hi = engine();
    return join32(hi, engine());
  }
  // n successive next64() words.
  void fill64(std::uint64_t* out, std::size_t n) {
    std::array<std::uint32_t, 2 * Mt19937Engine::kN> half;
    while (n > 0) {
      const std::size_t k = std::min(n, std::size_t(Mt19937Engine::kN));
      engine.fill(half.data(), 2 * k);
      for (std::size_t t = 0; t < k; ++t) out[t] = join32(half[2 * t], half[2 * t + 1]);
      out += k, n -= k;
    }
  }
};

}  // namespace dpdrng::rng
