// `dpdrng bench dpd` beside LAMMPS, without LAMMPS: absent, the comparison is "not applicable: LAMMPS not built"
// (null in JSON, never 0); with a stand-in launcher that writes a LAMMPS log, each scene's ratios (cells, all
// pairs) are the logged loop times' against dpdrng's own; a launcher that fails leaves them not applicable with LAMMPS's ERROR line. The real
// LAMMPS runs under ctest -L lammps (tests/lammps/bench_dpd.sh).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <tuple>
#include <nlohmann/json.hpp>

#include "../temp_dir.hpp"
#include "run_cli.hpp"

namespace dpdrng::cli_test::test_bench_dpd_lammps {
namespace {

// A short table: tea32(1) on both scenes, one round, no scaling comparison.
constexpr const char* kShort =
    "bench dpd --generators tea32 --rounds 1 --pairs all,cells --particles-cells 3000 --steps-cells 5 --steps-all 5 "
    "--repeat 1 --no-scaling --json";

// Runs `dpdrng ARGS` in `dir` with PATH = `dir` only, so that no lmp_dpdrng is found unless named.
Result run_in(const std::filesystem::path& dir, const std::string& args) {
  return run_after("cd \"" + dir.string() + "\" && PATH=\"" + dir.string() + "\" ", args);
}

void expect_not_applicable(const nlohmann::json& j, const std::string& why) {
  EXPECT_EQ(j["lammps"]["not_applicable"], why) << j["lammps"];
  EXPECT_EQ(j["lammps_all_pairs"]["not_applicable"], why) << j["lammps_all_pairs"];
  ASSERT_EQ(j["throughput"].size(), 6u);  // per scene: zeta = 0, unhashed, tea32(1)
  for (const auto& row : j["throughput"]) {
    EXPECT_TRUE(row["dpdrng_over_lammps"].is_null()) << row;
    EXPECT_EQ(row["dpdrng_over_lammps_not_applicable"], why) << row;
  }
}

TEST(CliBenchDpdLammps, AbsentIsNotApplicable) {
  const TempDir dir;
  const Result r = run_in(dir.path, kShort);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_not_applicable(nlohmann::json::parse(r.out), "LAMMPS not built");
  const Result text = run_in(dir.path, std::string(kShort).substr(0, std::string(kShort).size() - 7));
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("beside LAMMPS: not applicable: LAMMPS not built"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("cells: not applicable: LAMMPS not built"), std::string::npos) << text.out;
}

TEST(CliBenchDpdLammps, NoLammpsIsNotApplicable) {
  const TempDir dir;
  const Result r = run_in(dir.path, std::string(kShort) + " --no-lammps");
  ASSERT_EQ(r.code, 0) << r.err;
  expect_not_applicable(nlohmann::json::parse(r.out), "--no-lammps");
}

// A stand-in for lmp_dpdrng running `body` with the log's path in $log and the scene's bead count (its input's
// create_atoms line) in $n.
std::string fake_launcher(const std::filesystem::path& dir, const std::string& body) {
  const auto path = dir / "fake_lmp";
  std::ofstream(path) << "#!/bin/sh\nwhile [ $# -gt 0 ]; do [ \"$1\" = -log ] && log=$2; [ \"$1\" = -in ] && in=$2; "
                         "shift; done\n"
                         // Shell built-ins only: PATH holds the test's folder alone.
                         "while read -r a b c d rest; do [ \"$a $b $c\" = 'create_atoms 1 random' ] && n=$d; "
                         "done < \"$in\"\n"
                      << body;
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path.string();
}

// Each scene's last run took 0.5 s for its 5 steps: the ratios are the rows' speeds against those.
TEST(CliBenchDpdLammps, RatiosFromTheLoggedLoopTime) {
  const TempDir dir;
  const std::string lmp = fake_launcher(
      dir.path, "printf 'Loop time of 0.1 on 1 procs for 50 steps with %s atoms\\n\\n"
                "Loop time of 0.5 on 1 procs for 5 steps with %s atoms\\n' $n $n > \"$log\"\n");
  const Result r = run_in(dir.path, std::string(kShort) + " --lammps " + lmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& [key, pairs, beads, gamma] :
       {std::tuple{"lammps", "cells", 3000.0, 4.5}, std::tuple{"lammps_all_pairs", "all", 256.0, 6.75}}) {
    const auto& l = j[key];
    EXPECT_EQ(l["launcher"], lmp);
    EXPECT_EQ(l["own_particle_steps_per_s"].get<double>(), beads * 5 / 0.5) << key;
    EXPECT_EQ(l["hash_particle_steps_per_s"].get<double>(), beads * 5 / 0.5) << key;
    EXPECT_EQ(l["own_style"], "pair_style dpd 1 1 2");
    EXPECT_EQ(l["hash_style"], "pair_style dpd/hash 1 1 tea32 1 distance gauss halves 1");
    EXPECT_EQ(l["scene"]["gamma"], gamma) << key;
    EXPECT_EQ(l["threads"], 1) << key;
    ASSERT_EQ(l["dpdrng_seconds"].size(), 1u);
    EXPECT_EQ(l["dpdrng_over_own"].get<double>(),
              l["dpdrng_particle_steps_per_s"].get<double>() / l["own_particle_steps_per_s"].get<double>());
    for (const auto& row : j["throughput"]) {
      if (row["pairs"] != pairs) continue;
      ASSERT_TRUE(row["dpdrng_over_lammps"].is_number()) << row;
      EXPECT_EQ(row["dpdrng_over_lammps"].get<double>(),
                row["particle_steps_per_s"].get<double>() / l["own_particle_steps_per_s"].get<double>());
      EXPECT_TRUE(row["dpdrng_over_lammps_not_applicable"].is_null()) << row;
    }
  }
}

TEST(CliBenchDpdLammps, AFailingLammpsIsNotApplicableWithItsReason) {
  const TempDir dir;
  const std::string lmp =
      fake_launcher(dir.path, "echo 'ERROR: Unrecognized pair style dpd/hash (src/force.cpp:279)' > \"$log\"\nexit 1\n");
  const Result r = run_in(dir.path, std::string(kShort) + " --lammps " + lmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"lammps", "lammps_all_pairs"}) {
    const std::string why = j[key]["not_applicable"];
    EXPECT_NE(why.find("ERROR: Unrecognized pair style dpd/hash"), std::string::npos) << why;
  }
  for (const auto& row : j["throughput"]) EXPECT_TRUE(row["dpdrng_over_lammps"].is_null()) << row;
}

TEST(CliBenchDpdLammps, RefusesABadLauncherBeforeAnyRun) {
  expect_bad("bench dpd --lammps /nonexistent/lmp_dpdrng", "--lammps");
  expect_bad("bench dpd --lammps /bin/sh --no-lammps", "--no-lammps");
}

}  // namespace
}  // namespace dpdrng::cli_test::test_bench_dpd_lammps
