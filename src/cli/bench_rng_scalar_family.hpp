#pragma once
// Internal to the CLI: the definition of time_scalar_hash_of (bench_rng_scalar.hpp), for the files that
// instantiate it; each includes its own family's generator header.
#include "bench_rng_scalar.hpp"

namespace dpdrng::cli::bench_rng {

template <class G>
void scalar_hash(benchmark::State& state, const G& g, Mode mode) {
  std::uint64_t i = 0;
  for (auto _ : state) {
    for (std::size_t k = 0; k < kScalarCalls; ++k) {
      const auto b = g.stream(1, i++);
      if (mode == Mode::scalar) {
        for (auto w : b) benchmark::DoNotOptimize(w);
      } else {
        benchmark::DoNotOptimize(scalar_number(mode, b));
      }
    }
  }
}

template <rng::Family F>
void time_scalar_hash_of(benchmark::State& state, const rng::GeneratorSpec& spec, Mode mode) {
  rng::with_family_hash<F>(spec, [&](const auto& g) { scalar_hash(state, g, mode); });
}

}  // namespace dpdrng::cli::bench_rng
