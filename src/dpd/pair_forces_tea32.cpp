#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

std::unique_ptr<PairForces> make_tea32(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return rng::with_family_hash<rng::Family::tea32>(
      cfg.generator, [&](const auto& gen) { return make_for_generator(gen, cfg, kernel, n); });
}

}  // namespace dpdrng::dpd::detail
