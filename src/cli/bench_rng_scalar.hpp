#pragma once
// Internal to the CLI: bench rng's modes, and its scalar timing of one keyed hash. The scalar timing is compiled
// once per generator type; the types are split by family into bench_rng_scalar_<family> files (each including its
// own family's generator header), so that editing a generator recompiles only its family's timing.
#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/inverse_normal.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::cli::bench_rng {

// Modes, in table order. scalar: independent calls one at a time, each output forced into a register
// (benchmark::DoNotOptimize), so consecutive calls may overlap in the pipeline but are never vectorised.
// batch: fill_stream() into an L1-resident buffer. scalar-/batch- uniform and gauss: one number per call
// through the scalar draw<>() and through fill_noise(). scalar-/batch- inverse: one Gaussian number per call
// through the inverse normal CDF of the block's first word (to_unit_mid, inverse_normal.hpp), scalar and batched
// (fill_stream(), then the batched Φ⁻¹): the alternative to Box–Muller's pairing of two uniforms.
enum class Mode { scalar, batch, scalar_uniform, scalar_gauss, scalar_inverse, uniform, gauss, inverse };
constexpr Mode kModes[] = {Mode::scalar,         Mode::batch,   Mode::scalar_uniform, Mode::scalar_gauss,
                           Mode::scalar_inverse, Mode::uniform, Mode::gauss,          Mode::inverse};

inline bool is_scalar(Mode m) {
  return m == Mode::scalar || m == Mode::scalar_uniform || m == Mode::scalar_gauss || m == Mode::scalar_inverse;
}

// One number from a block, as the scalar modes draw it.
template <std::size_t N>
double scalar_number(Mode mode, const std::array<std::uint64_t, N>& b) {
  if (mode == Mode::scalar_uniform) return rng::draw<rng::Distribution::uniform>(b);
  if (mode == Mode::scalar_gauss) return rng::draw<rng::Distribution::gauss>(b);
  return rng::inverse_normal(rng::to_unit_mid(b[0]));
}

// The defect generator's numbers carry its injected defect (rng/defect.hpp); its words are the base's.
inline double scalar_number(Mode mode, const rng::DefectBlock& b) {
  if (mode == Mode::scalar_uniform) return rng::draw<rng::Distribution::uniform>(b);
  if (mode == Mode::scalar_gauss) return rng::draw<rng::Distribution::gauss>(b);
  return rng::draw<rng::Distribution::gauss>(rng::Feed::inverse, b, b);
}

// Each benchmark iteration produces this many outputs (words for scalar/batch, numbers for distributions).
constexpr std::size_t kScalarCalls = 256;

// Times independent calls of spec's generator, one at a time (a keyed hash; mt19937 is timed by the caller).
void time_scalar_hash(benchmark::State& state, const rng::GeneratorSpec& spec, Mode mode);

// The same for one family, instantiated in that family's file.
template <rng::Family F>
void time_scalar_hash_of(benchmark::State& state, const rng::GeneratorSpec& spec, Mode mode);

}  // namespace dpdrng::cli::bench_rng
