// The one place where the run-time noise choice becomes a noise kernel for the pair loop (the keyed hashes'
// kernels in their families' files, pair_forces_make.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "noise_kernel.hpp"
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

namespace detail {
std::unique_ptr<PairForces> pair_loop_for(std::unique_ptr<NoiseKernel> noise, const WaterConfig& cfg,
                                          const DpdKernel& kernel, std::size_t n) {
  // The pair series are tapped on the production steps.
  const std::int64_t production = std::max<std::int64_t>(0, cfg.steps - cfg.equilibrate);
  const auto series_steps = cfg.taps.pairs.empty() ? std::size_t{0} : static_cast<std::size_t>(production);
  return make_pair_loop(std::move(noise), kernel, cfg.pairs, cfg.threads, n, cfg.taps.pairs, series_steps);
}
}  // namespace detail

namespace {
template <class Noise>
std::unique_ptr<PairForces> loop(Noise noise, const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  return detail::pair_loop_for(make_noise_kernel(std::move(noise)), cfg, kernel, n);
}

template <rng::Family F>
std::unique_ptr<PairForces> hashed(const WaterConfig& cfg, const DpdKernel& kernel, std::size_t n) {
  if (cfg.seeding == rng::Seeding::distance) return detail::make_hashed<F, rng::Seeding::distance>(cfg, kernel, n);
  if (cfg.seeding == rng::Seeding::pair_step) return detail::make_hashed<F, rng::Seeding::pair_step>(cfg, kernel, n);
  rng::throw_counter_not_pair_seeding();
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
  cfg.threads = team_threads(cfg.threads, n, cfg.team_beads);
  const bool gauss = cfg.distribution == rng::Distribution::gauss;
  const rng::Family family = rng::family_of(cfg.generator.name);
  if (cfg.noise_override != NoiseOverride::off || family == rng::Family::mt19937)
    return gauss ? baseline_or_stream<rng::Distribution::gauss>(cfg, kernel, n)
                 : baseline_or_stream<rng::Distribution::uniform>(cfg, kernel, n);
  // A defect's or a plug-in's limits under the seeding, refused before the kernel is built.
  rng::check_seeding(cfg.generator, cfg.seeding);
  return rng::visit_keyed_family(family, cfg.generator.name,
                                 [&]<rng::Family F>() { return hashed<F>(cfg, kernel, n); });
}

}  // namespace dpdrng::dpd
