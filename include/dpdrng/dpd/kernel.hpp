#pragma once
// The Groot–Warren pair force as a small value type: the pair loop, the future domain-decomposition check
// (which evaluates a boundary pair with the separation its ghost copy sees) and the bilayer scene all call
// the same evaluate(). Conventions: d = r_j − r_i (minimum image or ghost-shifted), dv = v_j − v_i; the
// result is the force on i (the force on j is its negative).
//   F_i = [ −a_ij w  +  γ w² (ê·dv)  −  σ w ζ / √Δt ] ê,   ê = d / r,  w = 1 − r / r_c,  σ² = 2γk_BT
// which is Groot & Warren (1997) eq. 2–4 written with e_ij = −ê and v_ij = −dv.
#include <cmath>
#include <cstdint>
#include <vector>

namespace dpdrng::dpd {

struct PairForce {
  double s;    // F_i = s · d
  double a_w;  // a_ij·w·r = r_ij·F^C_ij, the conservative virial of the pair
  double w;    // 1 − r/r_c, the weight w_R with which the pair's ζ enters the force
};

struct DpdKernel {
  double rc = 1.0;
  double gamma = 4.5;
  double sigma = 3.0;
  double inv_sqrt_dt = 5.0;
  int ntypes = 1;
  std::vector<double> a{25.0};  // ntypes × ntypes, symmetric

  double rc2() const { return rc * rc; }
  double a_of(std::uint8_t ti, std::uint8_t tj) const { return a[std::size_t(ti) * ntypes + tj]; }

  // r2 must be in [0, r_c²). Two beads at one position (r = 0) have no direction between them: the pair is
  // skipped, as LAMMPS's pair style dpd skips r below 1e-10, and gives {0, 0} (no force, no virial, no NaN). The
  // select keeps every r > 0 pair's arithmetic as it is.
  static inline PairForce evaluate(double r2, double dx, double dy, double dz, double dvx, double dvy, double dvz,
                                   double a, double zeta, double rc, double gamma, double sigma_over_sqrt_dt) {
    const double r = std::sqrt(r2);
    const double inv_r = r2 > 0 ? 1.0 / r : 0.0;
    const double w = 1.0 - r / rc;
    const double e_dv = (dx * dvx + dy * dvy + dz * dvz) * inv_r;
    const double mag = -a * w + gamma * w * w * e_dv - sigma_over_sqrt_dt * w * zeta;
    return {mag * inv_r, a * w * r, w};
  }
  // a·w/r, the conservative virial per d_α² (r_α F^C_α = this · d_α²); 0 for a skipped pair at r = 0.
  static inline double conservative_weight(const PairForce& pf, double r2) { return r2 > 0 ? pf.a_w / r2 : 0.0; }
  // The conservative potential u(r) = (a/2) r_c w² has u' = −a w and u'' = a/r_c, so its Laplacian in 3D,
  // u'' + 2u'/r, is a/r_c − 2 a w / r = a/r_c − 2 · conservative_weight (0 for a skipped pair at r = 0). A
  // bead's ∇_i²U sums this over its partners, so Σ_i ∇_i²U is twice the sum over pairs.
  static inline double conservative_laplacian(const PairForce& pf, double r2, double a, double inv_rc) {
    return r2 > 0 ? a * inv_rc - 2.0 * conservative_weight(pf, r2) : 0.0;
  }
  PairForce operator()(double r2, double dx, double dy, double dz, double dvx, double dvy, double dvz, double a,
                       double zeta) const {
    return evaluate(r2, dx, dy, dz, dvx, dvy, dvz, a, zeta, rc, gamma, sigma * inv_sqrt_dt);
  }
};

// σ from γ and k_BT by the fluctuation–dissipation relation σ² = 2γk_BT (Español & Warren 1995).
DpdKernel make_kernel(double a, double rc, double gamma, double kT, double dt);

}  // namespace dpdrng::dpd
