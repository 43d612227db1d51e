#include "bench_rng_scalar_family.hpp"
#include "dpdrng/rng/random123.hpp"

namespace dpdrng::cli::bench_rng {

template void time_scalar_hash_of<rng::Family::philox4x32>(benchmark::State&, const rng::GeneratorSpec&, Mode);
template void time_scalar_hash_of<rng::Family::threefry2x64>(benchmark::State&, const rng::GeneratorSpec&, Mode);

}  // namespace dpdrng::cli::bench_rng
