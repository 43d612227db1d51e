#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

std::unique_ptr<PairForces> make_saru(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  // key[0] enters the distance seeding
  return rng::with_family_hash<rng::Family::saru>(
      cfg.generator, [&](const auto& gen) { return make_for_generator(gen, cfg, kernel, n); });
}

}  // namespace dpdrng::dpd::detail
