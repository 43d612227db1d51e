#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

std::unique_ptr<PairForces> make_tea64(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return rng::detail::dispatch_rounds<rng::Tea64, 1, 2, 3, 4, 5, 6, 8, 16, 32>(
      cfg.generator, [&](const auto& gen) { return make_for_generator(gen, cfg, kernel, n); });
}

}  // namespace dpdrng::dpd::detail
