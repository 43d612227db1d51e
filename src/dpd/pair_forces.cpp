// The one place where the run-time noise choice becomes a noise kernel for the pair loop (hash families in their
// own files).
#include <cmath>

#include "pair_forces_make.hpp"

namespace dpdrng::dpd {

DpdKernel make_kernel(double a, double rc, double gamma, double kT, double dt) {
  DpdKernel k;
  k.rc = rc;
  k.gamma = gamma;
  k.sigma = std::sqrt(2.0 * gamma * kT);
  k.inv_sqrt_dt = 1.0 / std::sqrt(dt);
  k.ntypes = 1;
  k.a = {a};
  return k;
}

namespace {
template <class Noise>
std::unique_ptr<PairForces> loop(Noise noise, const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return make_pair_loop(make_noise_kernel(std::move(noise)), kernel, cfg.pairs, cfg.threads, n, cfg.taps.pairs);
}

template <rng::Distribution D>
std::unique_ptr<PairForces> baseline_or_stream(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  if (cfg.noise_override == NoiseOverride::none) return loop(ZeroNoise{}, cfg, kernel, n);
  if (cfg.noise_override == NoiseOverride::unhashed) return loop(UnhashedNoise<D>{cfg.feed}, cfg, kernel, n);
  return loop(StreamNoise<D>(cfg.seed, cfg.feed), cfg, kernel, n);
}
}  // namespace

std::unique_ptr<PairForces> make_pair_forces(const WaterConfig& in, const DpdKernel& kernel, std::size_t n) {
  WaterConfig cfg = in;
  cfg.generator = rng::validated(in.generator);
  if (cfg.threads <= 0) cfg.threads = omp_get_max_threads();
  const bool gauss = cfg.distribution == rng::Distribution::gauss;
  const rng::Family family = rng::family_of(cfg.generator.name);
  if (cfg.noise_override != NoiseOverride::off || family == rng::Family::mt19937)
    return gauss ? baseline_or_stream<rng::Distribution::gauss>(cfg, kernel, n)
                 : baseline_or_stream<rng::Distribution::uniform>(cfg, kernel, n);
  switch (family) {
    case rng::Family::tea32: return detail::make_tea32(cfg, kernel, n);
    case rng::Family::tea64: return detail::make_tea64(cfg, kernel, n);
    case rng::Family::philox4x32:
    case rng::Family::threefry2x64: return detail::make_random123(cfg, kernel, n);
    case rng::Family::splitmix64: return detail::make_splitmix(cfg, kernel, n);
    case rng::Family::saru: return detail::make_saru(cfg, kernel, n);
    case rng::Family::defect: return detail::make_defect(cfg, kernel, n);
    case rng::Family::mt19937: break;
  }
  rng::throw_not_keyed_hash(cfg.generator.name);
}

}  // namespace dpdrng::dpd
