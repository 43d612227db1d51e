// The dispatch on the family; the timings are instantiated in the bench_rng_scalar_<family> files.
#include "bench_rng_scalar.hpp"

namespace dpdrng::cli::bench_rng {

void time_scalar_hash(benchmark::State& state, const rng::GeneratorSpec& spec, Mode mode) {
  switch (rng::family_of(spec.name)) {
    case rng::Family::tea32: return time_scalar_hash_of<rng::Family::tea32>(state, spec, mode);
    case rng::Family::tea64: return time_scalar_hash_of<rng::Family::tea64>(state, spec, mode);
    case rng::Family::philox4x32: return time_scalar_hash_of<rng::Family::philox4x32>(state, spec, mode);
    case rng::Family::threefry2x64: return time_scalar_hash_of<rng::Family::threefry2x64>(state, spec, mode);
    case rng::Family::splitmix64: return time_scalar_hash_of<rng::Family::splitmix64>(state, spec, mode);
    case rng::Family::saru: return time_scalar_hash_of<rng::Family::saru>(state, spec, mode);
    case rng::Family::defect: return time_scalar_hash_of<rng::Family::defect>(state, spec, mode);
    case rng::Family::plugin: return time_scalar_hash_of<rng::Family::plugin>(state, spec, mode);
    case rng::Family::mt19937: break;
  }
  rng::throw_not_keyed_hash(spec.name);
}

}  // namespace dpdrng::cli::bench_rng
