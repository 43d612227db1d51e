#pragma once
// Internal to src/dpd: the pair forces of a keyed-hash family under one pair seeding, every compiled round
// count (the distribution is a run-time field of the noise). Each family × seeding is explicitly instantiated in
// one translation unit of its own, written by cmake/families.cmake (pair_forces_family.hpp has the definition): the
// instantiations are the engine's largest, so they build in parallel, and a generator header rebuilds only its own
// family's.
#include <cstddef>
#include <memory>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::dpd {
class NoiseKernel;
}

namespace dpdrng::dpd::detail {

// The pair loop of cfg's pair mode, threads and taps around a noise kernel.
std::unique_ptr<PairForces> pair_loop_for(std::unique_ptr<NoiseKernel> noise, const WaterConfig& cfg,
                                          const DpdKernel& kernel, std::size_t n);

template <rng::Family F, rng::Seeding S>
std::unique_ptr<PairForces> make_hashed(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);

}  // namespace dpdrng::dpd::detail
