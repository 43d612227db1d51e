// A DPD pair-force loop that takes its noise from dpdrng::rng: ζ_ij from 32TEA(8) seeded by the bits of the pair
// separation (Okada, Brumby & Yasuoka 2021). Each bead's force is summed from its own side, as a domain owner
// would, and ζ_ji must equal ζ_ij bit for bit (then the forces cancel and momentum is kept).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "dpdrng/rng/seeding.hpp"
#include "dpdrng/rng/tea.hpp"

int main() {
  namespace rng = dpdrng::rng;
  const rng::PairNoise<rng::Tea32<8>, rng::Seeding::distance, rng::Distribution::gauss> noise{};
  const std::uint32_t n = 192;
  const double L = 4.0, a = 25.0, gamma = 6.75, kT = 1.0, dt = 0.04, sigma = std::sqrt(2 * gamma * kT);
  std::mt19937_64 init(2021);
  std::uniform_real_distribution<double> place(0.0, L);
  std::normal_distribution<double> thermal(0.0, std::sqrt(kT));
  std::vector<double> x(3 * n), v(3 * n), f(3 * n, 0.0);
  for (auto& c : x) c = place(init);
  for (auto& c : v) c = thermal(init);
  long pairs = 0, asymmetric = 0;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) {
      if (i == j) continue;
      double d[3], r2 = 0, ev = 0;  // d = r_j − r_i, minimum image
      for (int k = 0; k < 3; ++k) d[k] = x[3 * j + k] - x[3 * i + k], d[k] -= L * std::round(d[k] / L);
      for (int k = 0; k < 3; ++k) r2 += d[k] * d[k];
      if (r2 >= 1.0) continue;  // r_c = 1
      const double r = std::sqrt(r2), w = 1.0 - r;
      const double zeta = noise(rng::canonical({i, j, d[0], d[1], d[2], 0}));
      asymmetric += zeta != noise(rng::canonical({j, i, -d[0], -d[1], -d[2], 0}));
      for (int k = 0; k < 3; ++k) ev += -d[k] / r * (v[3 * i + k] - v[3 * j + k]);  // e_ij · v_ij, e_ij = −d/r
      const double fr = a * w - gamma * w * w * ev + sigma * w * zeta / std::sqrt(dt);
      for (int k = 0; k < 3; ++k) f[3 * i + k] += fr * -d[k] / r;
      ++pairs;
    }
  double net[3] = {0, 0, 0};
  for (std::uint32_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) net[k] += f[3 * i + k];
  const double drift = std::hypot(net[0], net[1], net[2]) / n;  // round-off only when every ζ_ji = ζ_ij
  std::printf("%ld pair evaluations, %ld with zeta_ij != zeta_ji, |net force| / bead = %.3g\n", pairs, asymmetric,
              drift);
  return asymmetric == 0 && drift < 1e-9 ? 0 : 1;
}
