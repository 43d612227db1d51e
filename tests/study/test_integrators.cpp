// The integrator as a study factor and the simulated-time scene: a config without [sweep] integrators keeps its
// hash and ids (MVV at the scene's λ), a listed integrator multiplies the cells, names itself in their ids and
// records, reaches the engine's config, and a bad one names the key; scene.time gives each Δt time / Δt steps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "../temp_dir.hpp"
#include "config_text.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/h5.hpp"
#include "dpdrng/study/measure.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng_test::study_test_integrators {

using namespace dpdrng;
using namespace dpdrng::study;
using config_text::error_of;
using config_text::with;

namespace {

const std::string kConfig =
    config_text::StudyText{.name = "i",
                           .generators = {{.rounds = "[1]"}},
                           .scene = "particles = 64\nlambda = 0.6\nsteps = 100\nequilibrate = 10\n",
                           .tests = "ttest_pairs = 4\nnist_generators = [\"tea32\"]\n"}
        .text();

const std::string kSwept =
    with(kConfig, "[[sweep.generator]]", "integrators = [\"mvv:0.5\", \"mvv:0.65\", \"shardlow\"]\n[[sweep.generator]]");

TEST(StudyIntegrators, AbsentFactorKeepsHashIdsAndTheScenesLambda) {
  const StudyConfig c = parse_config(kConfig, "cfg.toml");
  EXPECT_TRUE(c.integrators.empty());
  EXPECT_EQ(c.canonical().count("integrators"), 0u);
  const auto cells = enumerate_cells(c);
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_EQ(cells[0].id(), "mt19937-gauss-dt0.04-rep00");
  EXPECT_EQ(cells[1].id(), "tea32-r01-gauss-distance-dt0.04-rep00");
  const dpd::WaterConfig w = engine_config(cells[1], c, 1, TapPlan{});
  EXPECT_EQ(w.integrator, dpd::Integrator::mvv);
  EXPECT_EQ(w.lambda, 0.6);
}

TEST(StudyIntegrators, ListedIntegratorsMultiplyCellsAndReachTheEngine) {
  const StudyConfig c = parse_config(kSwept, "cfg.toml");
  EXPECT_NE(c.hash, parse_config(kConfig, "cfg.toml").hash);
  const auto cells = enumerate_cells(c);
  ASSERT_EQ(cells.size(), 3u * 4u);
  std::set<std::string> ids;
  for (const auto& cell : cells) {
    ids.insert(cell.id());
    const dpd::WaterConfig w = engine_config(cell, c, 1, TapPlan{});
    if (cell.integrator == "shardlow") {
      EXPECT_EQ(w.integrator, dpd::Integrator::shardlow);
      EXPECT_FALSE(cell.nist) << "Shardlow's sweep is not tapped: " << cell.id();
      EXPECT_TRUE(plan_taps(cell, c, 1).pairs.empty());
    } else {
      EXPECT_EQ(w.integrator, dpd::Integrator::mvv);
      EXPECT_EQ(w.lambda, cell.integrator == "mvv:0.65" ? 0.65 : 0.5) << cell.id();
    }
  }
  EXPECT_EQ(ids.size(), cells.size());
  EXPECT_TRUE(ids.count("tea32-r01-gauss-distance-dt0.04-mvv0.65-rep01"));
  EXPECT_TRUE(ids.count("mt19937-gauss-dt0.04-shardlow-rep00"));
  EXPECT_NO_THROW(validate_scene(c));
}

TEST(StudyIntegrators, BadIntegratorsNameTheKey) {
  for (const char* bad : {"\"rk4\"", "\"mvv:1.5\"", "\"mvv:x\"", "\"mvv:0.5\", \"mvv:0.5\""}) {
    const std::string e =
        error_of(with(kConfig, "[[sweep.generator]]", std::string("integrators = [") + bad + "]\n[[sweep.generator]]"));
    EXPECT_NE(e.find("sweep.integrators"), std::string::npos) << bad << ": " << e;
  }
  EXPECT_NE(error_of(with(kConfig, "[[sweep.generator]]", "integrators = []\n[[sweep.generator]]"))
                .find("sweep.integrators"),
            std::string::npos);
}

// scmvv:K and pnhln:μ are spelt like mvv:λ and reach the engine; scmvv draws its pair noise in the tapped pair
// loop (its cells keep the tests), pnhln draws none: it runs the reference cell alone, untapped.
TEST(StudyIntegrators, ScmvvAndPnhlnReachTheEngine) {
  const StudyConfig c = parse_config(
      with(kConfig, "[[sweep.generator]]", "integrators = [\"scmvv:5\", \"pnhln:2.5\"]\n[[sweep.generator]]"),
      "cfg.toml");
  const auto cells = enumerate_cells(c);
  ASSERT_EQ(cells.size(), 2u * 2u + 2u * 1u);  // scmvv: MT and tea32, pnhln: MT only; 2 replicas
  for (const auto& cell : cells) {
    const dpd::WaterConfig w = engine_config(cell, c, 1, TapPlan{});
    if (cell.integrator == "scmvv:5") {
      EXPECT_EQ(w.integrator, dpd::Integrator::scmvv);
      EXPECT_EQ(w.scmvv_iterations, 5);
      EXPECT_FALSE(plan_taps(cell, c, 1).pairs.empty()) << cell.id();
    } else {
      EXPECT_EQ(w.integrator, dpd::Integrator::pnhln);
      EXPECT_EQ(w.pnhln_mu, 2.5);
      EXPECT_TRUE(cell.reference) << cell.id();
      EXPECT_FALSE(cell.nist);
      EXPECT_TRUE(plan_taps(cell, c, 1).pairs.empty());
    }
  }
  EXPECT_EQ(cells[0].id(), "mt19937-gauss-dt0.04-scmvv5-rep00");
  EXPECT_NO_THROW(validate_scene(c));
}

TEST(StudyIntegrators, BadScmvvAndPnhlnNameTheKey) {
  for (const char* bad : {"\"scmvv\"", "\"scmvv:0\"", "\"scmvv:101\"", "\"scmvv:x\"", "\"scmvv:1.5\"",
                          "\"pnhln\"", "\"pnhln:0\"", "\"pnhln:-1\"", "\"pnhln:nan\"",
                          "\"scmvv:5\", \"scmvv:05\"", "\"pnhln:10\", \"pnhln:1e1\"",
                          "\"mvv:0.5\", \"mvv:0.50\""}) {
    const std::string e =
        error_of(with(kConfig, "[[sweep.generator]]", std::string("integrators = [") + bad + "]\n[[sweep.generator]]"));
    EXPECT_NE(e.find("sweep.integrators"), std::string::npos) << bad << ": " << e;
  }
}

// The record carries the integrator when the sweep names one, and only then (the records of a study without the
// factor lack the attribute).
TEST(StudyIntegrators, CellRecordsCarryTheIntegrator) {
  TempDir tmp;
  const auto swept = enumerate_cells(parse_config(kSwept, "cfg.toml"));
  const auto plain = enumerate_cells(parse_config(kConfig, "cfg.toml"));
  std::lock_guard lock(h5::lock());
  h5::Handle f = h5::create_file((tmp.path / "cells.h5").string());
  for (const Cell* cell : {&swept[5], &plain[1]}) {
    CellResult r;
    r.cell = *cell;
    h5::Handle g = h5::create_group(f.id(), cell->id());
    write_cell(g.id(), r);
    EXPECT_EQ(h5::read_attributes(g.id()).count("cell.integrator"), cell->integrator.empty() ? 0u : 1u);
    const CellResult back = read_cell(g.id());
    EXPECT_EQ(back.cell.integrator, cell->integrator);
    EXPECT_EQ(back.cell.id(), cell->id());
  }
}

TEST(StudyTime, EachDtRunsTheSameSimulatedTime) {
  const std::string timed = with(with(kSwept, "steps = 100\nequilibrate = 10", "time = 2.0\nequilibrate_time = 0.2"),
                                 "lambda = 0.6", "lambda = 0.6\ndt = [0.01, 0.04]");
  const StudyConfig c = parse_config(timed, "cfg.toml");
  EXPECT_EQ(c.scene.steps_at(0.01), 200);
  EXPECT_EQ(c.scene.equilibrate_at(0.01), 20);
  EXPECT_EQ(c.scene.steps_at(0.04), 50);
  EXPECT_EQ(c.scene.equilibrate_at(0.04), 5);
  for (const auto& cell : enumerate_cells(c)) {
    const dpd::WaterConfig w = engine_config(cell, c, 1, TapPlan{});
    EXPECT_NEAR(double(w.steps) * w.dt, 2.0, 1e-12) << cell.id();
  }
  // Without scene.time the canonical form has no time key, so such configs keep their hash.
  EXPECT_EQ(parse_config(kConfig, "cfg.toml").canonical()["scene"].count("time"), 0u);
  EXPECT_NE(error_of(with(kConfig, "steps = 100", "steps = 100\ntime = 2.0")).find("scene.time"), std::string::npos);
  EXPECT_NE(error_of(with(kConfig, "steps = 100\nequilibrate = 10", "equilibrate_time = 1.0")).find("equilibrate_time"),
            std::string::npos);
  EXPECT_NE(error_of(with(kConfig, "steps = 100\nequilibrate = 10", "time = 0.05")).find("scene.time"),
            std::string::npos);
}

}  // namespace

}  // namespace dpdrng_test::study_test_integrators
