// `dpdrng decompose` end to end and the sweep config it reads.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/decomposition_sweep.hpp"

namespace dpdrng::dpd {
namespace {

struct CliRun {
  int code = -1;
  std::string out;
};

CliRun run_cli(const std::string& args) {
  CliRun r;
  const std::string cmd = std::string("\"") + DPDRNG_CLI_PATH + "\" " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(DecomposeCli, PairStepAgreesAndDistanceDoesNot) {
  const std::string common = "decompose --domains 2,2,1 -g tea32 -r 8 --steps 20 --equilibrate 5 --chi2-every 5 "
                             "--ttest-pairs 2 --json --seeding ";
  const CliRun p = run_cli(common + "pair-step");
  ASSERT_EQ(p.code, 0) << p.out;
  const auto jp = nlohmann::json::parse(p.out);
  EXPECT_EQ(jp["domains"], "2x2x1");
  EXPECT_EQ(jp["seeding"], "pair-step");
  EXPECT_GT(jp["decomposed"]["boundary"]["boundary_pairs"].get<int>(), 0);
  EXPECT_EQ(jp["decomposed"]["boundary"]["zeta_mismatches"], 0);
  EXPECT_EQ(jp["randomness"]["chi2_tests"], 3);

  const CliRun d = run_cli(common + "distance --no-reference");
  ASSERT_EQ(d.code, 0) << d.out;
  const auto jd = nlohmann::json::parse(d.out);
  EXPECT_GT(jd["decomposed"]["boundary"]["zeta_mismatches"].get<int>(), 0);
  EXPECT_FALSE(jd.contains("reference"));
}

TEST(DecomposeCli, BadInputExitsWithTwo) {
  EXPECT_EQ(run_cli("decompose --domains 0 --steps 20 --equilibrate 5").code, 2);
  EXPECT_EQ(run_cli("decompose --seeding grid:3 --steps 20 --equilibrate 5").code, 2);
  EXPECT_EQ(run_cli("decompose -g mt19937 --steps 20 --equilibrate 5").code, 2);
  EXPECT_EQ(run_cli("decompose --scene bilayer").code, 2);
  EXPECT_EQ(run_cli("decompose --study /nonexistent/decomposition.toml").code, 2);
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
  const auto rows = run_decomp_sweep(s);
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& r : rows) EXPECT_TRUE(r.has_reference) << r.generator << " " << r.seeding << " " << r.domains;
  // The second grid reuses the first one's undecomposed run.
  EXPECT_EQ(rows[0].reference.temperature.mean, rows[1].reference.temperature.mean);
  const auto dir = std::filesystem::temp_directory_path() / ("dpdrng_decomp_" + std::to_string(getpid()));
  const std::string md = write_decomp_outputs(s, rows, dir.string(), nullptr);
  EXPECT_NE(md.find(" | grid:20 | 2x2x1 |"), std::string::npos) << md;
  EXPECT_TRUE(std::filesystem::exists(dir / "table.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "decomposition_2x2x1.gp"));
  std::ifstream csv(dir / "table.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("generator,seeding,distribution,domains", 0), 0u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dpdrng::dpd
