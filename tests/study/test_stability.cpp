// The stability report's arithmetic on hand-made cells: a method × Δt counts its stable replicas and keeps the
// earliest blow-up's step and reason, its accuracy comes from the stable replicas only (never from an unstable
// one), the largest accurate Δt stops at the first Δt that is inaccurate or unstable, and every blown-up point
// keeps its row in every table. The CI-sized study itself runs in StabilityCli.CiStudyReportsEveryCell.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sys/wait.h>

#include "../temp_dir.hpp"
#include "config_text.hpp"
#include "dpdrng/study/stability.hpp"
#include "dpdrng/study/store.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng_test::study_test_stability {

using namespace dpdrng::study;
namespace fs = std::filesystem;

namespace {

const std::string kConfig =
    config_text::StudyText{.name = "s",
                           .sweep_extra = "integrators = [\"mvv:0.5\", \"shardlow\"]\n",
                           .generators = {{.rounds = "[1]"}},
                           .scene = "particles = 64\ndt = [0.02, 0.05, 0.1]\ntime = 2.0\npairs = \"cells\"\n",
                           .tests = "chi2_steps = 0\nttest_pairs = 0\n"}
        .text();

// MVV at λ = 0.5 runs hot by 2 % × (Δt / 0.02) and blows up at Δt 0.1 (one replica at step 7, the other at 9);
// Shardlow holds k_BT = 1.001 and is stable throughout. D and g(r) of MT at Δt 0.02 are the reference.
std::vector<CellResult> made_up_cells(const StudyConfig& c) {
  std::vector<CellResult> out;
  for (const Cell& cell : enumerate_cells(c)) {
    CellResult r;
    r.cell = cell;
    const bool mvv = cell.integrator == "mvv:0.5";
    if (mvv && cell.dt == 0.1) {
      r.status = CellStatus::unstable;
      r.unstable_step = 9 - 2 * (cell.replica == 1 && !cell.reference);
      r.reason = "unstable at step " + std::to_string(r.unstable_step) + ": temperature runaway (k_BT = 150)";
      out.push_back(r);
      continue;
    }
    const double t = mvv ? 1.0 + 0.02 * cell.dt / 0.02 : 1.001;
    r.scalars["temperature_mean"] = t + (cell.replica ? 1e-4 : -1e-4);
    r.scalars["temperature_sem"] = 1e-4;
    r.scalars["pressure_conservative_mean"] = 23.64 * (1 + (mvv ? 0.01 : 0.0));
    r.scalars["diffusion_coefficient"] = 0.3 * (1 + cell.dt);
    r.scalars["cost.step_seconds"] = mvv ? 1e-3 : 2e-3;
    r.series["rdf/g"] = {0.5, 1.0, 1.2 + cell.dt};
    out.push_back(r);
  }
  return out;
}

TEST(Stability, PointsCountBlowUpsAndMeasureOnlyStableReplicas) {
  const StudyConfig c = parse_config(kConfig, "cfg.toml");
  const auto cells = made_up_cells(c);
  const StabilityAnalysis a = analyse_stability(c, cells);
  EXPECT_EQ(a.reference_dt, 0.02);
  EXPECT_EQ(a.reference_cells, 4u);  // MT at Δt 0.02 under both integrators, 2 replicas each
  EXPECT_NEAR(a.reference_diffusion, 0.3 * 1.02, 1e-12);
  ASSERT_EQ(a.points.size(), 2u * 2u * 3u);  // 2 integrators × (MT, tea32(1)) × 3 Δt
  const StabilityPoint* blown = nullptr;
  for (const auto& p : a.points) {
    EXPECT_EQ(p.replicas, 2u);
    if (p.integrator == "mvv:0.5" && p.generator == "tea32(1)" && p.dt == 0.1) blown = &p;
  }
  ASSERT_NE(blown, nullptr);
  EXPECT_EQ(blown->stable, 0u);
  EXPECT_TRUE(blown->all_blew_up());
  EXPECT_EQ(blown->first_blowup_step, 7);
  EXPECT_EQ(blown->reason, "temperature runaway (k_BT = 150)");
  EXPECT_TRUE(std::isnan(blown->temperature) && std::isnan(blown->temperature_error));
  const StabilityPoint& first = a.points.front();  // mvv:0.5 mt19937 at Δt 0.02
  EXPECT_EQ(first.method(), "mvv:0.5 mt19937 gauss");
  EXPECT_NEAR(first.temperature, 1.02, 1e-12);
  EXPECT_NEAR(first.temperature_error, 0.02, 1e-12);
  EXPECT_NEAR(first.pressure_error, 0.01, 1e-12);
  EXPECT_NEAR(first.diffusion_error, 0.0, 1e-12);
  EXPECT_NEAR(first.seconds_per_time, 1e-3 / 0.02, 1e-12);
}

TEST(Stability, FrontierBracketAndFirstBlowUp) {
  const StudyConfig c = parse_config(kConfig, "cfg.toml");
  const StabilityAnalysis a = analyse_stability(c, made_up_cells(c));
  // MVV: k_BT 1.02 at 0.02 and 1.05 at 0.05 (CIs ±0.0013), blown up at 0.1: outside from the smallest Δt.
  const Frontier mvv = accuracy_frontier(a, "mvv:0.5 tea32(1) gauss", Thermometer::kinetic, 0.01);
  EXPECT_TRUE(std::isnan(mvv.inside));
  EXPECT_EQ(mvv.outside, 0.02);
  EXPECT_EQ(first_unstable_dt(a, "mvv:0.5 tea32(1) gauss"), 0.1);
  const Frontier sh = accuracy_frontier(a, "shardlow tea32(1) gauss", Thermometer::kinetic, 0.01);
  EXPECT_EQ(sh.inside, 0.1);
  EXPECT_TRUE(std::isnan(sh.outside));
  EXPECT_TRUE(std::isnan(first_unstable_dt(a, "shardlow tea32(1) gauss")));
  const std::string frontier = frontier_markdown(a, 0.01);
  EXPECT_NE(frontier.find("| mvv:0.5 tea32(1) gauss | none – 0.02 | – |"), std::string::npos) << frontier;
  EXPECT_NE(frontier.find("| shardlow tea32(1) gauss | 0.1 – none in the sweep | – |"), std::string::npos)
      << frontier;
}

// A blown-up point is in the map, the accuracy table and the CSV: never dropped.
TEST(Stability, BlownUpPointsAppearInEveryTable) {
  const StudyConfig c = parse_config(kConfig, "cfg.toml");
  const StabilityAnalysis a = analyse_stability(c, made_up_cells(c));
  const std::string map = stability_map_markdown(a);
  EXPECT_NE(map.find("| mvv:0.5 tea32(1) gauss | 2/2 | 2/2 | **0/2** @7 |"), std::string::npos) << map;
  EXPECT_NE(map.find("mvv:0.5 tea32(1) gauss, Δt 0.1: 2 of 2 blew up; step 7: temperature runaway"),
            std::string::npos)
      << map;
  const std::string acc = accuracy_markdown(a);
  EXPECT_NE(acc.find("| mvv:0.5 tea32(1) gauss | 0.1 | 0/2 | blown up: step 7: temperature runaway"),
            std::string::npos)
      << acc;
  const std::string csv = stability_csv(a);
  EXPECT_NE(csv.find("mvv:0.5 tea32(1) gauss,mvv:0.5,tea32(1),gauss,0.1,2,0,7,\"temperature runaway (k_BT = 150)\",,"),
            std::string::npos)
      << csv;
}

}  // namespace

