// The configurational temperature's sums against finite differences of the conservative potential, and the ζ
// statistics of a run against generators whose defects are known (rng/defect.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/water.hpp"

namespace dpdrng_test::dpd_test_conf_temperature {

using namespace dpdrng;
using namespace dpdrng::dpd;

namespace {

constexpr double kA = 25.0, kRc = 1.0;

// U_i: the conservative potential of the pairs of bead i, u(r) = (a/2) r_c (1 − r/r_c)² inside r_c, written out
// here from Groot & Warren (1997) eq. 3 (F^C = a w ê is −u').
double bead_energy(const System& s, std::size_t i) {
  double u = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (j == i) continue;
    double r2 = 0;
    const double d[3] = {s.x[j] - s.x[i], s.y[j] - s.y[i], s.z[j] - s.z[i]};
    for (int a = 0; a < 3; ++a) {
      const double L = s.box.L[a];
      const double m = d[a] - L * std::round(d[a] / L);
      r2 += m * m;
    }
    const double r = std::sqrt(r2);
    if (r < kRc) u += 0.5 * kA * kRc * (1 - r / kRc) * (1 - r / kRc);
  }
  return u;
}

double& coord(System& s, std::size_t i, int a) { return a == 0 ? s.x[i] : a == 1 ? s.y[i] : s.z[i]; }

// Smallest distance of any pair to r = 0 or to r = r_c, where u'' jumps (a finite difference across either is
// not the Laplacian).
double margin(const System& s) {
  double m = 1e9;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      double r2 = 0;
      const double d[3] = {s.x[j] - s.x[i], s.y[j] - s.y[i], s.z[j] - s.z[i]};
      for (int a = 0; a < 3; ++a) {
        const double mm = d[a] - s.box.L[a] * std::round(d[a] / s.box.L[a]);
        r2 += mm * mm;
      }
      const double r = std::sqrt(r2);
      m = std::min({m, r, std::abs(r - kRc)});
    }
  return m;
}

}  // namespace

// Σ_i ∇_i²U from the pair loop (the closed form a/r_c − 2aw/r per pair and bead) against central second
// differences of U_i in each coordinate, and Σ_i |∇_i U|² (the conservative forces squared) against central first
// differences, in both pair modes. A wrong sign or factor in either (2u'/r dropped, the pair counted once, the
// dissipative force mixed into the conservative one) is off by far more than the 1e-6 relative tolerance.
TEST(ConfigurationalTemperature, SumsMatchFiniteDifferences) {
  const double L = 4.0, h = 1e-4;
  System s;
  for (std::uint64_t seed = 1;; ++seed) {
    s = make_fluid(60, Box{{L, L, L}}, 1.0, seed);
    if (margin(s) > 0.01) break;
  }
  double lap = 0, grad2 = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      double& x = coord(s, i, a);
      const double x0 = x, u0 = bead_energy(s, i);
      x = x0 + h;
      const double up = bead_energy(s, i);
      x = x0 - h;
      const double um = bead_energy(s, i);
      x = x0;
      lap += (up - 2 * u0 + um) / (h * h);
      grad2 += (up - um) / (2 * h) * (up - um) / (2 * h);
    }
  // Random positions: ⟨∇²u⟩ over an ideal gas's pair distances is 0 in 3D (∫ (1 − 2w/r) r² dr = 0 over the
  // sphere), so the sum has either sign; it must not be trivially small.
  ASSERT_GT(std::abs(lap), 10.0);
  ASSERT_GT(grad2, 100.0);
  for (PairMode mode : {PairMode::all, PairMode::cells}) {
    WaterConfig cfg;
    cfg.pairs = mode;
    cfg.threads = 1;
    cfg.generator = rng::validated({"philox4x32", 10});
    System t = s;
    // Moving beads and noise: neither may enter the conservative sums.
    for (std::size_t i = 0; i < t.size(); ++i) t.vx[i] = 0.1 * double(i % 7) - 0.3;
    auto pf = make_pair_forces(cfg, make_kernel(kA, kRc, 4.5, 1.0, 0.04), t.size());
    Taps taps;
    // A step that does not ask for them sums nothing.
    const ForceSums off = pf->compute(t, VelocityView{t.vx.data(), t.vy.data(), t.vz.data()}, 3, false, false, true, taps);
    EXPECT_FALSE(off.configurational);
    EXPECT_EQ(off.conf_laplacian, 0.0);
    pf->sum_configurational(true);
    const ForceSums f = pf->compute(t, VelocityView{t.vx.data(), t.vy.data(), t.vz.data()}, 3, false, false, true, taps);
    EXPECT_TRUE(f.configurational);
    EXPECT_NEAR(f.conf_laplacian, lap, 1e-6 * std::abs(lap)) << to_string(mode);
    EXPECT_NEAR(f.conf_force2, grad2, 1e-6 * grad2) << to_string(mode);
  }
}

