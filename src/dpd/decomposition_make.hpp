#pragma once
// Internal to src/dpd: the decomposed forces of one keyed-hash family, explicitly instantiated per family in the
// files cmake/families.cmake writes (decomposition_family.hpp has the definition).
#include <memory>

#include "dpdrng/dpd/decomposition.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::dpd::detail {

template <rng::Family F>
std::unique_ptr<DecomposedForces> make_decomposed(const rng::GeneratorSpec& spec, const DecompNoise& noise,
                                                  const DpdKernel& kernel, const DomainGrid& domains);

}  // namespace dpdrng::dpd::detail
