// The self-consistent velocity-Verlet (--integrator scmvv[:K]) against the exact stationary variance of its
// discrete Ornstein–Uhlenbeck limit, the iteration's fixed point, the pair noise it shares with MVV, and its
// kinetic temperature in the water scene. Sources and tolerances beside each test.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/dpd/self_consistent.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/registry.hpp"
#include "scale.hpp"

namespace dpdrng_test::dpd_test_scmvv {

using namespace dpdrng;
using namespace dpdrng::dpd;

namespace {

// One pair at a fixed weight w along x, its forces by the DPD kernel's formula (positions play no part): the
// relative velocity u = v₁ − v₀ is an Ornstein–Uhlenbeck process du = −Γu dt + η, Γ = 2γw², η the random force
// 2σwζ/√Δt on u (variance s² = 4σ²w²/Δt), whose exact stationary variance is σ²/γ = 2k_BT.
struct OnePair {
  double gamma = 4.5, sigma = 3.0, w = 0.5, dt = 0.1;
  std::mt19937_64 engine{12345};
  std::normal_distribution<double> normal;

  void set(System& s, VelocityView v, double zeta) const {
    const double f0 = gamma * w * w * (v.vx[1] - v.vx[0]) - sigma * w * zeta / std::sqrt(dt);
    s.fx = {f0, -f0}, s.fy = {0, 0}, s.fz = {0, 0};
  }
  ForceFn full() {
    return [this](System& s, VelocityView v) {
      set(s, v, normal(engine));
      return ForceSums{};
    };
  }
  ForceFn dissipative() {
    return [this](System& s, VelocityView v) {
      set(s, v, 0.0);
      return ForceSums{};
    };
  }
};

// The stationary variance of u under K iterations, from the scheme's recursion. With α = ΓΔt/2:
//   u' = (1 − α)u_n + ½Δt η_n,   u^k = u' + ½Δt(η_{n+1} − Γu^{k−1}),   u_{n+1} = u^K
// so u_{n+1} = p(1 − α)u_n + p½Δt η_n + q½Δt η_{n+1}, q = (1 − (−α)^K)/(1 + α), p = q + (−α)^K: an ARMA(1,1)
// process x' = cx + b₀η_n + b₁η_{n+1}, whose variance is s²[b₁² + (cb₁ + b₀)²/(1 − c²)].
double exact_variance(const OnePair& p, int K) {
  const double gamma_rel = 2 * p.gamma * p.w * p.w, alpha = 0.5 * gamma_rel * p.dt;
  const double power = std::pow(-alpha, K);
  const double q = (1 - power) / (1 + alpha), pp = q + power;
  const double c = pp * (1 - alpha), b1 = q * 0.5 * p.dt, b0 = pp * 0.5 * p.dt;
  const double s2 = 4 * p.sigma * p.sigma * p.w * p.w / p.dt;
  return s2 * (b1 * b1 + (c * b1 + b0) * (c * b1 + b0) / (1 - c * c));
}

struct Estimate {
  double mean = 0, sem = 0;
};

// ⟨u²⟩ over `steps` steps after 1000 of equilibration, its standard error from 20 batch means.
Estimate simulated_variance(OnePair& p, int K, long steps) {
  System s;
  s.box = Box{{10, 10, 10}};
  s.resize(2);
  s.x = {1.0, 1.5};
  SelfConsistentVerlet sc(p.dt, K, 1);
  const ForceFn full = p.full(), diss = p.dissipative();
  sc.start(s, full);
  for (int k = 0; k < 1000; ++k) sc.step(s, full, diss);
  constexpr int kBatches = 20;
  std::vector<double> batch(kBatches, 0.0);
  const long per = steps / kBatches;
  for (int b = 0; b < kBatches; ++b) {
    for (long k = 0; k < per; ++k) {
      sc.step(s, full, diss);
      const double u = s.vx[1] - s.vx[0];
      batch[b] += u * u;
    }
    batch[b] /= double(per);
  }
  Estimate e;
  for (double v : batch) e.mean += v / kBatches;
  double ss = 0;
  for (double v : batch) ss += (v - e.mean) * (v - e.mean);
  e.sem = std::sqrt(ss / (kBatches - 1) / kBatches);
  return e;
}

}  // namespace

// The reference is exact, not published: the scheme's own discrete Ornstein–Uhlenbeck limit (one pair, fixed
// weight, no conservative force), whose stationary variance follows from the recursion above for any Δt and K.
// At γ = 4.5, σ = 3 (k_BT = 1), w = 0.5 the pair's kinetic temperature ⟨u²⟩/2 falls below 1 with Δt by a known
// amount: 0.944 for DPD-VV (K = 1) at Δt = 0.1 and 0.891 at 0.2, 0.899 for K = 5 at 0.1, 0.800 for K = 2 at 0.2
// (the continuous process: 1). Each must match to 4 batch standard errors (about 1 % each), which tells K = 1
// from K = 5 at Δt = 0.1 and every case from the continuous 2k_BT.
TEST(Scmvv, OnePairMatchesItsExactDiscreteOrnsteinUhlenbeckVariance) {
  const long steps = dpdrng::dpd::test_scale::scaled(150000, 60000);
  struct Case {
    double dt;
    int K;
  };
  for (const Case c : {Case{0.1, 1}, Case{0.1, 5}, Case{0.2, 1}, Case{0.2, 2}}) {
    OnePair p;
    p.dt = c.dt;
    const double exact = exact_variance(p, c.K);
    const Estimate e = simulated_variance(p, c.K, steps);
    EXPECT_NEAR(e.mean, exact, 4 * e.sem) << "dt " << c.dt << " K " << c.K << " (exact " << exact << ")";
    if (!dpdrng::dpd::test_scale::small_scale()) {
      EXPECT_LT(e.sem, 0.012 * exact) << "dt " << c.dt << " K " << c.K;
      EXPECT_GT(std::abs(exact - 2.0), 4 * e.sem) << "the case cannot tell the scheme from the continuous process";
    }
  }
  // The references differ by more than the tolerance: the test tells K = 1 from K = 5.
  OnePair p;
  EXPECT_GT(std::abs(exact_variance(p, 1) - exact_variance(p, 5)), 0.08);
}

// K iterations approach the implicit half kick's fixed point v = v' + ½Δt[F^C + F^R + F^D(v)]: after one step
// from the same state, the velocities of K and K + 1 iterations differ by a factor ≈ ½Δt‖F^D‖ less each time
// (geometric convergence), down to round-off by K = 30. 256 beads, Δt = 0.04, γ = 4.5.
TEST(Scmvv, IterationsConvergeToTheSelfConsistentFixedPoint) {
  auto velocities_after_one_step = [](int K) {
    WaterConfig cfg;
    cfg.gamma = 4.5;
    cfg.steps = 1;
    cfg.equilibrate = 0;
    cfg.observables = false;
    cfg.threads = 1;
    cfg.integrator = Integrator::scmvv;
    cfg.scmvv_iterations = K;
    std::vector<double> v;
    RunHooks hooks;
    hooks.observe = [&](std::int64_t, const System& s) { v = s.vx; };
    run_water(cfg, hooks);
    return v;
  };
  auto distance = [](const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  };
  const auto v1 = velocities_after_one_step(1), v2 = velocities_after_one_step(2),
             v3 = velocities_after_one_step(3), v30 = velocities_after_one_step(30),
             v31 = velocities_after_one_step(31);
  const double d12 = distance(v1, v2), d23 = distance(v2, v3);
  EXPECT_GT(d12, 1e-6);       // the iterations change the velocities
  EXPECT_LT(d23, 0.5 * d12);  // and contract
  EXPECT_LT(distance(v30, v31), 1e-14);
}

// SCMVV draws its random force through the same pair noise as MVV: one noisy force evaluation a step (its
// dissipative passes draw nothing), the same pairs and numbers, so on the first step from the same state the
// numbers drawn and the ζ reported equal MVV's.
TEST(Scmvv, DrawsTheSamePairNoiseAsMvv) {
  WaterConfig cfg;
  cfg.steps = 1;
  cfg.equilibrate = 0;
  cfg.threads = 1;
  cfg.generator = rng::validated({"tea32", 1});
  cfg.seeding = rng::Seeding::pair_step;  // ζ of (i, j, step): the two schemes' positions differ in rounding
  const RunResult mvv = run_water(cfg);
  cfg.integrator = Integrator::scmvv;
  cfg.scmvv_iterations = 3;
  const RunResult sc = run_water(cfg);
  ASSERT_TRUE(mvv.ok() && sc.ok());
  EXPECT_EQ(sc.integrator, "scmvv:3");
  EXPECT_EQ(sc.timings.random_numbers, mvv.timings.random_numbers);
  EXPECT_EQ(sc.zeta.n, mvv.zeta.n);
  EXPECT_EQ(sc.zeta.s2, mvv.zeta.s2);
}

}  // namespace dpdrng_test::dpd_test_scmvv

