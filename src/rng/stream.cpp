#include "dpdrng/rng/stream.hpp"

#include <algorithm>
#include <array>

#include "dpdrng/rng/batch.hpp"
#include "dpdrng/rng/simd.hpp"

namespace dpdrng::rng {

namespace {

// Calls per chunk of the distribution paths: the words stay in L1 between hashing and mapping.
constexpr std::size_t kChunkCalls = 512;

template <class G>
void fill_hash(const G& g, std::uint64_t start, std::uint64_t offset, std::span<std::uint64_t> out) {
  constexpr std::uint64_t W = G::kWords;
  std::size_t k = 0;
  std::uint64_t call = offset / W;
  if (offset % W != 0) {  // resume inside a call
    const auto b = g.stream(start, call++);
    for (std::uint64_t w = offset % W; w < W && k < out.size(); ++w) out[k++] = b[w];
  }
  const std::size_t whole = (out.size() - k) / W;
  stream_batch(g, start, call, out.subspan(k, whole * W));
  k += whole * W;
  call += whole;
  if (k < out.size()) {
    const auto b = g.stream(start, call);
    for (std::uint64_t w = 0; k < out.size(); ++w) out[k++] = b[w];
  }
}

using simd::f64x8;
using simd::u64x8;

f64x8 to_double(u64x8 w) { return __builtin_convertvector(w, f64x8); }

// The same operations, in the same order, as the scalar draw<> in distribution.hpp (no contraction in ISO
// mode), so that uniform lanes equal the scalar values bit for bit and Gaussian lanes differ only by log/cos.
template <int W>
f64x8 map_block(Distribution dist, const std::uint64_t* words) {
  u64x8 w0, w1;
  if constexpr (W == 1) {
    w0 = simd::load<u64x8>(words);
    w1 = w0;
  } else {
    const u64x8 a = simd::load<u64x8>(words), b = simd::load<u64x8>(words + 8);
    w0 = __builtin_shufflevector(a, b, 0, 2, 4, 6, 8, 10, 12, 14);
    w1 = __builtin_shufflevector(a, b, 1, 3, 5, 7, 9, 11, 13, 15);
  }
  if (dist == Distribution::uniform) return std::numbers::sqrt3 * (2.0 * (to_double(w0 >> 11) * 0x1p-53) - 1.0);
  f64x8 u1, u2;
  if constexpr (W == 1) {
    u1 = (to_double(w0 & 0xffffffffu) + 1.0) * 0x1p-32;
    u2 = to_double(w0 >> 32) * 0x1p-32;
  } else {
    u1 = to_double((w0 >> 11) + 1) * 0x1p-53;
    u2 = to_double(w1 >> 11) * 0x1p-53;
  }
  return simd::sqrt(-2.0 * simd::log_unit(u1)) * simd::cos_2pi(u2);
}

template <int W>
void map_words(Distribution dist, std::span<const std::uint64_t> words, std::span<double> out) {
  std::size_t c = 0;
  for (; c + 8 <= out.size(); c += 8) simd::store(out.data() + c, map_block<W>(dist, words.data() + W * c));
  if (c == out.size()) return;
  std::array<std::uint64_t, 8 * W> tail{};  // pad the last block; its spare lanes are computed and dropped
  std::copy(words.begin() + W * c, words.begin() + W * out.size(), tail.begin());
  const f64x8 v = map_block<W>(dist, tail.data());
  for (std::size_t i = 0; c + i < out.size(); ++i) out[c + i] = v[i];
}

template <class G>
void fill_noise_hash(const G& g, Distribution dist, std::uint64_t start, std::uint64_t first,
                     std::span<double> out) {
  constexpr int W = G::kWords;
  std::array<std::uint64_t, kChunkCalls * W> words;
  for (std::size_t done = 0; done < out.size();) {
    const std::size_t n = std::min(kChunkCalls, out.size() - done);
    stream_batch(g, start, first + done, std::span(words.data(), n * W));
    map_words<W>(dist, std::span(words.data(), n * W), out.subspan(done, n));
    done += n;
  }
}

}  // namespace

int words_per_call(const GeneratorSpec& spec) {
  if (spec.name == "mt19937") return 1;
  return with_hash(spec, [](const auto& g) { return std::decay_t<decltype(g)>::kWords; });
}

void fill_stream(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t offset, std::span<std::uint64_t> out) {
  if (spec.name == "mt19937") {
    Mt19937 mt(start);
    mt.engine.discard(2 * offset);
    for (auto& w : out) w = mt.next64();
    return;
  }
  with_hash(spec, [&](const auto& g) { fill_hash(g, start, offset, out); });
}

void fill_unit(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t offset, std::span<double> out) {
  std::array<std::uint64_t, 1024> words;
  for (std::size_t done = 0; done < out.size();) {
    const std::size_t n = std::min(words.size(), out.size() - done);
    fill_stream(spec, start, offset + done, std::span(words.data(), n));
    for (std::size_t i = 0; i < n; ++i) out[done + i] = to_unit(words[i]);
    done += n;
  }
}

void fill_noise(const GeneratorSpec& spec, Distribution dist, std::uint64_t start, std::uint64_t first_call,
                std::span<double> out) {
  if (spec.name == "mt19937") {
    Mt19937 mt(start);
    mt.engine.discard(2 * first_call);
    std::array<std::uint64_t, kChunkCalls> words;
    for (std::size_t done = 0; done < out.size();) {
      const std::size_t n = std::min(kChunkCalls, out.size() - done);
      for (std::size_t i = 0; i < n; ++i) words[i] = mt.next64();
      map_words<1>(dist, std::span(words.data(), n), out.subspan(done, n));
      done += n;
    }
    return;
  }
  with_hash(spec, [&](const auto& g) { fill_noise_hash(g, dist, start, first_call, out); });
}

}  // namespace dpdrng::rng
