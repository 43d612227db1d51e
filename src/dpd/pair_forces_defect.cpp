#include "dpdrng/rng/defect.hpp"
#include "pair_forces_family.hpp"

namespace dpdrng::dpd::detail {

// One instantiation per seeding × distribution: the defect's size is a run-time parameter of the generator.
template std::unique_ptr<PairForces> make_hashed<rng::Family::defect, rng::Seeding::distance>(
    const WaterConfig&, const DpdKernel&, std::size_t);
template std::unique_ptr<PairForces> make_hashed<rng::Family::defect, rng::Seeding::pair_step>(
    const WaterConfig&, const DpdKernel&, std::size_t);

}  // namespace dpdrng::dpd::detail
