// The RNG's share of a force evaluation, measured by difference rather than by timing the hash alone: a
// calibration in isolation misses what the generator costs inside the loop (registers, vector width, the
// distribution's latency): it can report 19 % at 32 rounds for a step that the generator triples.
#include <algorithm>
#include <chrono>
#include <limits>

#include "dpdrng/dpd/pair_forces.hpp"

namespace dpdrng::dpd {

double rng_share_by_difference(PairForces& pair, const WaterConfig& cfg, const DpdKernel& kernel, System s,
                               std::uint64_t first_step, double budget_s) {
  using Clock = std::chrono::steady_clock;
  WaterConfig zc = cfg;
  zc.noise_override = NoiseOverride::none;
  zc.taps = {};
  auto zero = make_pair_forces(zc, kernel, s.size());
  const VelocityView v{s.vx.data(), s.vy.data(), s.vz.data()};
  Taps taps;
  // Each side's fastest evaluation: interference from the machine only ever adds time, so the minimum is the
  // least disturbed of the repeats (the engine keeps no statistics; this is a timing, not an estimate of a mean).
  double real = std::numeric_limits<double>::infinity(), none = real;
  const auto begin = Clock::now();
  // Alternating the two keeps a change of machine load from landing on one side only.
  for (std::uint64_t k = 0; k < 64; ++k) {
    const auto t0 = Clock::now();
    pair.compute(s, v, first_step + k, false, false, false, taps);
    const auto t1 = Clock::now();
    zero->compute(s, v, first_step + k, false, false, false, taps);
    const auto t2 = Clock::now();
    real = std::min(real, std::chrono::duration<double>(t1 - t0).count());
    none = std::min(none, std::chrono::duration<double>(t2 - t1).count());
    if (k >= 4 && std::chrono::duration<double>(t2 - begin).count() > budget_s) break;
  }
  return real > 0 ? std::max(0.0, (real - none) / real) : 0.0;
}

}  // namespace dpdrng::dpd
