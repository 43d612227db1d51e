#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

std::unique_ptr<PairForces> make_random123(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  auto f = [&](const auto& gen) { return make_for_generator(gen, cfg, kernel, n); };
  if (rng::family_of(cfg.generator.name) == rng::Family::philox4x32)
    return rng::with_family_hash<rng::Family::philox4x32>(cfg.generator, f);
  return rng::with_family_hash<rng::Family::threefry2x64>(cfg.generator, f);
}

std::unique_ptr<PairForces> make_splitmix(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return rng::with_family_hash<rng::Family::splitmix64>(
      cfg.generator, [&](const auto& gen) { return make_for_generator(gen, cfg, kernel, n); });
}

}  // namespace dpdrng::dpd::detail
