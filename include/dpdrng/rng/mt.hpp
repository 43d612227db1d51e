#pragma once
// The reference: MT19937 (Matsumoto & Nishimura 1998), the 32-bit original the paper names, with the sequence
// of std::mt19937 (and of GSL's gsl_rng_mt19937) for the same 32-bit seed. It is a stream, not a hash: it
// cannot be keyed by a pair, so the engine draws its numbers in a fixed pair order once per step, some 65 000
// draws a step in the paper's fluid; fill() regenerates the state 624 words at a time and tempers whole runs
// of it in loops the compiler vectorises, where a draw at a time costs a call, a bounds check and a branch.
// fill64_untempered leaves the tempering to a caller that reads few of its words (the engine's reference reads
// those of the pairs inside r_c, about 1 in 20).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

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
      const std::span<const std::uint32_t> r = run(n);
      for (std::size_t t = 0; t < r.size(); ++t) out[t] = temper(r[t]);
      out += r.size(), n -= r.size();
    }
  }
  void discard(unsigned long long n) {
    while (n > 0) n -= run(std::size_t(std::min<unsigned long long>(n, kN))).size();
  }
  // The next draws before tempering (temper() of each is the draw), as many as the state holds up to n (n >= 1):
  // a run of consecutive state words, valid until the next call.
  std::span<const std::uint32_t> run(std::size_t n) {
    if (next_ == kN) twist();
    const std::size_t k = std::min(n, std::size_t(kN - next_));
    const std::span<const std::uint32_t> r(s_.data() + next_, k);
    next_ += int(k);
    return r;
  }
  static std::uint32_t temper(std::uint32_t y) {
    y ^= y >> 11;
    y ^= (y << 7) & 0x9d2c5680u;
    y ^= (y << 15) & 0xefc60000u;
    return y ^ (y >> 18);
  }

 private:
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
    fill64_untempered(out, n);
    for (std::size_t t = 0; t < n; ++t) out[t] = temper64(out[t]);
  }
  // The same words before tempering, straight from the state: temper64(out[t]) is fill64's out[t]. A stream whose
  // words are mostly never read (the pairs outside r_c) tempers only those it reads.
  void fill64_untempered(std::uint64_t* out, std::size_t n) {
    while (n > 0) {
      const std::span<const std::uint32_t> r = engine.run(2 * n);
      const std::size_t k = r.size() / 2;
      for (std::size_t t = 0; t < k; ++t) out[t] = join32(r[2 * t], r[2 * t + 1]);
      out += k, n -= k;
      // A word left over at the end of the state: its pair's second word opens the next state.
      if (r.size() % 2 == 1) {
        const std::uint32_t hi = r.back();  // read before the next run regenerates the state
        *out++ = join32(hi, engine.run(1)[0]), --n;
      }
    }
  }
  // Mt19937Engine::temper on both halves at once: each shift's bits that cross into the other half are masked
  // off, as a 32-bit shift drops them; four operations on whole words, so a loop of them vectorises.
  static constexpr std::uint64_t temper64(std::uint64_t w) {
    w ^= (w >> 11) & 0x001fffff001fffffull;
    w ^= (w << 7) & 0x9d2c56809d2c5680ull;
    w ^= (w << 15) & 0xefc60000efc60000ull;
    return w ^ ((w >> 18) & 0x00003fff00003fffull);
  }
};

}  // namespace dpdrng::rng
