// The stability report's judgements on hand-made cells whose replica means and CIs are known in closed form:
// the accuracy frontier is a bracket read from the 95 % CIs (not from the point estimates), PNHLN is ranked by its
// configurational temperature, the crossing table's noise and integrator errors equal the hand computation, and
// the reference_gammas series runs the reference alone with exact cell ids.
//
// Two replicas at m − d and m + d have the mean m and the spread s = d√2. A point's CI pools one replica's variance
// with the other generators' at the same integrator and Δt: two points of two replicas at offset d each give
// s² = 2d², 2 degrees of freedom and the 95 % half-width t(0.975; 2) · s / √2 = t(0.975; 2) · d, with
// t(0.975; 2) = 4.30265272991 (Student's t: Abramowitz & Stegun, Table 26.10); a point alone at its integrator and
// Δt keeps t(0.975; 1) · d, t(0.975; 1) = 12.7062047361747.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "config_text.hpp"
#include "dpdrng/study/stability.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng_test::study_test_stability_frontier {

using namespace dpdrng::study;
using dpdrng::study::config_text::error_of;
using dpdrng::study::config_text::StudyText;

namespace {

constexpr double kT1 = 12.7062047361747;  // t(0.975; 1)
constexpr double kT2 = 4.302652729911275;  // t(0.975; 2)

struct Reading {
  double t = NAN, d = 1e-4;  // kinetic mean and replica offset (NaN: the cell blew up)
  double conf = NAN;         // configurational mean (offset d too)
  double step_seconds = 1e-3;
};
// (integrator, generator label, noise, Δt) → reading
using Table = std::map<std::tuple<std::string, std::string, std::string, double>, Reading>;

std::vector<CellResult> cells_from(const StudyConfig& c, const Table& table) {
  std::vector<CellResult> out;
  for (const Cell& cell : enumerate_cells(c)) {
    CellResult r;
    r.cell = cell;
    const auto it = table.find({cell.integrator, cell.label(), cell.noise(), cell.dt});
    const Reading x = it == table.end() ? Reading{} : it->second;
    if (!std::isfinite(x.t)) {
      r.status = CellStatus::unstable;
      r.unstable_step = 3;
      r.reason = "unstable at step 3: temperature runaway (k_BT = 150)";
      out.push_back(r);
      continue;
    }
    const double sign = cell.replica == 0 ? -1.0 : 1.0;
    r.scalars["temperature_mean"] = x.t + sign * x.d;
    if (std::isfinite(x.conf)) r.scalars["temperature_conf_mean"] = x.conf + sign * x.d;
    r.scalars["pressure_conservative_mean"] = 23.64;
    r.scalars["diffusion_coefficient"] = 0.3;
    r.scalars["cost.step_seconds"] = x.step_seconds;
    out.push_back(r);
  }
  return out;
}

StudyConfig config_of(const std::string& integrators, const std::string& dts, const std::string& feeds = "") {
  return parse_config(StudyText{.name = "s",
                                .sweep_extra = "integrators = " + integrators + "\n" + feeds,
                                .generators = {{.rounds = "[1]"}},
                                .scene = "particles = 64\ndt = " + dts + "\ntime = 2.0\npairs = \"cells\"\n",
                                .tests = "chi2_steps = 0\nttest_pairs = 0\n"}
                          .text(),
                      "cfg.toml");
}

}  // namespace

