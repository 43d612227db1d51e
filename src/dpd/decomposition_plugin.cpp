// The decomposition check of a plug-in (the listed families' files are written by cmake/families.cmake).
#include "decomposition_family.hpp"

namespace dpdrng::dpd::detail {

template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::plugin>(const rng::GeneratorSpec&,
                                                                                const DecompNoise&, const DpdKernel&,
                                                                                const DomainGrid&);

}  // namespace dpdrng::dpd::detail