namespace {
WaterConfig noise_run(const char* generator, rng::Seeding seeding, PairMode mode) {
  WaterConfig cfg;
  cfg.particles = 256;
  cfg.pairs = mode;
  cfg.steps = 700;
  cfg.equilibrate = 100;
  cfg.threads = 1;
  cfg.generator = rng::validated({generator, 0});
  cfg.seeding = seeding;
  cfg.zeta_lags = 3;
  return cfg;
}
// |x − expected| within 4 standard errors.
void expect_within(const Estimate& e, double expected, const char* what) {
  ASSERT_TRUE(e.not_applicable.empty()) << what << ": " << e.not_applicable;
  EXPECT_NEAR(e.mean, expected, 4 * e.se) << what;
  EXPECT_LT(e.se, 0.05) << what;  // enough products to tell 0.3 from 0
}
}  // namespace

// The defect generator's ζ_t = √(1+ε)(a η_{t−1} + √(1−a²) η_t) has corr(ζ_t, ζ_{t−1}) = ρ exactly and no
// correlation at lag 2 (an MA(1) sequence; defect.hpp): the tracked pairs must find ρ = 0.3 at lag 1 and 0 at
// lags 2 and 3, and no correlation across pairs sharing a bead (each pair's η is its own hash).
TEST(ZetaStatistics, TrackerFindsTheDefectsLagOneCorrelation) {
  const RunResult r = run_water(noise_run("defect:lag1=0.3", rng::Seeding::pair_step, PairMode::all));
  ASSERT_TRUE(r.ok()) << r.status;
  const ZetaCorrelation& z = r.zeta_correlation;
  ASSERT_TRUE(z.requested);
  ASSERT_TRUE(z.not_applicable.empty()) << z.not_applicable;
  ASSERT_EQ(z.autocorrelation.size(), 3u);
  expect_within(z.autocorrelation[0], 0.3, "lag 1");
  expect_within(z.autocorrelation[1], 0.0, "lag 2");
  expect_within(z.autocorrelation[2], 0.0, "lag 3");
  expect_within(z.shared_bead, 0.0, "shared bead");
}

// ⟨ζ²⟩ = 1 + ε under defect:variance=ε whatever the pair's distance, so the w_R²-weighted moment is 1 + ε too:
// 1.2 within its error, and 1 for the reference (whose ζ has unit variance and no correlation at any lag).
TEST(ZetaStatistics, WeightedSecondMomentOfKnownVariance) {
  const RunResult d = run_water(noise_run("defect:variance=0.2", rng::Seeding::pair_step, PairMode::cells));
  ASSERT_TRUE(d.ok()) << d.status;
  EXPECT_NEAR(d.zeta_weighted_second_moment.mean, 1.2, 4 * d.zeta_weighted_second_moment.sem);
  EXPECT_GT(d.zeta_weighted_second_moment.n, 0u);
  const RunResult m = run_water(noise_run("mt19937", rng::Seeding::distance, PairMode::all));
  ASSERT_TRUE(m.ok()) << m.status;
  EXPECT_NEAR(m.zeta_weighted_second_moment.mean, 1.0, 4 * m.zeta_weighted_second_moment.sem);
  EXPECT_LT(m.zeta_weighted_second_moment.sem, 0.01);
  ASSERT_TRUE(m.zeta_correlation.not_applicable.empty()) << m.zeta_correlation.not_applicable;
  for (const Estimate& e : m.zeta_correlation.autocorrelation) expect_within(e, 0.0, "mt19937");
}

// The mt19937 stream gives a pair its number by its slot in the step's pair order, which only the all-pairs mode
// can name for a tracked pair: in cells mode the correlation is not applicable, with the reason, never 0.
TEST(ZetaStatistics, StreamInCellsModeIsNotApplicable) {
  WaterConfig cfg = noise_run("mt19937", rng::Seeding::distance, PairMode::cells);
  cfg.steps = 150;
  const RunResult r = run_water(cfg);
  ASSERT_TRUE(r.ok()) << r.status;
  EXPECT_TRUE(r.zeta_correlation.autocorrelation.empty());
  EXPECT_NE(r.zeta_correlation.not_applicable.find("mt19937"), std::string::npos);
}

}  // namespace dpdrng_test::dpd_test_conf_temperature
