#include "dpdrng/rng/random123.hpp"
#include "pair_forces_family.hpp"

namespace dpdrng::dpd::detail {

template std::unique_ptr<PairForces> make_hashed<rng::Family::philox4x32, rng::Seeding::distance>(
    const WaterConfig&, const DpdKernel&, std::size_t);
template std::unique_ptr<PairForces> make_hashed<rng::Family::philox4x32, rng::Seeding::pair_step>(
    const WaterConfig&, const DpdKernel&, std::size_t);

}  // namespace dpdrng::dpd::detail
