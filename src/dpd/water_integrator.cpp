#include "dpdrng/dpd/water_integrator.hpp"

#include "dpdrng/dpd/pnhl.hpp"
#include "dpdrng/dpd/self_consistent.hpp"
#include "dpdrng/dpd/shardlow.hpp"

namespace dpdrng::dpd {

namespace {

bool conservative_only(Integrator i) { return i == Integrator::shardlow || i == Integrator::pnhln; }

}  // namespace

WaterIntegrator::WaterIntegrator(const WaterConfig& cfg) : mvv_(cfg.dt, cfg.lambda, cfg.threads) {
  switch (cfg.integrator) {
    case Integrator::mvv:
      break;
    case Integrator::shardlow:
      s1_ = std::make_unique<ShardlowS1>(cfg);
      break;
    case Integrator::scmvv: {
      sc_ = std::make_unique<SelfConsistentVerlet>(cfg.dt, cfg.scmvv_iterations, cfg.threads);
      WaterConfig d = cfg;
      d.noise_override = NoiseOverride::none;
      d.taps = {};
      dissipative_ = make_pair_forces(d, make_kernel(0.0, cfg.rc, cfg.gamma, cfg.kT, cfg.dt),
                                      static_cast<std::size_t>(cfg.particles));
      break;
    }
    case Integrator::pnhln:
      pnhl_ = std::make_unique<PairwiseNoseHooverLangevin>(cfg);
      break;
  }
}

WaterIntegrator::~WaterIntegrator() = default;

ForceSums WaterIntegrator::start(System& s, const ForceFn& force) {
  if (s1_) return s1_->start(s, force);
  if (sc_) return sc_->start(s, force);
  if (pnhl_) return pnhl_->start(s, force);
  return mvv_.start(s, force);
}

ForceSums WaterIntegrator::step(System& s, const ForceFn& force) {
  if (s1_) return s1_->step(s, force);
  if (sc_) {
    const ForceFn dissipative = [this](System& sys, VelocityView v) {
      return dissipative_->compute(sys, v, 0, false, false, false, no_taps_);
    };
    return sc_->step(s, force, dissipative);
  }
  if (pnhl_) return pnhl_->step(s, force);
  return mvv_.step(s, force);
}

WaterConfig pair_force_config(const WaterConfig& cfg) {
  WaterConfig c = cfg;
  if (conservative_only(cfg.integrator)) c.noise_override = NoiseOverride::none;
  return c;
}

DpdKernel pair_force_kernel(const WaterConfig& cfg) {
  const double gamma = conservative_only(cfg.integrator) ? 0.0 : cfg.gamma;
  return make_kernel(cfg.a, cfg.rc, gamma, cfg.kT, cfg.dt);
}

}  // namespace dpdrng::dpd
