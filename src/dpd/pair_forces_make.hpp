#pragma once
// Internal to src/dpd: the noise-kernel factory split by generator family, one translation unit each, since
// each family instantiates the kernel for every compiled round count × seeding × distribution.
#include <memory>

#include "noise_kernel.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::dpd::detail {

template <class G>
std::unique_ptr<PairForces> make_for_generator(const G& gen, const WaterConfig& cfg, const DpdKernel& kernel,
                                               std::size_t n) {
  auto build = [&]<rng::Seeding S, rng::Distribution D>() -> std::unique_ptr<PairForces> {
    HashNoise<rng::PairNoise<G, S, D>> noise{{gen, cfg.seed, cfg.feed}};
    return make_pair_loop(make_noise_kernel(noise), kernel, cfg.pairs, cfg.threads, n, cfg.taps.pairs);
  };
  using rng::Distribution, rng::Seeding;
  const bool gauss = cfg.distribution == Distribution::gauss;
  if (cfg.seeding == Seeding::distance)
    return gauss ? build.template operator()<Seeding::distance, Distribution::gauss>()
                 : build.template operator()<Seeding::distance, Distribution::uniform>();
  if (cfg.seeding == Seeding::pair_step)
    return gauss ? build.template operator()<Seeding::pair_step, Distribution::gauss>()
                 : build.template operator()<Seeding::pair_step, Distribution::uniform>();
  rng::throw_counter_not_pair_seeding();
}

std::unique_ptr<PairForces> make_tea32(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);
std::unique_ptr<PairForces> make_tea64(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);
std::unique_ptr<PairForces> make_random123(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);
std::unique_ptr<PairForces> make_splitmix(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);
std::unique_ptr<PairForces> make_defect(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);
std::unique_ptr<PairForces> make_saru(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n);

}  // namespace dpdrng::dpd::detail
