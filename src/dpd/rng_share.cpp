// The RNG's share of a force evaluation, measured by difference rather than by timing the hash alone: a
// calibration in isolation misses what the generator costs inside the loop (registers, vector width, the
// distribution's latency), and said 19 % at 32 rounds while the step tripled.
#include <algorithm>
#include <chrono>

#include "dpdrng/dpd/pair_forces.hpp"

namespace dpdrng::dpd {

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}  // namespace

double rng_share_by_difference(PairForces& pair, const WaterConfig& cfg, const DpdKernel& kernel, System s,
                               std::uint64_t first_step, double budget_s) {
  using Clock = std::chrono::steady_clock;
  WaterConfig zc = cfg;
  zc.noise_override = NoiseOverride::none;
  zc.taps = {};
  auto zero = make_pair_forces(zc, kernel, s.size());
  const VelocityView v{s.vx.data(), s.vy.data(), s.vz.data()};
  Taps taps;
  std::vector<double> real, none;
  const auto begin = Clock::now();
  // Alternating the two keeps a change of machine load from landing on one side only.
  for (std::uint64_t k = 0; k < 64; ++k) {
    const auto t0 = Clock::now();
    pair.compute(s, v, first_step + k, false, false, false, taps);
    const auto t1 = Clock::now();
    zero->compute(s, v, first_step + k, false, false, false, taps);
    const auto t2 = Clock::now();
    real.push_back(std::chrono::duration<double>(t1 - t0).count());
    none.push_back(std::chrono::duration<double>(t2 - t1).count());
    if (k >= 4 && std::chrono::duration<double>(t2 - begin).count() > budget_s) break;
  }
  const double r = median(real), z = median(none);
  return r > 0 ? std::max(0.0, (r - z) / r) : 0.0;
}

}  // namespace dpdrng::dpd
