#pragma once
// Internal to src/dpd: the per-noise kernel of the pair loop (pair_loop.hpp), one instantiation per noise
// policy (noise.hpp), so the hash inlines into the batch loops while the loop around them is compiled once.
#include <omp.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "dpdrng/dpd/noise.hpp"
#include "dpdrng/dpd/pair_loop.hpp"

namespace dpdrng::dpd {

template <class Noise>
class NoiseKernelOf final : public NoiseKernel {
 public:
  explicit NoiseKernelOf(Noise noise) : noise_(std::move(noise)) {}

  int words() const override { return Noise::kWords; }
  bool stream() const override { return Noise::kStream; }
  bool zero() const override { return Noise::kZero; }
  rng::Feed feed() const override { return noise_.feed(); }
  void threads(int count) override { scratch_.resize(std::size_t(count)); }
  void begin_step(std::size_t slots) override {
    if constexpr (Noise::kStream) noise_.begin_step(slots);
  }

  void row_words(const RowWords& b, int thread) override {
    Scratch& sc = scratch(thread, b.m);
    Block* blk = sc.blk.data();
    row_blocks(b, sc, blk);
    for (int w = 0; w < Noise::kWords; ++w)
      for (std::size_t t = 0; t < b.m; ++t) b.tap[w][t] = blk[t][w];
  }

  void pairs(const PairBatch& b, int thread) override {
    const std::size_t k = b.k;
    Scratch& sc = scratch(thread, k);
    if constexpr (kBatched) return pairs_batched(b, sc);
    Block* blk = sc.blk.data();
    auto slot = [&b](std::size_t t) { return b.slots ? b.slots[t] : b.slot + t; };
    for (std::size_t t = 0; t < k; ++t) {
      const rng::PairInput p{b.i[t], b.j[t], b.dx[t], b.dy[t], b.dz[t], b.step};
      blk[t] = noise_.raw(rng::canonical(p), slot(t));
    }
    if (noise_.feed() == rng::Feed::blocks)
      for (std::size_t t = 0; t < k; ++t) {
        const rng::PairInput p{b.i[t], b.j[t], b.dx[t], b.dy[t], b.dz[t], b.step};
        sc.blk2[t] = noise_.raw2(rng::canonical(p), slot(t));
      }
    noise_.zetas(blk, sc.blk2.data(), b.zeta, k);
    if (b.tap[0])
      for (int w = 0; w < Noise::kWords; ++w)
        for (std::size_t t = 0; t < k; ++t) b.tap[w][t] = blk[t][w];
    if (b.used) copy_used(blk, sc.blk2.data(), k, b.used);
  }

  void pair(const rng::PairInput& p, std::size_t slot, std::uint64_t* words, double& zeta) const override {
    const Block blk = noise_.raw(p, slot);
    const Block blk2 = noise_.feed() == rng::Feed::blocks ? noise_.raw2(p, slot) : blk;
    noise_.zetas(&blk, &blk2, &zeta, 1);
    for (int w = 0; w < Noise::kWords; ++w) words[w] = blk[w];
  }

  double ns_per_number() const override { return calibrate(false); }
  double ns_per_zeta() const override { return calibrate(true); }

 private:
  using Block = typename Noise::Block;
  static constexpr bool kBatched = requires { requires Noise::kBatch; };
  struct Scratch {
    std::vector<Block> blk, blk2;  // the pairs' blocks; their second blocks (blocks feed)
    std::vector<std::uint32_t> i, j;  // a batched generator's canonical pairs
    std::vector<double> dx, dy, dz;
  };

  // The blocks of every pair of row b (pairs (i, i + 1 + t)): a batched generator's in one call.
  void row_blocks(const RowWords& b, Scratch& sc, Block* out) const {
    const std::uint32_t i = b.i;
    if constexpr (kBatched) {
      sc.i.assign(b.m, i), sc.j.resize(b.m);
      for (std::size_t t = 0; t < b.m; ++t) sc.j[t] = std::uint32_t(i + 1 + t);
      noise_.raw_batch(sc.i.data(), sc.j.data(), b.dx, b.dy, b.dz, b.step, b.m, out, false);
    } else {
      for (std::size_t t = 0; t < b.m; ++t)
        out[t] = noise_.raw(rng::PairInput{i, std::uint32_t(i + 1 + t), b.dx[t], b.dy[t], b.dz[t], b.step}, b.slot + t);
    }
  }

  void pairs_batched(const PairBatch& b, Scratch& sc) {
    const std::size_t k = b.k;
    // rng::canonical() as selects, and only the inputs the seeding reads, in loops that vectorise.
    if constexpr (Noise::kDistance) {
      sc.dx.resize(k), sc.dy.resize(k), sc.dz.resize(k);
      canonical_separation(b.i, b.j, b.dx, k, sc.dx.data());
      canonical_separation(b.i, b.j, b.dy, k, sc.dy.data());
      canonical_separation(b.i, b.j, b.dz, k, sc.dz.data());
    } else {
      sc.i.resize(k), sc.j.resize(k);
      for (std::size_t t = 0; t < k; ++t) sc.i[t] = std::min(b.i[t], b.j[t]), sc.j[t] = std::max(b.i[t], b.j[t]);
    }
    batch_zetas(sc, sc.i.data(), sc.j.data(), sc.dx.data(), sc.dy.data(), sc.dz.data(), b.step, k, b.zeta);
    if (b.tap[0])
      for (int w = 0; w < Noise::kWords; ++w)
        for (std::size_t t = 0; t < k; ++t) b.tap[w][t] = sc.blk[t][w];
    if (b.used) copy_used(sc.blk.data(), sc.blk2.data(), k, b.used);
  }

