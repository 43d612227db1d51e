// The dispatch on the family; the timings are instantiated in the bench_rng_scalar_<family> files.
#include "bench_rng_scalar.hpp"

namespace dpdrng::cli::bench_rng {

void time_scalar_hash(benchmark::State& state, const rng::GeneratorSpec& spec, Mode mode) {
  rng::visit_keyed_family(rng::family_of(spec.name), spec.name,
                          [&]<rng::Family F>() { time_scalar_hash_of<F>(state, spec, mode); });
}

}  // namespace dpdrng::cli::bench_rng
