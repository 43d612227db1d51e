// `dpdrng nist`, its per-test subcommands and `dpdrng bench nist`, run as a user would: exit codes, TSV shape.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include "nist_test_util.hpp"

namespace dpdrng_test::stats_nist_test_nist_cli {

using namespace dpdrng::stats::nist;

namespace {

struct CliRun {
  int code;
  std::string out;
};

CliRun run_cli(const std::string& args) {
  const std::string cmd = std::string(DPDRNG_CLI_PATH) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, ""};
  std::string out;
  char buf[4096];
  while (std::size_t got = std::fread(buf, 1, sizeof buf, p)) out.append(buf, got);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// The first 10^5 bits of e as the reference's ASCII data files hold them (wrapped lines, as data.e is), in a
// file of this process's own: ctest runs the tests of this file as parallel processes, and one writing a shared
// file while another reads it would hand the reader a truncated input.
// Removed when the process ends.
struct ProcessFile {
  std::string path;
  ~ProcessFile() { std::remove(path.c_str()); }
};

const std::string& e_file() {
  static const ProcessFile file{[] {
    const std::string p = ::testing::TempDir() + "dpdrng_nist_e_" + std::to_string(getpid()) + ".txt";
    const BitSequence s = testing_::cached_expansion(testing_::Constant::e);
    std::ofstream f(p);
    for (std::size_t i = 0; i < 100000; ++i) f << (s[i] ? '1' : '0') << (i % 64 == 63 ? "\n" : "");
    return p;
  }()};
  return file.path;
}

int count_lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(NistCli, TsvHas188LinesWithNotApplicableMarked) {
  const CliRun r = run_cli("nist --input " + e_file() + " --format ascii --tsv");
  ASSERT_EQ(r.code, 0);
  EXPECT_EQ(count_lines(r.out), 188);
  EXPECT_NE(r.out.find("1\tFrequency\t-\t"), std::string::npos);
  EXPECT_NE(r.out.find("1\tUniversal\t-\tn/a"), std::string::npos);  // 10^5 bits < 387840
  EXPECT_NE(r.out.find("1\tNonOverlappingTemplate\t000000001\t"), std::string::npos);
}

TEST(NistCli, DefaultOutputIsTheFinalAnalysisReport) {
  const CliRun r = run_cli("nist -i " + e_file() + " --streams 2 --stream-bits 50000 --tests frequency,Runs");
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find(" C1  C2  C3  C4  C5  C6  C7  C8  C9 C10  P-VALUE  PROPORTION  STATISTICAL TEST"),
            std::string::npos);
  EXPECT_NE(r.out.find("Runs"), std::string::npos);
}

TEST(NistCli, BadInputExitsWithTwo) {
  EXPECT_EQ(run_cli("nist -i " + e_file() + " --streams 3 --stream-bits 100000").code, 2);  // too few bits
  EXPECT_EQ(run_cli("nist -i /nonexistent/file").code, 2);
  EXPECT_EQ(run_cli("nist -i " + e_file() + " --tests NoSuchTest").code, 2);
  EXPECT_EQ(run_cli("nist -i " + e_file() + " --format hex").code, 2);
  EXPECT_EQ(run_cli("nist").code, 2);  // no input
}

TEST(NistCli, PerTestSubcommandAndJson) {
  const CliRun r = run_cli("nist runs -i " + e_file() + " --json");
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("\"test\": \"Runs\""), std::string::npos);
  const CliRun t = run_cli("nist non-overlapping-template -i " + e_file() + " --template 000000001 --tsv");
  ASSERT_EQ(t.code, 0);
  EXPECT_EQ(count_lines(t.out), 1);
  EXPECT_EQ(run_cli("nist non-overlapping-template -i " + e_file() + " --template 0101").code, 2);
}

TEST(NistCli, BenchRuns) {
  const CliRun r = run_cli("bench nist --sequences 2 --bits 65536 --json");
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("\"LinearComplexity\""), std::string::npos);
  // The shipped wisdom is for 2^20 bits: any other length is planned by FFTW_ESTIMATE.
  EXPECT_NE(r.out.find("\"fft_plan\": \"FFTW_ESTIMATE\""), std::string::npos);
}

// --fft-wisdom plans the transform afresh and prints FFTW's wisdom for it instead of the benchmark.
TEST(NistCli, BenchPrintsFftWisdom) {
  const CliRun r = run_cli("bench nist --bits 4096 --fft-wisdom");
  ASSERT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("(fftw-3", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("fftw_wisdom"), std::string::npos);
  EXPECT_EQ(r.out.find("LinearComplexity"), std::string::npos);
}

}  // namespace

}  // namespace dpdrng_test::stats_nist_test_nist_cli
