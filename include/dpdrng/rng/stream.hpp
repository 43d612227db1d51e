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

// Output words per call (tea64, philox4x32, threefry2x64 give two; the others one).
int words_per_call(const GeneratorSpec& spec);

}  // namespace dpdrng::rng