namespace {

int run_cli(const std::string& args, std::string* err) {
  TempDir logs;
  const fs::path e = logs.path / "stderr";
  const std::string cmd = std::string(DPDRNG_CLI_PATH) + " " + args + " >/dev/null 2>'" + e.string() + "'";
  const int rc = std::system(cmd.c_str());
  std::ifstream in(e);
  *err = std::string(std::istreambuf_iterator<char>(in), {});
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// study/stability-ci.toml end to end: every cell stored, MVV blown up at Δt 0.5 (the run's own guard, not a
// made-up cell), its cells null (no observable stored) and named in every table of the report; the γ = 4.5 series
// read back from the store with its γ; the frontier, ranking and crossing tables and their CSVs written, every
// frontier of the report equal to accuracy_frontier on the stored cells.
TEST(StabilityCli, CiStudyReportsEveryCell) {
  TempDir tmp;
  const std::string cfg = std::string(DPDRNG_SOURCE_DIR) + "/study/stability-ci.toml";
  const fs::path out = tmp.path / "s";
  std::string err;
  ASSERT_EQ(run_cli("study run '" + cfg + "' --out '" + out.string() + "' --threads 2", &err), 0) << err;
  const StudyConfig c = load_config(cfg);
  const auto cells = Store(out).load_all();
  ASSERT_EQ(cells.size(), enumerate_cells(c).size());
  std::size_t unstable = 0;
  for (const auto& cell : cells) {
    if (cell.status != CellStatus::unstable) continue;
    ++unstable;
    EXPECT_NE(cell.reason.find("unstable at step"), std::string::npos) << cell.reason;
    for (const char* k : {"temperature_mean", "pressure_mean", "pressure_conservative_mean", "diffusion_coefficient"})
      EXPECT_FALSE(cell.has(k)) << cell.cell.id() << " stores " << k;
  }
  ASSERT_GT(unstable, 0u) << "MVV at Δt 0.5 should blow up";
  ASSERT_EQ(run_cli("study report '" + out.string() + "'", &err), 0) << err;
  const std::string md = read(out / "report" / "report.md");
  for (const char* section : {"## Stability map", "## Accuracy frontiers", "## The integrators ranked", "## The friction series",
                              "## The crossing: noise error against integrator error",
                              "## Accuracy against cost per unit of simulated time", "## Unstable and failed cells"})
    EXPECT_NE(md.find(section), std::string::npos) << section;
  EXPECT_NE(md.find("| mvv:0.5 tea32(1) gauss | 0.5 | 0/2 | blown up: step "), std::string::npos) << md;
  // The swept integrators, not the scene's unused λ, and no claim of error control over zero tests.
  EXPECT_NE(md.find("integrators swept: mvv:0.5, mvv:0.65, shardlow, scmvv:5, pnhln:10"), std::string::npos)
      << md.substr(0, 1200);
  EXPECT_EQ(md.find("λ = 0.5,"), std::string::npos) << md.substr(0, 1200);
  EXPECT_NE(md.find("Error control: none needed (no tests, no verdicts)"), std::string::npos);
  const StabilityAnalysis a = analyse_stability(c, cells);
  // Four integrators with MT19937 and 32TEA(1) under two feeds, pnhln with MT19937 only, and the γ = 4.5 series of
  // all five with MT19937, each at 4 Δt.
  EXPECT_EQ(a.points.size(), (4u * 2u * 2u + 1u + 5u) * 4u);
  std::size_t gamma_points = 0;
  for (const auto& p : a.points) {
    if (p.integrator == "pnhln:10") {
      EXPECT_EQ(p.generator, "mt19937") << p.method();
    }
    if (p.gamma > 0) {
      ++gamma_points;
      EXPECT_EQ(p.gamma, 4.5);
      EXPECT_TRUE(p.reference) << p.method();
      EXPECT_NE(p.method().find(" γ4.5"), std::string::npos) << p.method();
    }
  }
  EXPECT_EQ(gamma_points, 5u * 4u);
  for (const auto& p : a.points) EXPECT_EQ(p.replicas, p.dt == 0.05 ? 3u : 2u) << p.method() << " at " << p.dt;
  const std::string frontier_csv_text = read(out / "report" / "frontier.csv");
  for (const auto& m : stability_methods(a)) {
    const Frontier f = accuracy_frontier(a, m, Thermometer::kinetic, 0.01);
    EXPECT_NE(md.find("| " + m + " | " + bracket_text(f) + " |"), std::string::npos) << m;
    EXPECT_NE(frontier_csv_text.find(m + ",kinetic,"), std::string::npos) << m;
  }
  // The friction series row of λ = 0.65: its brackets beside the scene's γ ones, from the same frontiers.
  const std::string g45 = "| mvv:0.65 | 4.5 | " +
                          bracket_text(accuracy_frontier(a, "mvv:0.65 mt19937 gauss γ4.5", Thermometer::kinetic, 0.01)) +
                          " | ";
  EXPECT_NE(md.find(g45), std::string::npos) << g45;
  const auto ranks = rank_integrators(a, 0.01);
  ASSERT_EQ(ranks.size(), 5u);
  for (const auto& r : ranks) {
    EXPECT_EQ(r.ranked_by, r.integrator == "pnhln:10" ? Thermometer::configurational : Thermometer::kinetic);
    EXPECT_GT(r.step_seconds, 0) << r.integrator;  // every cell records its step seconds
  }
  EXPECT_EQ(read(out / "report" / "ranking.csv"), ranking_csv(ranks));
  EXPECT_EQ(read(out / "report" / "crossing.csv"), crossing_csv(crossing_rows(a)));
  // The cells name the CPU their costs were measured on, and the ranking says it.
  EXPECT_NE(md.find("measured on " + a.cpus.front()), std::string::npos);
  const std::string csv = read(out / "report" / "stability.csv");
  for (const auto& p : a.points) {
    EXPECT_NE(csv.find(p.method() + "," + p.integrator), std::string::npos) << p.method();
    char dt[32];
    std::snprintf(dt, sizeof dt, "%g", p.dt);
    if (p.all_blew_up()) {
      EXPECT_NE(md.find("| " + p.method() + " | " + dt + " | 0/"), std::string::npos) << p.method();
    }
  }
}

}  // namespace

}  // namespace dpdrng_test::study_test_stability
