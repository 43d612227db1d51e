#include "pair_forces_make.hpp"

namespace dpdrng::dpd::detail {

// One instantiation per seeding × distribution: the defect's size is a run-time parameter of the generator.
std::unique_ptr<PairForces> make_defect(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  rng::check_defect_seeding(cfg.generator, cfg.seeding);
  rng::Defect gen;
  gen.key = cfg.generator.key;
  gen.p = rng::parse_defect(cfg.generator.name);
  return make_for_generator(gen, cfg, kernel, n);
}

}  // namespace dpdrng::dpd::detail
