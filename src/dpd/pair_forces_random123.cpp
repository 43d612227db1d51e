#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

std::unique_ptr<PairForces> make_random123(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  auto f = [&](const auto& gen) { return make_for_generator(gen, cfg, kernel, n); };
  if (cfg.generator.name == "philox4x32") return rng::detail::dispatch_rounds<rng::Philox4x32, 7, 10>(cfg.generator, f);
  return rng::detail::dispatch_rounds<rng::Threefry2x64, 13, 20>(cfg.generator, f);
}

std::unique_ptr<PairForces> make_splitmix(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return make_for_generator(rng::SplitMix64<1>{}, cfg, kernel, n);
}

}  // namespace dpdrng::dpd::detail
