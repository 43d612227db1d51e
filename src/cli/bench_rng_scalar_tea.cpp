#include "bench_rng_scalar_family.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng::cli::bench_rng {

template void time_scalar_hash_of<rng::Family::tea32>(benchmark::State&, const rng::GeneratorSpec&, Mode);
template void time_scalar_hash_of<rng::Family::tea64>(benchmark::State&, const rng::GeneratorSpec&, Mode);

}  // namespace dpdrng::cli::bench_rng
