#include "decomposition_family.hpp"
#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/saru.hpp"
#include "dpdrng/rng/splitmix.hpp"

namespace dpdrng::dpd::detail {

// The families without a round count.
template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::splitmix64>(const rng::GeneratorSpec&,
                                                                                    const DecompNoise&,
                                                                                    const DpdKernel&,
                                                                                    const DomainGrid&);
template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::saru>(const rng::GeneratorSpec&,
                                                                              const DecompNoise&, const DpdKernel&,
                                                                              const DomainGrid&);
template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::plugin>(const rng::GeneratorSpec&,
                                                                                const DecompNoise&, const DpdKernel&,
                                                                                const DomainGrid&);
template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::defect>(const rng::GeneratorSpec&,
                                                                                const DecompNoise&, const DpdKernel&,
                                                                                const DomainGrid&);

}  // namespace dpdrng::dpd::detail
