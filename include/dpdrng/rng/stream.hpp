#pragma once
// A generator as a standalone stream of 64-bit words: what `dpdrng gen`, the benchmarks and the statistical
// tests consume. Hashes run in counter mode (word k of call i = stream(start, i)[k]); mt19937 runs sequentially.
#include <cstdint>
#include <functional>
#include <span>

#include "dpdrng/rng/registry.hpp"

namespace dpdrng::rng {

// Fills out with consecutive output words of the stream that starts at `start`, beginning at word `offset`.
void fill_stream(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t offset, std::span<std::uint64_t> out);

// Word-indexed like fill_stream, mapped to [0,1) by to_unit(): out[k] = to_unit(word offset + k).
void fill_unit(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t offset, std::span<double> out);

// One number per generator call, the value PairNoise would give for that call's block:
// out[k] = draw<dist>(stream(start, first_call + k)); mt19937's "call" is one next64() word.
// Bit-identical to the scalar draw for both distributions: the Gaussian runs box_muller()'s own functions in
// vectorised loops (distribution.hpp).
void fill_noise(const GeneratorSpec& spec, Distribution dist, std::uint64_t start, std::uint64_t first_call,
                std::span<double> out);
inline void fill_uniform(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t first_call,
                         std::span<double> out) {
  fill_noise(spec, Distribution::uniform, start, first_call, out);
}
inline void fill_gauss(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t first_call,
                       std::span<double> out) {
  fill_noise(spec, Distribution::gauss, start, first_call, out);
}

// Box–Muller of one-word blocks: out[k] = box_muller(std::array<std::uint64_t, 1>{words[k]}) bit for bit, sixteen
// words at a time (the pair loop's batches of 32TEA, SplitMix64 and Saru blocks take this path).
void box_muller_words(const std::uint64_t* words, std::size_t n, double* out);

// Box–Muller of two 64-bit words per number: out[k] = box_muller(std::array<std::uint64_t, 2>{u1[k], u2[k]}) bit
// for bit, eight at a time (the blocks feed's first words, and the halves feed of two-word blocks).
void box_muller_two_words(const std::uint64_t* u1, const std::uint64_t* u2, std::size_t n, double* out);

// Output words per call (tea64, philox4x32, threefry2x64 give two; the others one).
int words_per_call(const GeneratorSpec& spec);

}  // namespace dpdrng::rng
