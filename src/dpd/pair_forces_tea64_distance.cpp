#include "dpdrng/rng/tea.hpp"
#include "pair_forces_family.hpp"

namespace dpdrng::dpd::detail {

template std::unique_ptr<PairForces> make_hashed<rng::Family::tea64, rng::Seeding::distance>(
    const WaterConfig&, const DpdKernel&, std::size_t);

}  // namespace dpdrng::dpd::detail
