#pragma once
// Internal to src/dpd: the definition of make_hashed (pair_forces_make.hpp), for the files that instantiate it;
// each includes its own family's generator header.
#include "noise_kernel.hpp"
#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

template <rng::Family F, rng::Seeding S>
std::unique_ptr<PairForces> make_hashed(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return rng::with_family_hash<F>(cfg.generator, [&]<class G>(const G& gen) -> std::unique_ptr<PairForces> {
    auto build = [&]<rng::Distribution D>() {
      HashNoise<rng::PairNoise<G, S, D>> noise{{gen, cfg.seed, cfg.feed}};
      return make_pair_loop(make_noise_kernel(noise), kernel, cfg.pairs, cfg.threads, n, cfg.taps.pairs);
    };
    if (cfg.distribution == rng::Distribution::gauss) return build.template operator()<rng::Distribution::gauss>();
    return build.template operator()<rng::Distribution::uniform>();
  });
}

}  // namespace dpdrng::dpd::detail
