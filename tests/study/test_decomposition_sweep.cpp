// The decomposition check's runs, `dpdrng decompose` end to end, and the sweep config it reads.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"
#include "../cli/run_cli.hpp"
#include "../dpd/scale.hpp"
#include "../temp_dir.hpp"

namespace dpdrng::study::test_decomposition_sweep {
namespace {

using namespace dpdrng::dpd;

DecompNoise noise(const std::string& gen, int rounds, const std::string& seeding) {
  DecompNoise n;
  n.generator = rng::validated({gen, rounds});
  n.seeding = parse_decomp_seeding(seeding);
  return n;
}

TEST(DecompositionRun, MomentumIsConservedUndecomposedAndDriftsWithDistanceSeeding) {
  DecompConfig c;
  c.water.steps = test_scale::scaled(200, 40);
  c.water.equilibrate = 10;
  c.chi2_every = 0;
  c.ttest_pairs = 0;
  c.noise = noise("tea32", 8, "distance");
  c.domains = parse_domains("2,2,1");
  const DecompResult d = run_decomposition(c);
  ASSERT_TRUE(d.has_reference);
  EXPECT_EQ(d.decomposed.status.text(), "ok");
  EXPECT_LT(d.reference.momentum_drift, 1e-12);
  EXPECT_EQ(d.reference.boundary.boundary, 0u);
  EXPECT_GT(d.decomposed.boundary.zeta_mismatch, 0u);
  EXPECT_GT(d.decomposed.momentum_drift, 1e-3);

  c.noise = noise("tea32", 8, "pair-step");
  c.reference = false;
  const DecompResult p = run_decomposition(c);
  EXPECT_EQ(p.decomposed.boundary.zeta_mismatch, 0u);
  EXPECT_GT(p.decomposed.boundary.separation_mismatch, 0u);
  EXPECT_LT(p.decomposed.momentum_drift, 1e-10);
}

TEST(DecompositionRun, RejectsBadConfigs) {
  DecompConfig c;
  c.ttest_pairs = 300;
  EXPECT_THROW(run_decomposition(c), InputError);
}

TEST(DecomposeCli, PairStepAgreesAndDistanceDoesNot) {
  const std::string common = "decompose --domains 2,2,1 -g tea32 -r 8 --steps 20 --equilibrate 5 --chi2-every 5 "
                             "--ttest-pairs 2 --json --seeding ";
  const cli_test::Result p = cli_test::run(common + "pair-step");
  ASSERT_EQ(p.code, 0) << p.out;
  const auto jp = nlohmann::json::parse(p.out);
  EXPECT_EQ(jp["domains"], "2x2x1");
  EXPECT_EQ(jp["seeding"], "pair-step");
  EXPECT_GT(jp["decomposed"]["boundary"]["boundary_pairs"].get<int>(), 0);
  EXPECT_EQ(jp["decomposed"]["boundary"]["zeta_mismatches"], 0);
  EXPECT_EQ(jp["randomness"]["chi2_tests"], 3);

  const cli_test::Result d = cli_test::run(common + "distance --no-reference");
  ASSERT_EQ(d.code, 0) << d.out;
  const auto jd = nlohmann::json::parse(d.out);
  EXPECT_GT(jd["decomposed"]["boundary"]["zeta_mismatches"].get<int>(), 0);
  EXPECT_FALSE(jd.contains("reference"));
}

TEST(DecomposeCli, BadInputExitsWithTwo) {
  EXPECT_EQ(cli_test::run("decompose --domains 0 --steps 20 --equilibrate 5").code, 2);
  EXPECT_EQ(cli_test::run("decompose --seeding grid:3 --steps 20 --equilibrate 5").code, 2);
  EXPECT_EQ(cli_test::run("decompose -g mt19937 --steps 20 --equilibrate 5").code, 2);
  EXPECT_EQ(cli_test::run("decompose --scene bilayer").code, 2);
  EXPECT_EQ(cli_test::run("decompose --study /nonexistent/decomposition.toml").code, 2);
}

const char* kSweep = R"(
name = "t"
domains = ["2", "2,2,1"]
seedings = ["distance", "grid:20"]
[[generators]]
name = "tea32"
rounds = [1, 8]
[[generators]]
name = "philox4x32"
[scene]
steps = 30
equilibrate = 10
[tests]
chi2_every = 10
)";

TEST(DecompositionSweep, ParsesAndChecksKeys) {
  const DecompSweep s = parse_decomp_sweep(kSweep, "<test>");
  ASSERT_EQ(s.generators.size(), 3u);
  EXPECT_EQ(rng::describe(s.generators[1]), "tea32(8)");
  EXPECT_EQ(s.generators[2].rounds, 10);  // philox4x32's default
  ASSERT_EQ(s.seedings.size(), 2u);
  EXPECT_EQ(s.seedings[1].grid_bits, 20);
  EXPECT_EQ(s.domains[1].n, (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(s.base.water.steps, 30);
  EXPECT_EQ(s.base.chi2_every, 10);
  EXPECT_THROW(parse_decomp_sweep(std::string(kSweep) + "bogus = 1\n", "<test>"), InputError);
  EXPECT_THROW(parse_decomp_sweep("domains = [\"2\"]\n", "<test>"), InputError);  // no generators
  std::string bad = kSweep;
  bad.replace(bad.find("steps = 30"), 10, "stepz = 30");
  EXPECT_THROW(parse_decomp_sweep(bad, "<test>"), InputError);
  bad = kSweep;
  bad.replace(bad.find("grid:20"), 7, "grid:99");
  EXPECT_THROW(parse_decomp_sweep(bad, "<test>"), InputError);
}

TEST(DecompositionSweep, RunsAndWritesItsTable) {
  std::string text = kSweep;
  text.replace(text.find("rounds = [1, 8]"), 15, "rounds = [8]");
  text.replace(text.find("name = \"philox4x32\""), 19, "name = \"tea64\"");
  const DecompSweep s = parse_decomp_sweep(text, "<test>");
  TempDir dir;
  const CellStore store(dir.path / "store");
  open_decomp_store(store, s);
  const DecompRunSummary sum = run_decomp_sweep(s, store, {});
  EXPECT_EQ(sum.computed, 4u);
  std::vector<std::string> missing;
  const auto rows = load_decomp_rows(s, store, &missing);
  EXPECT_TRUE(missing.empty());
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& r : rows) EXPECT_TRUE(r.has_reference) << r.generator << " " << r.seeding << " " << r.domains;
  // The second grid reuses the first one's undecomposed run.
  EXPECT_EQ(rows[0].reference.temperature.mean, rows[1].reference.temperature.mean);
  EXPECT_EQ(rows[0].domains, "2x1x1");
  EXPECT_EQ(rows[1].domains, "2x2x1");
  const std::string md = write_decomp_outputs(s, rows, (dir.path / "out").string(), nullptr);
  EXPECT_NE(md.find(" | grid:20 | 2x2x1 |"), std::string::npos) << md;
  EXPECT_TRUE(std::filesystem::exists(dir.path / "out" / "charts" / "mismatch_2x2x1.gp"));
  EXPECT_TRUE(std::filesystem::exists(dir.path / "out" / "charts" / "drift_2x1x1.gp"));
  std::ifstream csv(dir.path / "out" / "table.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header.rfind("generator,seeding,distribution,domains", 0), 0u);
  EXPECT_EQ(first.rfind("tea32(8),distance,gauss,2x1x1,256,30,ok,", 0), 0u) << first;
}

}  // namespace
}  // namespace dpdrng::study::test_decomposition_sweep