  // out[t] = d[t], negated where i[t] > j[t] (canonical()'s negation: the sign bit flipped, as unary minus does),
  // without a branch on the order, which in cells mode is a coin toss.
  static void canonical_separation(const std::uint32_t* __restrict i, const std::uint32_t* __restrict j,
                                   const double* __restrict d, std::size_t k, double* __restrict out) {
    for (std::size_t t = 0; t < k; ++t) {
      const std::uint64_t flip = std::uint64_t(i[t] > j[t]) << 63;
      out[t] = std::bit_cast<double>(std::bit_cast<std::uint64_t>(d[t]) ^ flip);
    }
  }

  void batch_zetas(Scratch& sc, const std::uint32_t* i, const std::uint32_t* j, const double* dx, const double* dy,
                   const double* dz, std::uint64_t step, std::size_t k, double* zeta) const {
    noise_.raw_batch(i, j, dx, dy, dz, step, k, sc.blk.data(), false);
    if (noise_.feed() == rng::Feed::blocks) noise_.raw_batch(i, j, dx, dy, dz, step, k, sc.blk2.data(), true);
    noise_.zetas(sc.blk.data(), sc.blk2.data(), zeta, k);
  }

  // The k pairs' blocks (and second blocks under the blocks feed), pair after pair, into out.
  void copy_used(const Block* blk, const Block* blk2, std::size_t k, std::uint64_t* out) const {
    const bool two = noise_.feed() == rng::Feed::blocks;
    for (std::size_t t = 0; t < k; ++t) {
      for (int w = 0; w < Noise::kWords; ++w) *out++ = blk[t][w];
      if (two)
        for (int w = 0; w < Noise::kWords; ++w) *out++ = blk2[t][w];
    }
  }

  Scratch& scratch(int thread, std::size_t m) {
    Scratch& sc = scratch_[std::size_t(thread)];
    if (sc.blk.size() < m) sc.blk.resize(m), sc.blk2.resize(m);
    return sc;
  }

  // Best of 5 repetitions of 4096 calls.
  double calibrate(bool zeta_only) const {
    if constexpr (Noise::kZero) {
      return 0.0;
    } else {
      constexpr std::size_t kCalls = 4096;
      Noise noise = noise_;
      std::vector<double> dx(kCalls), dy(kCalls), dz(kCalls), zeta(kCalls);
      std::vector<Block> blk(kCalls), blk2(kCalls);
      for (std::size_t t = 0; t < kCalls; ++t) dx[t] = 0.9 - 4e-4 * t, dy[t] = 0.25 - 1e-4 * t, dz[t] = 1e-4 * t - 0.1;
      const bool two = noise.feed() == rng::Feed::blocks;
      std::vector<std::uint32_t> is(kCalls, 7), js(kCalls);
      for (std::size_t t = 0; t < kCalls; ++t) js[t] = std::uint32_t(8 + t);
      auto fill = [&] {
        if constexpr (Noise::kStream) noise.begin_step(kCalls);
        if constexpr (kBatched) {  // as the pair loop calls it: one call for the batch
          noise.raw_batch(is.data(), js.data(), dx.data(), dy.data(), dz.data(), 99, kCalls, blk.data(), false);
        } else {
          for (std::size_t t = 0; t < kCalls; ++t)
            blk[t] = noise.raw(rng::PairInput{7, std::uint32_t(8 + t), dx[t], dy[t], dz[t], 99}, t);
        }
      };
      fill();  // warm-up, and real blocks for the ζ timing (the stream's second buffer too)
      if (two)
        for (std::size_t t = 0; t < kCalls; ++t)
          blk2[t] = noise.raw2(rng::PairInput{7, std::uint32_t(8 + t), dx[t], dy[t], dz[t], 99}, t);
      double best = std::numeric_limits<double>::infinity();
      volatile double sink = 0;
      for (int rep = 0; rep < 5; ++rep) {
        double acc = 0;
        const auto t0 = std::chrono::steady_clock::now();
        if (zeta_only)
          noise.zetas(blk.data(), blk2.data(), zeta.data(), kCalls), acc = zeta[kCalls / 2];
        else
          fill(), acc = double(blk[kCalls / 2][0] & 1);
        const auto t1 = std::chrono::steady_clock::now();
        sink = sink + acc;
        best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / kCalls);
      }
      return best;
    }
  }

  Noise noise_;
  std::vector<Scratch> scratch_;
};

template <class Noise>
std::unique_ptr<NoiseKernel> make_noise_kernel(Noise noise) {
  return std::make_unique<NoiseKernelOf<Noise>>(std::move(noise));
}

}  // namespace dpdrng::dpd
