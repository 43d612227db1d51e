#pragma once
// Internal to src/dpd: the decomposed force loop (decomposition.hpp) for one keyed hash, and make_decomposed,
// which picks the family's hash. The check's time goes to its geometry (two views of every pair), not to the
// hash: every round count runs the runtime-rounds hash and the distribution is a run-time field, so there is one
// instantiation per generator type. The families of each generator header are instantiated in a file of their own
// (written by cmake/families.cmake; the plug-in's is decomposition_plugin.cpp), which includes only that header, so
// that a generator header rebuilds only its own families'.
#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <vector>

#include "decomposition_make.hpp"
#include "dpdrng/rng/seeding_repair.hpp"

namespace dpdrng::dpd::detail {

// Internal linkage: each family's file compiles its own instantiations.
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <class G>
class Decomposed final : public DecomposedForces {
 public:
  Decomposed(G gen, const DecompNoise& noise, const DpdKernel& k, const DomainGrid& g)
      : gen_(gen),
        seed_(noise.seed),
        seeding_(noise.seeding),
        feed_(noise.feed),
        distribution_(noise.distribution),
        k_(k),
        g_(g) {}

  int words_per_pair() const override { return G::kWords; }

  std::array<std::uint64_t, 2> raw(const System& s, std::uint32_t i, std::uint32_t j,
                                   std::uint64_t step) const override {
    const rng::PairInput p = canonical_input(s, i, j, step);
    const auto b = block(p, p);
    std::array<std::uint64_t, 2> out{b[0], 0};
    if constexpr (G::kWords > 1) out[1] = b[1];
    return out;
  }

