#include "dpdrng/rng/plugin.hpp"
#include "pair_forces_family.hpp"

namespace dpdrng::dpd::detail {

template std::unique_ptr<PairForces> make_hashed<rng::Family::plugin, rng::Seeding::distance>(
    const WaterConfig&, const DpdKernel&, std::size_t);
template std::unique_ptr<PairForces> make_hashed<rng::Family::plugin, rng::Seeding::pair_step>(
    const WaterConfig&, const DpdKernel&, std::size_t);

}  // namespace dpdrng::dpd::detail
