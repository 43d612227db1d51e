#include "bench_rng_scalar_family.hpp"
#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/saru.hpp"
#include "dpdrng/rng/splitmix.hpp"

namespace dpdrng::cli::bench_rng {

template void time_scalar_hash_of<rng::Family::splitmix64>(benchmark::State&, const rng::GeneratorSpec&, Mode);
template void time_scalar_hash_of<rng::Family::saru>(benchmark::State&, const rng::GeneratorSpec&, Mode);
template void time_scalar_hash_of<rng::Family::defect>(benchmark::State&, const rng::GeneratorSpec&, Mode);
template void time_scalar_hash_of<rng::Family::plugin>(benchmark::State&, const rng::GeneratorSpec&, Mode);

}  // namespace dpdrng::cli::bench_rng
