#include "decomposition_family.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng::dpd::detail {

template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::tea32>(const rng::GeneratorSpec&,
                                                                               const DecompNoise&, const DpdKernel&,
                                                                               const DomainGrid&);
template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::tea64>(const rng::GeneratorSpec&,
                                                                               const DecompNoise&, const DpdKernel&,
                                                                               const DomainGrid&);

}  // namespace dpdrng::dpd::detail
