#include "dpdrng/rng/stream.hpp"

#include <algorithm>
#include <array>
#include <bit>

#include "dpdrng/rng/batch.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/mt.hpp"
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

template <int W>
std::array<std::uint64_t, W> block_at(const std::uint64_t* words, std::size_t call) {
  std::array<std::uint64_t, W> b;
  for (int w = 0; w < W; ++w) b[w] = words[W * call + w];
  return b;
}

// The scalar draw's own functions, so every number equals the scalar draw<> bit for bit: plain loops that GCC
// vectorises at -O3 where it can. A loop calling std::sqrt does not vectorise (libm's sqrt may set errno), so
// the Gaussian goes a register at a time, with the SIMD sqrt (correctly rounded, like std::sqrt). Blocks of one
// register, not two passes over the chunk, let the out-of-order core run one block's sqrt on the divider while
// the next block's polynomials use the FMA units.

// The low (u1) or high (u2) halves of 16 words.
simd::u32x16 word_halves(const std::uint64_t* w, bool high) {
  if constexpr (std::endian::native == std::endian::little) {
    const auto a = simd::load<simd::u32x16>(w), b = simd::load<simd::u32x16>(w + 8);
    return high ? __builtin_shufflevector(a, b, 1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31)
                : __builtin_shufflevector(a, b, 0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  } else {
    simd::u32x16 h;
    for (int j = 0; j < 16; ++j) h[j] = static_cast<std::uint32_t>(high ? w[j] >> 32 : w[j]);
    return h;
  }
}

// Lanes 0–7 or 8–15 widened to double (exact). GCC 12 splits the generic conversion into 128-bit pieces.
simd::f64x8 widen(simd::f32x16 v, bool high) {
  using f32x8 = float __attribute__((vector_size(32)));
  const f32x8 half = high ? __builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15)
                          : __builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7);
#if defined(__AVX512F__)
  // The masked form with every lane selected: the unmasked one trips GCC 12's -Wmaybe-uninitialized.
  const __m256 x = reinterpret_cast<__m256>(half);
  return reinterpret_cast<simd::f64x8>(_mm512_maskz_cvtps_pd(static_cast<__mmask8>(0xff), x));
#else
  return __builtin_convertvector(half, simd::f64x8);
#endif
}

}  // namespace

// Not a vectorised loop but GNU vectors, because the single-precision log reads a 16-entry table that the
// auto-vectoriser would turn into scalar loads and a register permutes in one instruction (unit_math_f32.hpp);
// its kernels are templates that the scalar draw runs on one lane, so the bits agree.
void box_muller_words(const std::uint64_t* w, std::size_t n, double* o) {
  std::size_t c = 0;
  for (; c + 16 <= n; c += 16) {
    const BoxMullerParts32x16 p = box_muller_parts32(word_halves(w + c, false), word_halves(w + c, true));
    const simd::f32x16 root = simd::sqrt(p.radius2);
    simd::store(o + c, widen(root, false) * widen(p.cosine, false));
    simd::store(o + c + 8, widen(root, true) * widen(p.cosine, true));
  }
  for (; c < n; ++c) o[c] = box_muller(std::array<std::uint64_t, 1>{w[c]});
}

namespace {

// out[k] = box_muller({u1[S·k], u2[S·k]}) bit for bit, eight at a time: the pair loop's two word arrays (S = 1) and
// a stream of S-word blocks, whose Gaussian reads each block's first two words (u1 = w, u2 = w + 1).
template <std::size_t S>
void box_muller_two_words(const std::uint64_t* u1, const std::uint64_t* u2, std::size_t n, double* o) {
  std::size_t c = 0;
  for (; c + 8 <= n; c += 8) {
    alignas(64) double radius2[8], cosine[8];
    for (std::size_t j = 0; j < 8; ++j) {
      const BoxMullerParts p = box_muller_parts(std::array<std::uint64_t, 2>{u1[S * (c + j)], u2[S * (c + j)]});
      radius2[j] = p.radius2;
      cosine[j] = p.cosine;
    }
    simd::store(o + c, simd::sqrt(simd::load<simd::f64x8>(radius2)) * simd::load<simd::f64x8>(cosine));
  }
  for (; c < n; ++c) o[c] = box_muller(std::array<std::uint64_t, 2>{u1[S * c], u2[S * c]});
}

}  // namespace

void box_muller_two_words(const std::uint64_t* u1, const std::uint64_t* u2, std::size_t n, double* o) {
  box_muller_two_words<1>(u1, u2, n, o);
}

namespace {

template <int W>
void map_words(Distribution dist, std::span<const std::uint64_t> words, std::span<double> out) {
  const std::uint64_t* w = words.data();
  double* o = out.data();
  const std::size_t n = out.size();
  if (dist == Distribution::uniform) {
    for (std::size_t c = 0; c < n; ++c) o[c] = uniform_unit_variance(block_at<W>(w, c));
  } else if constexpr (W == 1) {
    box_muller_words(w, n, o);
  } else {
    box_muller_two_words<W>(w, w + 1, n, o);
  }
}

// The defect generator's ζ is not a function of one call's words alone (it reads the previous call too): the
// scalar draw, call by call.
void fill_noise_hash(const Defect& g, Distribution dist, std::uint64_t start, std::uint64_t first,
                     std::span<double> out) {
  for (std::size_t c = 0; c < out.size(); ++c) {
    const DefectBlock b = g.stream(start, first + c);
    out[c] = dist == Distribution::gauss ? draw<Distribution::gauss>(b) : draw<Distribution::uniform>(b);
  }
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

// Streams hash a counter: a plug-in needs its counter entry.
void check_counter(const GeneratorSpec& spec) {
  if (is_plugin(spec.name)) check_plugin_seeding(load_plugin(spec.name), Seeding::counter);
}

}  // namespace

int words_per_call(const GeneratorSpec& spec) {
  if (family_of(spec.name) == Family::mt19937) return 1;
  check_counter(spec);
  return with_hash(spec, [](const auto& g) { return std::decay_t<decltype(g)>::kWords; });
}

void fill_stream(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t offset, std::span<std::uint64_t> out) {
  if (family_of(spec.name) == Family::mt19937) {
    Mt19937 mt(start);
    mt.engine.discard(2 * offset);
    mt.fill64(out.data(), out.size());
    return;
  }
  check_counter(spec);
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
  if (family_of(spec.name) == Family::mt19937) {
    Mt19937 mt(start);
    mt.engine.discard(2 * first_call);
    std::array<std::uint64_t, kChunkCalls> words;
    for (std::size_t done = 0; done < out.size();) {
      const std::size_t n = std::min(kChunkCalls, out.size() - done);
      mt.fill64(words.data(), n);
      map_words<1>(dist, std::span(words.data(), n), out.subspan(done, n));
      done += n;
    }
    return;
  }
  check_counter(spec);
  with_hash(spec, [&](const auto& g) { fill_noise_hash(g, dist, start, first_call, out); });
}

}  // namespace dpdrng::rng
