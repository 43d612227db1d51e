#pragma once
// Internal to src/dpd: the definition of make_hashed (pair_forces_make.hpp), for the files that instantiate it;
// each includes its own family's generator header.
#include "noise_kernel.hpp"
#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

template <rng::Family F, rng::Seeding S>
std::unique_ptr<PairForces> make_hashed(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return rng::with_family_hash<F>(cfg.generator, [&]<class G>(const G& gen) -> std::unique_ptr<PairForces> {
    const HashNoise<G, S> noise{gen, cfg.seed, cfg.feed, cfg.distribution};
    return pair_loop_for(make_noise_kernel(noise), cfg, kernel, n);
  });
}

}  // namespace dpdrng::dpd::detail