  ForceSums compute(System& s, VelocityView v, std::uint64_t step, BoundaryStats* stats,
                    std::vector<BoundaryPair>* pairs) override {
    const std::size_t n = s.size();
    dom_.resize(n);
    for (std::size_t i = 0; i < n; ++i) dom_[i] = g_.domain_of(s.box, s.x[i], s.y[i], s.z[i]);
    std::fill(s.fx.begin(), s.fx.end(), 0.0);
    std::fill(s.fy.begin(), s.fy.end(), 0.0);
    std::fill(s.fz.begin(), s.fz.end(), 0.0);
    if (pairs) pairs->clear();
    BoundaryStats st;
    st.evaluations = 1;
    ForceSums sums;
    sums.min_r2 = k_.rc2();
    const double rc2 = k_.rc2(), sig = k_.sigma * k_.inv_sqrt_dt;
    const double a_ij = k_.a[0];
    const double grid_scale = std::ldexp(1.0, seeding_.grid_bits);
    // The views differ from the minimum image by a few ulps, so this margin only skips pairs neither owner
    // can see inside r_c, before paying for two views.
    const double prefilter = rc2 * (1 + 1e-9);
    const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const double ux = min_image(s.x[j] - s.x[i], Lx, Lx / 2), uy = min_image(s.y[j] - s.y[i], Ly, Ly / 2),
                     uz = min_image(s.z[j] - s.z[i], Lz, Lz / 2);
        if (!(ux * ux + uy * uy + uz * uz < prefilter)) continue;
        const PairView a = view_from(s, g_, i, j);  // the owner of i
        const PairView bj = view_from(s, g_, j, i);  // the owner of j: r_i − r_j
        const double r2a = a.r2(), r2b = bj.r2();
        const bool in_a = r2a < rc2, in_b = r2b < rc2;
        if (!in_a && !in_b) continue;
        ++st.in_range;
        const double dvx = v.vx[j] - v.vx[i], dvy = v.vy[j] - v.vy[i], dvz = v.vz[j] - v.vz[i];
        const rng::PairInput canon = canonical_input(s, i, j, step);
        double za = 0, zb = 0;
        PairForce fa{0, 0, 0}, fb{0, 0, 0};
        if (in_a) {
          za = zeta(rng::PairInput{i, j, a.d[0], a.d[1], a.d[2], step}, canon);
          fa = DpdKernel::evaluate(r2a, a.d[0], a.d[1], a.d[2], dvx, dvy, dvz, a_ij, za, k_.rc, k_.gamma, sig);
          s.fx[i] += fa.s * a.d[0], s.fy[i] += fa.s * a.d[1], s.fz[i] += fa.s * a.d[2];
          add_virial(sums, fa, a, r2a);
          sums.min_r2 = std::min(sums.min_r2, r2a);
        }
        if (in_b) {
          // B hashes the pair in canonical order (i < j, r_j − r_i), i.e. x_j − ghost_i. 0 − d is that value
          // exactly, and +0.0 (not −0.0) where the two coordinates coincide, as the direct subtraction gives.
          zb = zeta(rng::PairInput{i, j, 0.0 - bj.d[0], 0.0 - bj.d[1], 0.0 - bj.d[2], step}, canon);
          fb = DpdKernel::evaluate(r2b, bj.d[0], bj.d[1], bj.d[2], -dvx, -dvy, -dvz, a_ij, zb, k_.rc, k_.gamma, sig);
          s.fx[j] += fb.s * bj.d[0], s.fy[j] += fb.s * bj.d[1], s.fz[j] += fb.s * bj.d[2];
          add_virial(sums, fb, bj, r2b);
          sums.min_r2 = std::min(sums.min_r2, r2b);
        }
        if (dom_[i] == dom_[j]) continue;
        ++st.boundary;
        if (a.shifted()) ++st.shifted;
        bool sep_differs = false;
        for (int c = 0; c < 3; ++c) {
          sep_differs |= !same_bits(a.d[c], 0.0 - bj.d[c]);
          if (seeding_.kind == DecompSeedingKind::grid)
            st.grid_straddle_expected += std::min(1.0, std::fabs(a.d[c] + bj.d[c]) * grid_scale);
        }
        st.separation_mismatch += sep_differs;
        if (in_a != in_b) {
          ++st.range_mismatch;
        } else if (!same_bits(za, zb)) {
          ++st.zeta_mismatch;
          const double dz = std::fabs(za - zb);
          st.zeta_diff_sum += dz, st.zeta_diff_sum2 += dz * dz;
          st.zeta_diff_max = std::max(st.zeta_diff_max, dz);
        }
        const double mx = fa.s * a.d[0] + fb.s * bj.d[0], my = fa.s * a.d[1] + fb.s * bj.d[1],
                     mz = fa.s * a.d[2] + fb.s * bj.d[2];
        st.force_mismatch_max = std::max(st.force_mismatch_max, std::sqrt(mx * mx + my * my + mz * mz));
        if (pairs) {
          BoundaryPair bp;
          bp.i = i, bp.j = j, bp.domain_i = dom_[i], bp.domain_j = dom_[j];
          bp.a = a;
          bp.b = bj;
          for (int c = 0; c < 3; ++c) bp.b.d[c] = 0.0 - bj.d[c], bp.b.shift[c] = -bj.shift[c];
          bp.in_a = in_a, bp.in_b = in_b, bp.zeta_a = za, bp.zeta_b = zb;
          pairs->push_back(bp);
        }
      }
    }
    for (int c = 0; c < 3; ++c) sums.virial[c] *= 0.5, sums.virial_cons[c] *= 0.5;
    sums.in_range = st.in_range;
    sums.numbers = 2 * st.in_range;
    double net[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) net[0] += s.fx[i], net[1] += s.fy[i], net[2] += s.fz[i];
    const double nf = std::sqrt(net[0] * net[0] + net[1] * net[1] + net[2] * net[2]) / double(n);
    st.net_force_max = nf, st.net_force_sum2 = nf * nf;
    if (stats) stats->merge(st);
    return sums;
  }

 private:
  using Block = typename G::Block;

  // The undecomposed separation min_image(x_j − x_i), i < j, from the wrapped coordinates both owners hold.
  static rng::PairInput canonical_input(const System& s, std::uint32_t i, std::uint32_t j, std::uint64_t step) {
    const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
    return {i, j, min_image(s.x[j] - s.x[i], Lx, Lx / 2), min_image(s.y[j] - s.y[i], Ly, Ly / 2),
            min_image(s.z[j] - s.z[i], Lz, Lz / 2), step};
  }

  Block block(const rng::PairInput& seen, const rng::PairInput& canon) const {
    switch (seeding_.kind) {
      case DecompSeedingKind::distance: return rng::pair_block<rng::Seeding::distance>(gen_, seen, seed_);
      case DecompSeedingKind::pair_step: return rng::pair_block<rng::Seeding::pair_step>(gen_, seen, seed_);
      case DecompSeedingKind::grid: return rng::grid_block(gen_, seen, seeding_.grid_bits);
      case DecompSeedingKind::canonical: return rng::pair_block<rng::Seeding::distance>(gen_, canon, seed_);
    }
    return {};
  }
  // Under the blocks feed both owners hash the second block from their own view, rotated (rng::second_input).
  double zeta(const rng::PairInput& seen, const rng::PairInput& canon) const {
    const Block a = block(seen, canon);
    const Block b = feed_ == rng::Feed::blocks ? block(rng::second_input(seen), rng::second_input(canon)) : a;
    if (distribution_ == rng::Distribution::gauss) return rng::draw<rng::Distribution::gauss>(feed_, a, b);
    return rng::draw<rng::Distribution::uniform>(feed_, a, b);
  }

  // r_ij = −d, F_ij = s·d: (r_ij)_α (F_ij)_α = −s d_α²; conservative part a w d_α² / r (as PairLoop).
  static void add_virial(ForceSums& sums, const PairForce& f, const PairView& v, double r2) {
    for (int c = 0; c < 3; ++c) {
      sums.virial[c] -= f.s * v.d[c] * v.d[c];
      sums.virial_cons[c] += DpdKernel::conservative_weight(f, r2) * v.d[c] * v.d[c];
    }
  }

  G gen_;
  std::uint64_t seed_;
  DecompSeeding seeding_;
  rng::Feed feed_;
  rng::Distribution distribution_;
  DpdKernel k_;
  DomainGrid g_;
  std::vector<int> dom_;
};

}  // namespace

template <rng::Family F>
std::unique_ptr<DecomposedForces> make_decomposed(const rng::GeneratorSpec& spec, const DecompNoise& noise,
                                                  const DpdKernel& kernel, const DomainGrid& domains) {
  return rng::with_family_hash_any_rounds<F>(spec, [&]<class G>(const G& gen) -> std::unique_ptr<DecomposedForces> {
    return std::make_unique<Decomposed<G>>(gen, noise, kernel, domains);
  });
}

}  // namespace dpdrng::dpd::detail
