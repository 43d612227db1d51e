#include "dpdrng/dpd/bonded.hpp"

#include <algorithm>
#include <cmath>

namespace dpdrng::dpd {

namespace {
double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void separation(const System& s, std::uint32_t i, std::uint32_t j, double d[3]) {
  const auto& L = s.box.L;
  d[0] = min_image(s.x[j] - s.x[i], L[0], 0.5 * L[0]);
  d[1] = min_image(s.y[j] - s.y[i], L[1], 0.5 * L[1]);
  d[2] = min_image(s.z[j] - s.z[i], L[2], 0.5 * L[2]);
}

// One pass for both add() and measure(), so the forces and the numbers reported with them cannot disagree.
template <bool Apply>
BondedSums visit(const BondedForces& bf, const System& cs, System* s, const Topology& t) {
  BondedSums out;
  for (const auto& b : t.bonds) {
    double d[3];
    separation(cs, b[0], b[1], d);
    const double r = std::sqrt(dot(d, d));
    out.max_bond = std::max(out.max_bond, r);
    if (!(r > 0)) continue;
    out.energy_bond += bf.bond.energy(r);
    const double sc = bf.bond.scale(r);
    // W = r_i·F_i + r_j·F_j = d·F_j = s d_α² per direction.
    for (int a = 0; a < 3; ++a) out.virial_bond[a] += sc * d[a] * d[a];
    if constexpr (Apply) {
      s->fx[b[1]] += sc * d[0], s->fy[b[1]] += sc * d[1], s->fz[b[1]] += sc * d[2];
      s->fx[b[0]] -= sc * d[0], s->fy[b[0]] -= sc * d[1], s->fz[b[0]] -= sc * d[2];
    }
  }
  for (const auto& a3 : t.angles) {
    double b1[3], b2[3];
    separation(cs, a3[0], a3[1], b1);
    separation(cs, a3[1], a3[2], b2);
    const CosineBend::Forces f = bf.bend.forces(b1, b2);
    out.energy_bend += f.energy;
    // Σ r_i·F_i with F_2 = −F_1 − F_3: (r_1 − r_2)·F_1 + (r_3 − r_2)·F_3 = −b1·F_1 + b2·F_3.
    for (int a = 0; a < 3; ++a) out.virial_bend[a] += -b1[a] * f.f1[a] + b2[a] * f.f3[a];
    if constexpr (Apply) {
      s->fx[a3[0]] += f.f1[0], s->fy[a3[0]] += f.f1[1], s->fz[a3[0]] += f.f1[2];
      s->fx[a3[2]] += f.f3[0], s->fy[a3[2]] += f.f3[1], s->fz[a3[2]] += f.f3[2];
      s->fx[a3[1]] -= f.f1[0] + f.f3[0], s->fy[a3[1]] -= f.f1[1] + f.f3[1], s->fz[a3[1]] -= f.f1[2] + f.f3[2];
    }
  }
  return out;
}
}  // namespace

double CosineBend::energy(const double b1[3], const double b2[3]) const {
  const double n = std::sqrt(dot(b1, b1) * dot(b2, b2));
  if (!(n > 0)) return 0.0;
  return k * (1.0 - dot(b1, b2) / n);
}

CosineBend::Forces CosineBend::forces(const double b1[3], const double b2[3]) const {
  Forces f{{0, 0, 0}, {0, 0, 0}, 0.0};
  const double q1 = dot(b1, b1), q2 = dot(b2, b2);
  if (!(q1 > 0) || !(q2 > 0)) return f;
  const double inv_n = 1.0 / std::sqrt(q1 * q2);
  const double c = dot(b1, b2) * inv_n;
  f.energy = k * (1.0 - c);
  // U = k(1 − c), b1 = r_2 − r_1, b2 = r_3 − r_2:  F_1 = −k ∂c/∂b1,  F_3 = +k ∂c/∂b2, with
  // ∂c/∂b1 = b2/(|b1||b2|) − c b1/|b1|²  and  ∂c/∂b2 = b1/(|b1||b2|) − c b2/|b2|².
  for (int a = 0; a < 3; ++a) {
    f.f1[a] = -k * (b2[a] * inv_n - c * b1[a] / q1);
    f.f3[a] = k * (b1[a] * inv_n - c * b2[a] / q2);
  }
  return f;
}

BondedSums BondedForces::add(System& s, const Topology& t) const { return visit<true>(*this, s, &s, t); }

BondedSums BondedForces::measure(const System& s, const Topology& t) const {
  return visit<false>(*this, s, nullptr, t);
}

}  // namespace dpdrng::dpd
