#include "dpdrng/dpd/decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "decomposition_make.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/defect.hpp"

namespace dpdrng::dpd {

int DomainGrid::domain_of(const Box& box, double x, double y, double z) const {
  const double p[3] = {x, y, z};
  int c[3];
  for (int a = 0; a < 3; ++a) {
    // The clamp keeps a bead at x = L − tiny, whose x·n/L may round up to n, in the last domain.
    const int k = static_cast<int>(std::floor(p[a] * n[a] / box.L[a]));
    c[a] = std::clamp(k, 0, n[a] - 1);
  }
  return (c[0] * n[1] + c[1]) * n[2] + c[2];
}

void BoundaryStats::merge(const BoundaryStats& o) {
  evaluations += o.evaluations;
  in_range += o.in_range;
  boundary += o.boundary;
  shifted += o.shifted;
  separation_mismatch += o.separation_mismatch;
  range_mismatch += o.range_mismatch;
  zeta_mismatch += o.zeta_mismatch;
  zeta_diff_sum += o.zeta_diff_sum;
  zeta_diff_sum2 += o.zeta_diff_sum2;
  zeta_diff_max = std::max(zeta_diff_max, o.zeta_diff_max);
  force_mismatch_max = std::max(force_mismatch_max, o.force_mismatch_max);
  net_force_max = std::max(net_force_max, o.net_force_max);
  net_force_sum2 += o.net_force_sum2;
  grid_straddle_expected += o.grid_straddle_expected;
}

double BoundaryStats::zeta_diff_rms() const { return zeta_mismatch ? std::sqrt(zeta_diff_sum2 / zeta_mismatch) : 0.0; }
double BoundaryStats::net_force_rms() const { return evaluations ? std::sqrt(net_force_sum2 / evaluations) : 0.0; }

std::unique_ptr<DecomposedForces> make_decomposed_forces(const DecompNoise& noise, const DpdKernel& kernel,
                                                         const DomainGrid& domains) {
  if (kernel.ntypes != 1) throw InputError("the decomposition check runs one-type scenes (water) only");
  const rng::GeneratorSpec spec = rng::validated(noise.generator);
  if (!rng::find_generator(spec.name).keyed_hash)
    throw InputError("decompose needs a keyed hash: '" + spec.name +
                     "' is a sequential stream, which cannot give two domains the same number without a message");
  if (rng::is_defect(spec.name) && rng::parse_defect(spec.name).lag1 != 0)
    throw InputError("decompose: a lag-1 defect is not supported (it needs the step in every seeding)");
  // Every decomposition seeding but pair-step hashes a separation (grid and canonical included).
  rng::check_seeding(spec, noise.seeding.kind == DecompSeedingKind::pair_step ? rng::Seeding::pair_step
                                                                              : rng::Seeding::distance);
  return rng::visit_keyed_family(rng::family_of(spec.name), spec.name, [&]<rng::Family F>() {
    return detail::make_decomposed<F>(spec, noise, kernel, domains);
  });
}

}  // namespace dpdrng::dpd