// MT: 1.006 ± 0.0004 at Δt 0.05 is inside ±1 %; 1.009 ± 0.0017 at 0.1 straddles the edge (its point estimate is
// inside); 1.05 at 0.2 is outside. The bracket is 0.05 – 0.2: a frontier from point estimates would say 0.1, and
// one that took the first non-inside Δt as "outside" would say 0.1 too.
// 32TEA(1): −3 % at 0.02, inside at 0.05, straddling at 0.1 (0.991 ± 0.0017), +3 % at 0.2: its inside Δt lies
// above an outside one, which the frontier lists (a cancellation, not accuracy).
TEST(StabilityFrontier, BracketComesFromTheCisNotThePointEstimates) {
  const StudyConfig c = config_of(R"(["mvv:0.5"])", "[0.02, 0.05, 0.1, 0.2, 0.3]");
  Table t;
  const std::string mvv = "mvv:0.5";
  t[{mvv, "mt19937", "gauss", 0.02}] = {1.002};
  t[{mvv, "mt19937", "gauss", 0.05}] = {1.006};
  t[{mvv, "mt19937", "gauss", 0.1}] = {1.009, 4e-4};
  t[{mvv, "mt19937", "gauss", 0.2}] = {1.05};
  t[{mvv, "tea32(1)", "gauss", 0.02}] = {0.97};
  t[{mvv, "tea32(1)", "gauss", 0.05}] = {0.995};
  t[{mvv, "tea32(1)", "gauss", 0.1}] = {0.991, 4e-4};
  t[{mvv, "tea32(1)", "gauss", 0.2}] = {1.03};
  const StabilityAnalysis a = analyse_stability(c, cells_from(c, t));
  const StabilityPoint* straddle = nullptr;
  for (const auto& p : a.points)
    if (p.reference && p.dt == 0.1) straddle = &p;
  ASSERT_NE(straddle, nullptr);
  EXPECT_NEAR(straddle->temperature_ci, kT2 * 4e-4, 1e-12);

  const Frontier mt = accuracy_frontier(a, "mvv:0.5 mt19937 gauss", Thermometer::kinetic, 0.01);
  EXPECT_EQ(mt.inside, 0.05);
  EXPECT_EQ(mt.outside, 0.2);
  EXPECT_TRUE(mt.outside_below.empty());
  EXPECT_EQ(bracket_text(mt), "0.05 – 0.2");

  const Frontier tea = accuracy_frontier(a, "mvv:0.5 tea32(1) gauss", Thermometer::kinetic, 0.01);
  EXPECT_EQ(tea.inside, 0.05);
  EXPECT_EQ(tea.outside, 0.2);
  ASSERT_EQ(tea.outside_below.size(), 1u);
  EXPECT_EQ(tea.outside_below[0], 0.02);

  // No configurational temperature in these cells: no frontier, never a made-up one.
  const Frontier conf = accuracy_frontier(a, "mvv:0.5 mt19937 gauss", Thermometer::configurational, 0.01);
  EXPECT_TRUE(std::isnan(conf.inside));
  EXPECT_EQ(conf.outside, 0.3);  // the blow-up is outside any band
  const std::string csv = frontier_csv(a, 0.01);
  EXPECT_NE(csv.find("mvv:0.5 tea32(1) gauss,kinetic,0.01,0.05,0.2,0.02,0.3\n"), std::string::npos) << csv;
}

