// bench rng's scalar timing of a plug-in (the listed families' files are written by cmake/families.cmake).
#include "bench_rng_scalar_family.hpp"

namespace dpdrng::cli::bench_rng {

template void time_scalar_hash_of<rng::Family::plugin>(benchmark::State&, const rng::GeneratorSpec&, Mode);

}  // namespace dpdrng::cli::bench_rng
