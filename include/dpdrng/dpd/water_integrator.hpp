#pragma once
// The water scene's integrator, chosen by cfg.integrator: Groot–Warren MVV (integrator.hpp), Shardlow's S1
// (shardlow.hpp), the self-consistent velocity-Verlet (self_consistent.hpp) or the pairwise Nosé–Hoover–Langevin
// thermostat (pnhl.hpp), behind one start/step interface. The scene's force callback computes the pair forces of
// pair_force_config / pair_force_kernel; scmvv's dissipative-only passes run on a pair loop of the integrator's own.
#include <memory>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/dpd/integrator.hpp"
#include "dpdrng/dpd/kernel.hpp"
#include "dpdrng/dpd/pair_forces.hpp"

namespace dpdrng::dpd {

class ShardlowS1;
class SelfConsistentVerlet;
class PairwiseNoseHooverLangevin;

class WaterIntegrator {
 public:
  // threads must be resolved (> 0).
  explicit WaterIntegrator(const WaterConfig& cfg);
  ~WaterIntegrator();
  ForceSums start(System& s, const ForceFn& force);
  ForceSums step(System& s, const ForceFn& force);

 private:
  ModifiedVelocityVerlet mvv_;
  std::unique_ptr<ShardlowS1> s1_;
  std::unique_ptr<SelfConsistentVerlet> sc_;
  std::unique_ptr<PairForces> dissipative_;  // scmvv: F^D alone (no conservative force, no noise)
  std::unique_ptr<PairwiseNoseHooverLangevin> pnhl_;
  Taps no_taps_;
};

// What the scene's pair forces must compute under cfg.integrator: everything for mvv and scmvv; for shardlow and
// pnhln the conservative force alone (γ = 0 and no noise: the integrator does the rest, so the reported virial is
// the conservative one).
WaterConfig pair_force_config(const WaterConfig& cfg);
DpdKernel pair_force_kernel(const WaterConfig& cfg);

}  // namespace dpdrng::dpd