// PNHLN's thermostat pins the kinetic temperature (1.000 at every Δt here) while its configurational temperature
// leaves ±1 % after Δt 0.02; GW-MVV holds k_BT inside to 0.05. Ranked by the kinetic temperature PNHLN would come
// first (inside to 0.1); by the configurational one it comes second.
TEST(StabilityFrontier, PnhlnIsRankedByItsConfigurationalTemperature) {
  const StudyConfig c = config_of(R"(["mvv:0.5", "pnhln:10"])", "[0.02, 0.05, 0.1]");
  Table t;
  for (const auto& [dt, kin, conf] : {std::tuple{0.02, 1.002, 1.0}, {0.05, 1.005, 1.0}, {0.1, 1.03, 1.0}})
    t[{"mvv:0.5", "mt19937", "gauss", dt}] = {kin, 1e-4, conf, 1e-3};
  for (const auto& [dt, conf] : {std::pair{0.02, 1.003}, {0.05, 1.02}, {0.1, 1.06}})
    t[{"pnhln:10", "mt19937", "gauss", dt}] = {1.0, 1e-4, conf, 2e-3};
  const StabilityAnalysis a = analyse_stability(c, cells_from(c, t));
  const auto r = rank_integrators(a, 0.01);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].integrator, "mvv:0.5");
  EXPECT_EQ(r[0].ranked_by, Thermometer::kinetic);
  EXPECT_EQ(r[0].kinetic.inside, 0.05);
  EXPECT_EQ(r[1].integrator, "pnhln:10");
  EXPECT_EQ(r[1].ranked_by, Thermometer::configurational);
  EXPECT_EQ(r[1].kinetic.inside, 0.1);  // pinned: inside everywhere, and not what it is ranked by
  EXPECT_EQ(r[1].configurational.inside, 0.02);
  EXPECT_EQ(r[1].configurational.outside, 0.05);
  // Cost per unit time at the ranked frontier: step seconds / inside Δt; per step relative to GW-MVV's.
  EXPECT_NEAR(r[0].seconds_per_time, 1e-3 / 0.05, 1e-15);
  EXPECT_NEAR(r[1].seconds_per_time, 2e-3 / 0.02, 1e-15);
  EXPECT_NEAR(r[1].relative_step_cost, 2.0, 1e-12);
  EXPECT_EQ(r[1].jdpd_factor, 1.9);
  const std::string csv = ranking_csv(r);
  EXPECT_NE(csv.find("2,pnhln:10,pnhln:10 mt19937 gauss,configurational,0.1,,0.02,0.05,0.002,2,0.1,1.9\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(ranking_markdown(r, 0.01).find("| 2 | pnhln:10 | configurational | 0.02 – 0.05 |"), std::string::npos);
}

// GW-MVV λ = 0.5 at Δt 0.04: MT19937 runs hot (halves 1.036, blocks 1.037); 32TEA(1) halves reads 1.001, blocks
// 1.020; every point two replicas at ±1e-3, so the pooled variance over the four points has 4 degrees of freedom
// and each half-width is t(0.975; 4) · 1e-3, t(0.975; 4) = 2.77644510520 (Abramowitz & Stegun, Table 26.10). By
// hand: halves noise error 1.001 − 1.036 = −0.035 ± √2·t·1e-3 against integrator error +0.036 ± t·1e-3, and
// 1.001 ± t·1e-3 holds 1: they cancel fully; blocks −0.017 ± √2·t·1e-3 against +0.037, and 1.020 ± t·1e-3 does
// not hold 1: partly.
TEST(StabilityFrontier, CrossingTableEqualsHandComputation) {
  const StudyConfig c = config_of(R"(["mvv:0.5", "pnhln:10"])", "[0.04]", "feeds = [\"halves\", \"blocks\"]\n");
  Table t;
  t[{"mvv:0.5", "mt19937", "gauss", 0.04}] = {1.036, 1e-3, 1.001};
  t[{"mvv:0.5", "mt19937", "gauss-blocks", 0.04}] = {1.037, 1e-3, 1.002};
  t[{"mvv:0.5", "tea32(1)", "gauss", 0.04}] = {1.001, 1e-3, 0.966};
  t[{"mvv:0.5", "tea32(1)", "gauss-blocks", 0.04}] = {1.020, 1e-3, 0.985};
  t[{"pnhln:10", "mt19937", "gauss", 0.04}] = {1.0, 1e-4, 1.01};
  const auto rows = crossing_rows(analyse_stability(c, cells_from(c, t)));
  ASSERT_EQ(rows.size(), 4u);  // PNHLN draws no pair noise: no row
  const CrossingRow* halves = nullptr;
  const CrossingRow* blocks = nullptr;
  for (const auto& r : rows) {
    EXPECT_EQ(r.integrator, "mvv:0.5");
    if (r.generator == "tea32(1)") (r.noise == "gauss" ? halves : blocks) = &r;
    if (r.reference) {
      EXPECT_EQ(r.cancellation.rfind("not applicable: ", 0), 0u) << r.cancellation;
    }
  }
  ASSERT_TRUE(halves && blocks);
  EXPECT_NEAR(halves->noise_shift, 1.001 - 1.036, 1e-12);
  constexpr double kT4 = 2.7764451051977987;  // t(0.975; 4)
  EXPECT_NEAR(halves->noise_shift_ci, std::sqrt(2.0) * kT4 * 1e-3, 1e-12);
  EXPECT_NEAR(halves->integrator_error, 0.036, 1e-12);
  EXPECT_NEAR(halves->integrator_error_ci, kT4 * 1e-3, 1e-12);
  EXPECT_NEAR(halves->temperature_conf, 0.966, 1e-12);
  EXPECT_EQ(halves->cancellation, "full");
  EXPECT_NEAR(blocks->noise_shift, 1.020 - 1.037, 1e-12);
  EXPECT_NEAR(blocks->noise_shift_ci, std::sqrt(2.0) * kT4 * 1e-3, 1e-12);
  EXPECT_NEAR(blocks->integrator_error, 0.037, 1e-12);
  EXPECT_EQ(blocks->cancellation, "partial");
  const std::string csv = crossing_csv(rows);
  EXPECT_NE(csv.find("mvv:0.5,tea32(1),gauss,0.04,1.001,0.00277645,0.966,0.00277645,-0.035,0.00392649,0.036,0.00277645,"
                     "\"full\"\n"),
            std::string::npos)
      << csv;
  const std::string md = crossing_markdown(rows);
  EXPECT_NE(md.find("- mvv:0.5 tea32(1) gauss at Δt 0.04: noise error -3.50 ± 0.39 % against integrator error +3.60 "
                    "± 0.28 %"),
            std::string::npos)
      << md;
}

// A point whose replicas scatter far more than the pool's (offset 1e-2 against 1e-4: F = 10⁴ on 1 and 1 degrees
// of freedom, upper tail 0.0064 < 0.05) keeps its own t(0.975; 1) · d; the quiet point beside it pools both
// spreads (its own is not larger), so its CI widens to t(0.975; 2) · √((2·10⁻⁸ + 2·10⁻⁴)/2) / √2.
TEST(StabilityFrontier, APointThatScattersMoreKeepsItsOwnSpread) {
  const StudyConfig c = config_of(R"(["mvv:0.5"])", "[0.02]");
  Table t;
  t[{"mvv:0.5", "mt19937", "gauss", 0.02}] = {1.0, 1e-4};
  t[{"mvv:0.5", "tea32(1)", "gauss", 0.02}] = {1.0, 1e-2};
  const StabilityAnalysis a = analyse_stability(c, cells_from(c, t));
  ASSERT_EQ(a.points.size(), 2u);
  for (const auto& p : a.points) {
    if (p.reference)
      EXPECT_NEAR(p.temperature_ci, kT2 * std::sqrt((2e-8 + 2e-4) / 2) / std::sqrt(2.0), 1e-10);
    else
      EXPECT_NEAR(p.temperature_ci, kT1 * 1e-2, 1e-12);
  }
}

TEST(StabilityFrontier, JdpdFactorsOnlyWherePublished) {
  EXPECT_EQ(jdpd_cost_factor("mvv:0.65"), 1.0);
  EXPECT_EQ(jdpd_cost_factor("shardlow"), 1.1);
  EXPECT_EQ(jdpd_cost_factor("scmvv:1"), 1.4);
  EXPECT_EQ(jdpd_cost_factor("scmvv:5"), 2.3);
  EXPECT_EQ(jdpd_cost_factor("pnhln:10"), 1.9);
  EXPECT_TRUE(std::isnan(jdpd_cost_factor("scmvv:3")));
}

// The friction series: the reference alone, under the first noise, at every integrator, Δt and replica, with the
// value in its id; the scene's cells keep their ids, and a config without the key keeps its canonical form.
TEST(StabilityFrontier, ReferenceGammasAddReferenceCellsWithExactIds) {
  const std::string base = StudyText{.name = "s",
                                     .sweep_extra = "feeds = [\"halves\", \"blocks\"]\nintegrators = [\"mvv:0.65\"]\n",
                                     .generators = {{.rounds = "[1]"}},
                                     .scene = "particles = 64\ndt = [0.02, 0.04]\ntime = 2.0\n",
                                     .tests = "chi2_steps = 0\nttest_pairs = 0\n"}
                               .text();
  const StudyConfig plain = parse_config(base, "cfg.toml");
  const StudyConfig with = parse_config(
      config_text::with(base, "integrators =", "reference_gammas = [4.5]\nintegrators ="), "cfg.toml");
  EXPECT_FALSE(plain.canonical().contains("reference_gammas"));
  EXPECT_EQ(with.canonical()["reference_gammas"], nlohmann::json::array({4.5}));
  EXPECT_NE(plain.hash, with.hash);
  const auto a = enumerate_cells(plain), b = enumerate_cells(with);
  ASSERT_EQ(b.size(), a.size() + 2u * 2u);  // 2 Δt × 2 replicas, one reference cell each
  std::vector<std::string> extra;
  for (const auto& cell : b) {
    if (cell.gamma == 0) {
      EXPECT_TRUE(std::any_of(a.begin(), a.end(), [&](const Cell& x) { return x.id() == cell.id(); })) << cell.id();
      continue;
    }
    EXPECT_TRUE(cell.reference);
    EXPECT_EQ(cell.feed, dpdrng::rng::Feed::halves);
    EXPECT_EQ(cell.gamma, 4.5);
    extra.push_back(cell.id());
  }
  EXPECT_EQ(extra.front(), "mt19937-gauss-dt0.02-mvv0.65-gamma4.5-rep00");
  EXPECT_NE(error_of(config_text::with(base, "integrators =", "reference_gammas = [6.75]\nintegrators =")).find(
                "sweep.reference_gammas: 6.75 is the scene's gamma"),
            std::string::npos);
  EXPECT_NE(error_of(config_text::with(base, "integrators =", "reference_gammas = [-1]\nintegrators =")).find(
                "reference_gammas"),
            std::string::npos);
}

// More replicas at chosen Δt: every variant and the reference there, the first replicas' cells unchanged, the
// other Δt at `replicas`; a Δt not in the scene or a count not above `replicas` is refused naming the key.
TEST(StabilityFrontier, ExtraReplicasOnlyAtTheirDt) {
  const std::string base = StudyText{.name = "s",
                                     .sweep_extra = "integrators = [\"mvv:0.65\", \"pnhln:10\"]\n",
                                     .generators = {{.rounds = "[1]"}},
                                     .scene = "particles = 64\ndt = [0.02, 0.04]\ntime = 2.0\n",
                                     .tests = "chi2_steps = 0\nttest_pairs = 0\n"}
                               .text();
  const StudyConfig plain = parse_config(base, "cfg.toml");
  const auto extra = [&](const std::string& table) {
    return config_text::with(base, "integrators =", "extra_replicas = " + table + "\nintegrators =");
  };
  const StudyConfig more = parse_config(extra(R"({ "0.04" = 5 })"), "cfg.toml");
  EXPECT_FALSE(plain.canonical().contains("extra_replicas"));
  EXPECT_EQ(more.canonical()["extra_replicas"], nlohmann::json({{"0.04", 5}}));
  EXPECT_EQ(more.replicas_at(0.02), 2);
  EXPECT_EQ(more.replicas_at(0.04), 5);
  const auto a = enumerate_cells(plain), b = enumerate_cells(more);
  // At Δt 0.04, 3 more replicas of mvv:0.65 (MT19937 and 32TEA(1)) and of pnhln (MT19937 only).
  ASSERT_EQ(b.size(), a.size() + 3u * (2u + 1u));
  std::map<double, int> top;
  for (const auto& cell : b) {
    top[cell.dt] = std::max(top[cell.dt], cell.replica);
    if (cell.replica < 2) {
      EXPECT_TRUE(std::any_of(a.begin(), a.end(), [&](const Cell& x) { return x.id() == cell.id(); })) << cell.id();
    }
  }
  EXPECT_EQ(top[0.02], 1);
  EXPECT_EQ(top[0.04], 4);
  EXPECT_NE(error_of(extra(R"({ "0.03" = 5 })")).find("sweep.extra_replicas: 0.03 is not one of scene.dt"),
            std::string::npos);
  EXPECT_NE(error_of(extra(R"({ "0.04" = 2 })")).find("sweep.extra_replicas.0.04: out of range"), std::string::npos)
      << error_of(extra(R"({ "0.04" = 2 })"));
  EXPECT_NE(error_of(extra(R"({ "x" = 4 })")).find("sweep.extra_replicas.x"), std::string::npos);
}

}  // namespace dpdrng_test::study_test_stability_frontier