namespace dpdrng_test::dpd_test_scmvv {
namespace {

// ρ = 3, a = 25, γ = 4.5 (σ = 3), k_BT = 1: the system of Groot & Warren (1997), Besold et al. (2000) and
// Nikunen, Karttunen & Vattulainen (2003). 500 beads, cells, Philox pair noise.
RunResult water(const char* integrator, double dt, std::int64_t steps) {
  WaterConfig cfg;
  cfg.particles = 500;
  cfg.pairs = PairMode::cells;
  cfg.gamma = 4.5;
  cfg.dt = dt;
  cfg.steps = steps;
  cfg.equilibrate = steps / 10;
  cfg.generator = rng::validated({"philox4x32", 10});
  cfg.seeding = rng::Seeding::pair_step;
  cfg.observables = false;
  cfg.threads = 1;
  set_integrator(cfg, integrator, "integrator");
  return run_water(cfg);
}

}  // namespace

// Besold, Vattulainen, Karttunen & Polson, Phys. Rev. E 62, R7611 (2000) and Vattulainen et al., J. Chem. Phys.
// 116, 3967 (2002): re-evaluating the dissipative force with the updated velocities (DPD-VV) brings the kinetic
// temperature much closer to k_BT than Groot–Warren's λ = 0.5 at the same Δt, and iterating to self-consistency
// closer still. Their tables' numbers were not available to this test; the reference is that published ordering,
// with the margins measured here (1000 steps, 500 beads; 1000 beads and 3000 steps gave ⟨k_BT⟩ = 1.060 (MVV),
// 1.025 (K = 1) and 0.992 (K = 5) at Δt = 0.06, ± 0.003): at Δt = 0.06 DPD-VV's deviation from 1 must be below
// MVV's by more than two standard errors of each, and K = 5's within 1 % plus 3 standard errors.
TEST(Scmvv, KineticTemperatureCloserToKTThanGrootWarrenAtDt006) {
  const std::int64_t steps = test_scale::scaled(1000, 400);
  const RunResult mvv = water("mvv", 0.06, steps), vv = water("scmvv:1", 0.06, steps),
                  sc = water("scmvv:5", 0.06, steps);
  ASSERT_TRUE(mvv.ok() && vv.ok() && sc.ok()) << mvv.status << " / " << vv.status << " / " << sc.status;
  const double err_mvv = std::abs(mvv.temperature.mean - 1), err_vv = std::abs(vv.temperature.mean - 1);
  EXPECT_LT(err_vv + 2 * (vv.temperature.sem + mvv.temperature.sem), err_mvv)
      << vv.temperature.mean << " vs " << mvv.temperature.mean;
  EXPECT_NEAR(sc.temperature.mean, 1.0, 0.01 + 3 * sc.temperature.sem);
}

}  // namespace dpdrng_test::dpd_test_scmvv
