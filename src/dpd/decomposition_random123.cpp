#include "decomposition_family.hpp"
#include "dpdrng/rng/random123.hpp"

namespace dpdrng::dpd::detail {

template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::philox4x32>(const rng::GeneratorSpec&,
                                                                                    const DecompNoise&,
                                                                                    const DpdKernel&,
                                                                                    const DomainGrid&);
template std::unique_ptr<DecomposedForces> make_decomposed<rng::Family::threefry2x64>(const rng::GeneratorSpec&,
                                                                                      const DecompNoise&,
                                                                                      const DpdKernel&,
                                                                                      const DomainGrid&);

}  // namespace dpdrng::dpd::detail
