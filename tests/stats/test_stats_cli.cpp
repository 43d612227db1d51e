// The chi2, ttest, corr, moments, gof and chi2d subcommands end to end: the built executable, its output and its exit codes
// (0 = ran, whatever the verdict; 2 = bad input).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include <algorithm>
#include <unistd.h>

namespace dpdrng_test::stats_test_stats_cli {

namespace {

struct CliRun {
  int code = -1;
  std::string out;
};

const std::string kCli = std::string("\"") + DPDRNG_CLI_PATH + "\"";

// A shell command line (pipes and redirections allowed); standard error stays on the terminal unless redirected.
CliRun shell(const std::string& cmd) {
  CliRun r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

CliRun run_cli(const std::string& args) { return shell(kCli + " " + args); }

// `dpdrng gen ... --format raw | dpdrng <args>`
CliRun piped(const std::string& g, int rounds, int count, const std::string& args) {
  return shell(kCli + " gen -g " + g + " -r " + std::to_string(rounds) + " --count " +
         std::to_string(count) + " --format raw | " + kCli + " " + args);
}

std::filesystem::path temp_file(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() / ("dpdrng_stats_cli_" + std::to_string(getpid()) + name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

}  // namespace

// The paper's χ² setting straight from the generator: 32 640 words, 16 Sturges bins, 15 dof.
TEST(StatsCli, Chi2OnAGeneratorPipe) {
  const CliRun r = piped("tea32", 32, 32640, "chi2 --input - --format u64 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["n"], 32640);
  EXPECT_EQ(j["bins"], 16);
  EXPECT_EQ(j["dof"], 15);
  EXPECT_EQ(j["counts"].size(), 16u);
  EXPECT_EQ(j["verdict"], "pass");
}

// tea32(1) on 32 640 consecutive counters: the verdict is "fail", and that is data: exit 0.
TEST(StatsCli, FailingVerdictStillExitsZero) {
  const CliRun r = piped("tea32", 1, 32640, "chi2 --input - --format u64");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("verdict         fail"), std::string::npos) << r.out;
}

TEST(StatsCli, PassFractionOverChunks) {
  const CliRun r = piped("tea32", 32, 20000, "ttest -i - -f u64 --per 1000 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["chunks"], 20);
  EXPECT_EQ(j["p_values"].size(), 20u);
  EXPECT_EQ(j["pass_fraction"]["applicable"], 20);
  EXPECT_EQ(j["pass_fraction"]["verdict"], "pass");
  const CliRun human = piped("tea32", 32, 2500, "chi2 -i - -f u64 --per 1000");
  EXPECT_EQ(human.code, 0);
  EXPECT_NE(human.out.find("500 trailing values not tested"), std::string::npos) << human.out;
}

TEST(StatsCli, TextInputAndFixedBins) {
  std::string s;
  for (int i = 0; i < 100; ++i) s += std::to_string((i + 0.5) / 100.0) + "\n";
  const auto f = temp_file("bins.txt", s);
  const CliRun r = run_cli("chi2 -i " + f.string() + " -f text --bins 4 --json");
  std::filesystem::remove(f);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["bins"], 4);
  EXPECT_EQ(j["counts"], nlohmann::json::array({25, 25, 25, 25}));
  EXPECT_EQ(j["statistic"], 0.0);
}

TEST(StatsCli, CorrOnStreamAndOnPairNoise) {
  const CliRun stream = piped("tea32", 1, 5000, "corr -i - -f u64 --lags 1,2 --json");
  ASSERT_EQ(stream.code, 0) << stream.out;
  const auto j = nlohmann::json::parse(stream.out);
  ASSERT_EQ(j["checks"].size(), 2u);
  EXPECT_EQ(j["checks"][0]["verdict"], "fail");
  EXPECT_GT(j["checks"][0]["r"].get<double>(), 0.9);

  const CliRun pairs = piped("tea32", 32, 6000, "corr -i - -f u64 --pairs 100 --json");
  ASSERT_EQ(pairs.code, 0) << pairs.out;
  const auto k = nlohmann::json::parse(pairs.out);
  EXPECT_EQ(k["steps"], 60);
  ASSERT_EQ(k["checks"].size(), 2u);
  EXPECT_EQ(k["checks"][0]["n"], 99 * 60);
  EXPECT_EQ(k["checks"][1]["n"], 100 * 59);
  const CliRun ragged = piped("tea32", 32, 6001, "corr -i - -f u64 --pairs 100 2>&1");
  EXPECT_EQ(ragged.code, 2) << ragged.out;
}

// Bad input: exit 2 with a one-line reason on standard error.
TEST(StatsCli, BadInputExitsTwo) {
  const auto trunc = temp_file("trunc.bin", std::string(12, '\x01'));
  const auto text = temp_file("bad.txt", "0.1\n0.2\nzero point three\n");
  const auto range = temp_file("range.txt", "0.1\n1.5\n");
  const std::vector<std::string> cases{
      "chi2 -i " + trunc.string() + " -f u64",          // 12 bytes: not whole 8-byte words
      "ttest -i " + text.string() + " -f text",          // a line that is not a number
      "chi2 -i " + range.string() + " -f text",          // 1.5 is outside [0,1)
      "chi2 -i /nonexistent/x -f u64",                   // cannot open
      "chi2 -i - -f u64 < /dev/null",                    // no values
      "chi2 -i " + range.string() + " -f text --bins 1",  // one bin tests nothing
      "chi2 -i " + range.string() + " -f hex",           // unknown format
      "ttest -i " + range.string() + " -f text --per 0",  // empty chunks
      "corr -i " + range.string() + " -f text --offsets 2",  // pair offsets on a stream without pairs
  };
  for (const std::string& args : cases) {
    const CliRun r = run_cli(args + " 2>&1");
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << "\n" << r.out;
  }
  for (const auto& f : {trunc, text, range}) std::filesystem::remove(f);
}

// The tests on ζ end to end: the hand-worked sample {1, 2, 3, 4, 10} through moments (mean 4, s² = 12.5,
// ⟨x²⟩ = 26), the five-point U(−√3, √3) sample of AndersonDarling.HandWorkedStatistic through gof, and a
// generator's words through chi2d both ways.
TEST(StatsCli, MomentsGofAndChi2dEndToEnd) {
  const auto f = temp_file("moments.txt", "1\n2\n3\n4\n10\n");
  const CliRun m = run_cli("moments -i " + f.string() + " -f text --json");
  std::filesystem::remove(f);
  ASSERT_EQ(m.code, 0) << m.out;
  const auto jm = nlohmann::json::parse(m.out);
  EXPECT_DOUBLE_EQ(jm["mean"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(jm["variance"].get<double>(), 12.5);
  EXPECT_DOUBLE_EQ(jm["second_moment"].get<double>(), 26.0);
  EXPECT_EQ(jm["variance_ci"].size(), 2u);

  std::string five;
  for (double u : {0.1, 0.3, 0.5, 0.7, 0.9}) five += std::to_string(std::sqrt(3.0) * (2 * u - 1)) + "\n";
  const auto g = temp_file("gof.txt", five);
  const CliRun a = run_cli("gof -i " + g.string() + " -f text --target uniform --json");
  std::filesystem::remove(g);
  ASSERT_EQ(a.code, 0) << a.out;
  const auto ja = nlohmann::json::parse(a.out);
  EXPECT_NEAR(ja["statistic"].get<double>(), 0.13008, 1e-4);  // text input keeps 6 digits
  EXPECT_EQ(ja["verdict"], "pass");

  // 32TEA(32) passes with either pairing; 32TEA(1) on consecutive counters fails with its halves.
  for (const char* pairs : {"halves", "words"}) {
    const CliRun r = piped("tea32", 32, 40000, std::string("chi2d -i - -f u64 --bins 8 --json --pairs ") + pairs);
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["pairs"], pairs);
    EXPECT_EQ(j["n"], std::string(pairs) == "halves" ? 40000 : 20000);
    EXPECT_EQ(j["dof"], 63);
    EXPECT_EQ(j["verdict"], "pass") << pairs;
  }
  const CliRun weak = piped("tea32", 1, 40000, "chi2d -i - -f u64 --bins 8 --json");
  ASSERT_EQ(weak.code, 0) << weak.out;
  EXPECT_EQ(nlohmann::json::parse(weak.out)["verdict"], "fail");
}

}  // namespace dpdrng_test::stats_test_stats_cli
