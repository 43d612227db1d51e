// `dpdrng bench dpd`: the scaling comparison's JSON contract and its refusals. Speeds are not asserted (the
// CI machine is shared); what is checked is that every measured pair and side-by-side run is reported.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "run_cli.hpp"

namespace dpdrng::cli_test::test_bench_dpd {
namespace {

TEST(CliBenchDpd, ScalingOnlyReportsEveryPairAndTheSideBySideRuns) {
  const Result r = run("bench dpd --scaling-only --repeat 2 --steps-cells 5 --particles-cells 3000 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("throughput"));
  EXPECT_FALSE(j.contains("paper"));
  ASSERT_EQ(j["scaling"].size(), 2u);
  EXPECT_EQ(j["scaling"][0]["threads"], 1);
  EXPECT_EQ(j["scaling"][1]["threads"], 2);
  EXPECT_EQ(j["scaling"][0]["particles"], 3000);
  for (const char* key : {"scaling_pair_ratios", "scaling_side_by_side_ratios"}) {
    ASSERT_EQ(j[key].size(), 2u) << key;
    for (double v : j[key]) EXPECT_TRUE(std::isfinite(v) && v > 0) << key << " " << v;
  }
  for (const auto& m : j["scaling"]) {
    // Cells of width r_c: a bead meets its own cell's later beads and 13 neighbour cells' (13.5 cells, ~40
    // candidates at ρ = 3) for about 2πρ/3 ≈ 6.3 pairs inside r_c.
    EXPECT_GT(m["candidates_per_pair"].get<double>(), 5.0) << m;
    EXPECT_LT(m["candidates_per_pair"].get<double>(), 8.0) << m;
    EXPECT_GT(m["ns_per_pair"].get<double>(), 0.0) << m;
  }
  // The governor's probes of one thread: a share of the two-thread runs' steps, never all of them.
  const double share = j["scaling_two_thread_runs_one_thread_step_share"];
  EXPECT_GE(share, 0.0);
  EXPECT_LT(share, 1.0);
  // The median of two pairs' ratios is their mean.
  const double a = j["scaling_side_by_side_ratios"][0], b = j["scaling_side_by_side_ratios"][1];
  EXPECT_EQ(j["scaling_side_by_side_2_copies"].get<double>(), 0.5 * (a + b));
}

// Beside a busy loop: the three scenes, each pair's ratio, and the share of the two-thread runs' steps that their
// team governor ran on one thread. The 256-bead scene runs on one thread whatever is asked, so all its steps do.
TEST(CliBenchDpd, OversubscribedReportsTheStepsRunOnOneThread) {
  const Result r = run("bench dpd --oversubscribe --repeat 2 --steps-all 20 --steps-cells 5 --particles-cells 3000 "
                       "--json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["oversubscribed"].size(), 3u);
  for (const auto& o : j["oversubscribed"]) {
    ASSERT_EQ(o["pair_ratios"].size(), 2u) << o;
    const double share = o["one_thread_step_share"];
    EXPECT_GE(share, 0.0) << o;
    EXPECT_LE(share, 1.0) << o;
  }
  EXPECT_EQ(j["oversubscribed"][0]["two_threads"]["threads"], 1);
  EXPECT_EQ(j["oversubscribed"][0]["one_thread_step_share"], 1.0);
  EXPECT_EQ(j["oversubscribed"][1]["two_threads"]["threads"], 2);  // the team forced
}

// Shardlow's coloured sweep at one and two threads: both runs reported with their pairs inside r_c per second.
TEST(CliBenchDpd, ScalingTimesShardlow) {
  const Result r = run("bench dpd --scaling-only --integrator shardlow --repeat 1 --steps-cells 5 "
                       "--particles-cells 3000 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["context"]["integrator"], "shardlow");
  ASSERT_EQ(j["scaling"].size(), 2u);
  for (const auto& m : j["scaling"]) {
    // ρ = 3: about 2πρ/3 ≈ 6.3 pairs per bead inside r_c.
    const double per_bead = m["pair_steps_per_s"].get<double>() / m["particle_steps_per_s"].get<double>();
    EXPECT_GT(per_bead, 5.0) << m;
    EXPECT_LT(per_bead, 8.0) << m;
  }
}

// A list of integrators times each one's step against GW-MVV's (mvv added when not listed), with Jdpd's
// published factor beside the four schemes it ships and null for a K it does not report.
TEST(CliBenchDpd, IntegratorsSideBySideAgainstMvv) {
  const Result r = run("bench dpd --integrator shardlow,scmvv:1,scmvv:2,pnhln --pairs all --repeat 1 "
                       "--steps-all 5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["integrators"].size(), 5u);
  EXPECT_EQ(j["integrators"][0]["integrator"], "mvv");
  EXPECT_EQ(j["integrators"][0]["factor_vs_mvv"], 1.0);
  for (const auto& c : j["integrators"]) {
    EXPECT_GT(c["factor_vs_mvv"].get<double>(), 0.0) << c;
    EXPECT_EQ(c["factor_vs_mvv"].get<double>(),
              c["median_s"].get<double>() / j["integrators"][0]["median_s"].get<double>());
  }
  EXPECT_EQ(j["integrators"][2]["integrator"], "scmvv:1");
  EXPECT_EQ(j["integrators"][2]["jdpd_factor"], 1.4);
  EXPECT_TRUE(j["integrators"][3]["jdpd_factor"].is_null());  // scmvv:2
  EXPECT_EQ(j["integrators"][4]["integrator"], "pnhln:10");
}

TEST(CliBenchDpd, RefusesBadArgumentsBeforeAnyRun) {
  for (const char* args : {"bench dpd --repeat 0", "bench dpd --scaling-only --no-scaling",
                           "bench dpd --integrator shardlow", "bench dpd --scaling-only --integrator verlet",
                           "bench dpd --integrator mvv,scmvv:0", "bench dpd --integrator mvv,pnhln --scaling-only",
                           "bench dpd --generators tea32,nope", "bench dpd --rounds 0", "bench dpd --pairs some"}) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_FALSE(r.err.empty()) << args;
  }
}

}  // namespace
}  // namespace dpdrng::cli_test::test_bench_dpd
