#include "dpdrng/dpd/system.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace dpdrng::dpd {

void System::resize(std::size_t n) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &fx, &fy, &fz}) v->assign(n, 0.0);
  for (auto* v : {&ix, &iy, &iz}) v->assign(n, 0);
  type.assign(n, 0);
}

namespace {
// floor() rather than one conditional subtraction: a runaway bead may cross several images in one step.
inline void wrap1(double& x, std::int32_t& img, double L) {
  if (x >= 0 && x < L) return;
  // A blown-up bead (non-finite, or so far out that the image count would overflow): park it at 0 so the
  // invariant x in [0, L) that cell lists index by still holds; the run's stability check stops the run.
  if (!(std::abs(x) < 1e9 * L)) {
    x = 0;
    return;
  }
  const double k = std::floor(x / L);
  x -= k * L;
  img += static_cast<std::int32_t>(k);
  if (x >= L) x -= L, ++img;  // x = −tiny rounds to x + L == L
  if (x < 0) x = 0;
}
}  // namespace

void System::wrap() { wrap(0, size()); }

// Each coordinate wraps on its own, so the few that left the box in a step are found a block at a time by a
// count that vectorises, and only a block that has one is visited coordinate by coordinate.
void System::wrap(std::size_t lo, std::size_t hi) {
  constexpr std::size_t kBlock = 32;
  for (int a = 0; a < 3; ++a) {
    double* p = (a == 0 ? x : a == 1 ? y : z).data();
    std::int32_t* img = (a == 0 ? ix : a == 1 ? iy : iz).data();
    const double L = box.L[std::size_t(a)];
    for (std::size_t b = lo; b < hi; b += kBlock) {
      const std::size_t e = std::min(hi, b + kBlock);
      int out = 0;
      for (std::size_t i = b; i < e; ++i) out += !(p[i] >= 0 && p[i] < L);
      if (out == 0) continue;
      for (std::size_t i = b; i < e; ++i) wrap1(p[i], img[i], L);
    }
  }
}

std::array<double, 3> System::momentum() const {
  std::array<double, 3> p{0, 0, 0};
  for (std::size_t i = 0; i < size(); ++i) p[0] += vx[i], p[1] += vy[i], p[2] += vz[i];
  return p;
}

double System::kinetic_twice() const {
  double k = 0;
  for (std::size_t i = 0; i < size(); ++i) k += vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i];
  return k;
}

System make_fluid(std::size_t n, const Box& box, double kT, std::uint64_t seed) {
  System s;
  s.box = box;
  s.resize(n);
  std::mt19937_64 eng(seed);
  // Hand-written transforms rather than std:: distributions, whose output differs between standard libraries.
  auto unit = [&] { return static_cast<double>(eng() >> 11) * 0x1p-53; };
  auto gauss = [&] {
    const double u1 = 1.0 - unit(), u2 = unit();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.141592653589793 * u2);
  };
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = unit() * box.L[0];
    s.y[i] = unit() * box.L[1];
    s.z[i] = unit() * box.L[2];
  }
  const double sd = std::sqrt(kT);
  for (std::size_t i = 0; i < n; ++i) s.vx[i] = sd * gauss(), s.vy[i] = sd * gauss(), s.vz[i] = sd * gauss();
  if (n > 1) {
    const auto p = s.momentum();
    for (std::size_t i = 0; i < n; ++i) s.vx[i] -= p[0] / n, s.vy[i] -= p[1] / n, s.vz[i] -= p[2] / n;
    // Exactly kT at the start, so short runs are not dominated by the first sample's deviation.
    const double scale = std::sqrt(kT * (3.0 * n - 3.0) / s.kinetic_twice());
    for (std::size_t i = 0; i < n; ++i) s.vx[i] *= scale, s.vy[i] *= scale, s.vz[i] *= scale;
  }
  return s;
}

}  // namespace dpdrng::dpd
