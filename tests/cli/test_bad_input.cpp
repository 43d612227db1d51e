// Hostile input, as a new user would type it: every case exits 2 with one line naming the flag or key (or is
// computed right), nothing is lost and nothing half-written. docs/bad-input.md lists each class with the test
// here that keeps it true (BadInputDoc checks that the two agree).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "run_cli.hpp"

namespace dpdrng_test::cli_test_bad_input {

using namespace dpdrng::cli_test;
namespace fs = std::filesystem;

namespace {

// Each {arguments, what the message names} after `prefix`.
void expect_all_bad(const std::string& prefix, const std::vector<std::pair<std::string, std::string>>& cases) {
  for (const auto& [args, names] : cases) expect_bad(prefix + args, names);
}

// A file under the test's scratch name, holding `bytes`.
std::string file_with(const std::string& suffix, const std::string& bytes) {
  const std::string p = scratch(suffix);
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

std::string random_bytes(std::size_t n, unsigned seed) {
  std::mt19937 g(seed);
  std::string s(n, '\0');
  for (auto& c : s) c = static_cast<char>(g() & 0xff);
  return s;
}

std::string doubles(const std::vector<double>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

}  // namespace

TEST(BadInput, NistUniversalNegativeInitBlocks) {
  const std::string f = file_with(".raw", random_bytes(20000, 1));
  expect_bad("nist universal -i " + f + " --format raw --block-length 5 --init-blocks -1", "--init-blocks -1");
  expect_bad("nist universal -i " + f + " --format raw --block-length 5 --init-blocks -2147483648", "--init-blocks");
}

TEST(BadInput, NistUniversalBlockLengthOne) {
  const std::string f = file_with(".raw", random_bytes(20000, 2));
  expect_bad("nist universal -i " + f + " --format raw --block-length 1", "--block-length 1");
  expect_bad("nist -i " + f + " --format raw --universal-L 1", "--universal-L 1");
  // L = 2, the smallest allowed, gives a P-value in [0, 1].
  const Result r = run("nist universal -i " + f + " --format raw --block-length 2 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const double p = nlohmann::json::parse(r.out)["results"][0][0]["values"][0]["p"];
  EXPECT_GE(p, 0.0);
  EXPECT_LE(p, 1.0);
}

TEST(BadInput, NistLinearComplexityShortBlocks) {
  const std::string f = file_with(".raw", random_bytes(20000, 3));
  expect_bad("nist linear-complexity -i " + f + " --format raw --block-length 1", "--block-length 1");
  expect_bad("nist linear-complexity -i " + f + " --format raw --block-length 11", "at least 12");
  // From 12 on the mathematics holds, but SP800-22 rev1a 2.10.7 recommends 500 <= M <= 5000.
  expect_bad("nist linear-complexity -i " + f + " --format raw --block-length 12", "2.10.7");
  EXPECT_EQ(run("nist linear-complexity -i " + f + " --format raw --block-length 500").code, 0);
}

TEST(BadInput, NistTestParametersBeforeAnyWork) {
  // Refused before the input is even opened: the file does not exist, yet the parameter is what is named.
  expect_all_bad("nist -i " + scratch(".missing") + " ",
                 {{"block-frequency --block-length -5", "--block-length -5"},
                  {"non-overlapping-template --template-length 40", "--template-length 40"},
                  {"non-overlapping-template --blocks 0", "--blocks 0"},
                  {"overlapping-template --K 0", "--K 0"},
                  {"overlapping-template --template-length 9 --block-length 8", "--block-length 8"},
                  {"serial --template-length 1", "--template-length 1"},
                  {"approximate-entropy --template-length 30", "--template-length 30"},
                  {"--serial-m 99", "--serial-m 99"},
                  {"--tests Runs --universal-L 1 --streams 2", "--stream-bits"}});
  // A battery parameter is not checked for tests that are not run.
  const std::string f = file_with(".raw", random_bytes(2000, 4));
  EXPECT_EQ(run("nist -i " + f + " --format raw --tests runs --serial-m 99").code, 0);
}

TEST(BadInput, NistPerTestOptionsInheritFromTheParent) {
  const std::string f = file_with(".raw", random_bytes(4000, 5));
  const Result before = run("nist --format raw runs -i " + f + " --json");
  const Result after = run("nist runs --format raw -i " + f + " --json");
  ASSERT_EQ(before.code, 0) << before.err;
  EXPECT_EQ(before.out, after.out);
  EXPECT_EQ(nlohmann::json::parse(before.out)["format"], "raw");
  EXPECT_EQ(run("nist -i " + f + " --format raw --streams 2 --stream-bits 16000 runs --tsv").out,
            run("nist runs -i " + f + " --format raw --streams 2 --stream-bits 16000 --tsv").out);
  expect_bad("nist --format raw runs --format ascii -i " + f, "--format is given both before and after 'runs'");
  expect_bad("nist --serial-m 5 runs --format raw -i " + f, "--serial-m is an option of the whole battery");
}

TEST(BadInput, NistAsciiRefusesAnythingButBits) {
  const std::string f = file_with(".raw", random_bytes(4000, 6));
  expect_bad("nist -i " + f, "--format raw");
  expect_bad("nist runs -i " + f, "input is not an ASCII bit string");
  // Hex digits, a comment, a stray letter: refused at their offset, where the reference would skip them and test
  // the stray '0' and '1' characters.
  expect_bad("nist frequency -i " + file_with(".txt", "0110 1001\r\n1111 0000 x\n"),
             "input is not an ASCII bit string: byte 'x' at offset 21; for binary words (gen --format raw) use "
             "--format raw");
  expect_bad("nist -i " + file_with(".hash", "# bits\n0110\n"), "byte '#' at offset 0");
  // gen's default output (hex lines) into nist's default format (ascii), through a pipe.
  const std::string cli = "\"" DPDRNG_CLI_PATH "\"";
  const std::string err = scratch(".err");
  const std::string pipe = "bash -c 'set -o pipefail; " + cli + " gen -g tea32 -r 1 --count 2000 | " + cli +
                           " nist --input - 2> \"" + err + "\"'";
  const int status = std::system(pipe.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
  EXPECT_NE(slurp(err).find("input is not an ASCII bit string: byte "), std::string::npos) << slurp(err);
  std::remove(err.c_str());
  // Bits with white space of every kind are read as they are.
  const std::string t = file_with(".bits", "0110 1001\r\n1111\t0000\v\f\n");
  const Result r = run("nist frequency -i " + t + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["stream_bits"], 16);
}

// Text where raw words belong: gen's hex lines given to a reader of u64 or f64 (which would take 17-byte lines as
// 8-byte words whenever the line count is a multiple of 8).
TEST(BadInput, TextGivenAsRawWordsIsRefused) {
  const Result hex = run("gen -g tea32 -r 1 --count 32640");
  ASSERT_EQ(hex.code, 0);
  ASSERT_EQ(hex.out.size() % 8, 0u);
  const std::string f = file_with(".hex", hex.out);
  for (const std::string cmd : {"chi2 --format u64", "ttest --format u64", "moments --format f64",
                                "gof --format f64 --target gauss", "chi2d --format u64"})
    expect_bad(cmd + " --input " + f, "the input is text (hex lines of gen without --format raw?)");
  std::string column;
  for (int k = 1; k < 32; ++k) column += std::to_string(k / 32.0) + "\n";
  const std::string numbers = file_with(".txt", column);
  expect_bad("chi2 --format u64 --input " + numbers, "--format text");
  EXPECT_EQ(run("chi2 --format text --input " + numbers).code, 0);
}

TEST(BadInput, NistStreamOptions) {
  expect_all_bad("nist --format raw -i " + file_with(".raw", random_bytes(4000, 7)) + " ",
                 {{"--streams 3 --stream-bits 0", "--stream-bits: '0' is out of range"},
                  {"--streams 3", "--streams needs --stream-bits"},
                  {"--stream-bits 64", "--stream-bits needs --streams"},
                  {"--streams -3 --stream-bits 10", "'-3'"},
                  {"--streams 99999 --stream-bits 99999", "fewer than"},
                  {"--streams 4294967296 --stream-bits 4294967296", "more bits than"}});
}

TEST(BadInput, TtestOfHugeValues) {
  // Period-3 pattern -a, +a, +a: lag-1 autocorrelation exactly -1/2 as n grows, whatever a.
  std::vector<double> x(3000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (i % 3 ? 1e300 : -1e300) * (1 + 1e-3 * double(i % 7));
  std::vector<double> unit(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) unit[i] = x[i] * 1e-300;
  const Result big = run("ttest -f f64 --json -i " + file_with(".f64", doubles(x)));
  const Result small = run("ttest -f f64 --json -i " + file_with(".unit.f64", doubles(unit)));
  ASSERT_EQ(big.code, 0) << big.err;
  const auto jb = nlohmann::json::parse(big.out), js = nlohmann::json::parse(small.out);
  ASSERT_TRUE(jb["r"].is_number()) << big.out;
  EXPECT_NEAR(jb["r"].get<double>(), js["r"].get<double>(), 1e-12);
  EXPECT_NEAR(jb["r"].get<double>(), -0.5, 0.01);
  EXPECT_TRUE(jb["p"].is_number());
}

TEST(BadInput, CorrOfAlternatingHugeValues) {
  for (const double a : {1.0, 1e200}) {
    std::vector<double> x(1000);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = i % 2 ? a : -a;
    const Result r = run("corr -f f64 --json -i " + file_with(".f64", doubles(x)));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["checks"][0]["r"], -1.0) << a;
  }
}

TEST(BadInput, GenCountOverflow) {
  expect_bad("gen --count 99999999999999999999999", "--count: '99999999999999999999999' is out of range");
  // tea64 writes two words a call: 2^63 calls are 2^64 words.
  expect_bad("gen -g tea64 --count 9223372036854775808", "more than 2^64 - 1 words");
}

TEST(BadInput, NumbersAreDecimal) {
  EXPECT_EQ(run("gen --count 3 --start 010").out, run("gen --count 3 --start 10").out);
  expect_bad("gen --count 3 --start 0x10", "not a decimal integer");
  expect_bad("gen --count 3e2", "not a decimal integer");
  expect_bad("chi2 -i - -f u64 --alpha 0x1p-7", "--alpha");
}

TEST(BadInput, ValuesAbove2To64Refused) {
  const std::string beyond = "18446744073709551616";
  expect_bad("gen --count 1 --start " + beyond, "--start");
  expect_bad("simulate -n 64 --steps 20 --equilibrate 10 -q --seed " + beyond, "--seed");
  expect_bad("simulate -n 64 --steps 20 --equilibrate 10 -q --init-seed " + beyond, "--init-seed");
  expect_bad("chi2 -i - -f u64 --per " + beyond, "--per");
  expect_bad("gen --count 1 --key 1,2,3,4294967296", "--key");
  const Result r = run("gen --count 1 --start 18446744073709551615");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.size(), 17u);
}

TEST(BadInput, RangesStatedInWords) {
  const Result alpha = run("chi2 -i - -f u64 --alpha -1");
  EXPECT_EQ(alpha.code, 2);
  EXPECT_NE(alpha.err.find("expected a number within (0, 1)"), std::string::npos) << alpha.err;
  const Result per = run("chi2 -i - -f u64 --per 0");
  EXPECT_NE(per.err.find("expected an integer from 1 to 2^64 - 1"), std::string::npos) << per.err;
  for (const Result& r : {alpha, per}) EXPECT_LT(r.err.size(), 160u) << r.err;
  expect_bad("simulate --threads 5000", "from 0 to 1024");
}

TEST(BadInput, NegativeCountsNotEchoedAsHuge) {
  for (const std::string args : {"gen --count -1", "nist -i x --streams -3 --stream-bits 8", "chi2 -i x -f u64 --per -2",
                                 "corr -i x -f u64 --pairs -1"}) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err.find("1844674407370955"), std::string::npos) << args << ": " << r.err;
    EXPECT_NE(r.err.find("out of range"), std::string::npos) << args << ": " << r.err;
  }
}

TEST(BadInput, UnknownSubcommandIsNamed) {
  expect_bad("foo", "unknown command 'foo' for dpdrng (known: list,");
  expect_bad("study frobnicate", "unknown command 'frobnicate' for dpdrng study (known: run, merge, report, calibrate, cells)");
  expect_bad("bench", "dpdrng bench needs a command");
}

TEST(BadInput, StudyCalibrateAndDefectGenerator) {
  const std::string cfg = std::string(DPDRNG_SOURCE_DIR) + "/study/ci.toml";
  const std::string out = scratch(".calib");
  expect_bad("study calibrate " + cfg + " --out " + out + " --variance 0.01,nan", "--variance");
  expect_bad("study calibrate " + cfg + " --out " + out + " --variance -1", "variance");
  expect_bad("study calibrate " + cfg + " --out " + out + " --lag1 0.6", "lag1");
  expect_bad("study calibrate " + cfg + " --out " + out + " --replicas 1", "--replicas");
  expect_bad("study calibrate " + cfg + " --out " + out + " --null-studies 0", "--null-studies");
  expect_bad("study calibrate " + cfg, "--out is required");
  EXPECT_FALSE(fs::exists(out));
  expect_bad("gen -g defect:lag1=2 --count 4", "lag1");
  expect_bad("gen -g defect:varience=0.1 --count 4", "unknown key 'varience'");
  expect_bad("gen -g defect:variance=0.1,base=tea32 --count 4", "base 'tea32'");
  expect_bad("simulate -g defect:lag1=0.2 --steps 2 --equilibrate 0 --particles 64", "pair-step");
  EXPECT_EQ(run("gen -g defect:variance=0.5 --count 4").out, run("gen -g philox4x32 -r 10 --count 4").out);
}

TEST(BadInput, StudyRunThreadsAndOut) {
  const std::string cfg = std::string(DPDRNG_SOURCE_DIR) + "/study/ci.toml";
  const std::string out = scratch(".out");
  expect_bad("study run " + cfg + " --out " + out + " --threads -1", "--threads: '-1' is out of range");
  expect_bad("study run " + cfg + " --out ''", "--out: an empty path");
  const std::string file = file_with(".file", "a file, not a directory");
  expect_bad("study run " + cfg + " --out " + file, "--out " + file + ": exists and is not a directory");
  expect_bad("study run " + cfg + " --out " + file + "/sub", "cannot create it");
  EXPECT_FALSE(fs::exists(out));
  expect_bad("study merge " + out + " --out ''", "--out: an empty path");
  expect_bad("decompose --study ''", "--study: an empty path");
  expect_bad("study run " + cfg + " --out " + out + " --shard 99999999999/3", "--shard: k");
  expect_bad("study cells " + cfg + " --shard 1/0", "--shard: N");
  expect_bad("study cells " + cfg + " --shard 2", "not k/N");
  EXPECT_FALSE(fs::exists(out));
  // A report directory that cannot be made is refused before anything is read or written.
  const std::string dir = scratch(".study");
  fs::create_directories(dir);
  std::ofstream(dir + "/study.toml") << std::ifstream(cfg).rdbuf();
  std::ofstream(dir + "/report") << "a file where the report directory goes";
  expect_bad("study report " + dir, "report directory " + dir + "/report: exists and is not a directory");
  EXPECT_FALSE(fs::exists(dir + "/study.h5"));
  // A folder of results without its cells, as committed results are kept: the report it has stays as it is.
  fs::remove(dir + "/report");
  fs::create_directories(dir + "/report");
  std::ofstream(dir + "/report/report.md") << "the committed report";
  expect_bad("study report " + dir, "no cells to report");
  std::ifstream md(dir + "/report/report.md");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(md), {}), "the committed report");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/report"), fs::directory_iterator{}), 1);
  fs::remove_all(dir);
}

TEST(BadInput, SimulateTinyStepAndDensity) {
  expect_bad("simulate --dt 1e-300", "invalid dt: 1e-300: a bead at the thermal speed would move");
  expect_bad("simulate --density 1e-300", "invalid density");
  expect_bad("simulate --density 1e-4 --pairs cells", "more than 64 a bead");
  expect_bad("simulate-bilayer --dt-warmup 1e-300", "invalid dt_warmup");
  // The same rule in a study config, named with the dt as written.
  std::ifstream ci(std::string(DPDRNG_SOURCE_DIR) + "/study/ci.toml");
  std::string cfg((std::istreambuf_iterator<char>(ci)), {});
  cfg.replace(cfg.find("[scene]"), 7, "[scene]\ndt = 1e-300");
  expect_bad("study run " + file_with(".toml", cfg) + " --out " + scratch(".out"), "scene (dt = 1e-300): invalid dt");
  EXPECT_FALSE(fs::exists(scratch(".out")));
  // The smallest step the rule allows for the default box still runs.
  EXPECT_EQ(run("simulate -n 64 --steps 20 --equilibrate 10 -q --dt 1e-8").code, 0);
}

TEST(BadInput, SimulateSeriesDirCheckedFirst) {
  const std::string file = file_with(".file", "x");
  // 10^9 steps would run for days: the directory must be refused before the first one.
  expect_bad("simulate --steps 1000000000 -q --series " + file + "/series", "--series " + file + "/series");
  expect_bad("simulate --steps 1000000000 -q --series " + file, "exists and is not a directory");
  expect_bad("simulate --steps 1000000000 -q --series ''", "--series: an empty path");
  expect_bad("simulate --scene bilayer --steps 1000000000 -q --series " + file, "exists and is not a directory");
  const std::string dir = scratch(".series") + "/a/b";
  ASSERT_EQ(run("simulate -n 64 --steps 20 --equilibrate 10 -q --series " + dir).code, 0);
  EXPECT_TRUE(fs::is_regular_file(dir + "/series.csv"));
  fs::remove_all(scratch(".series"));
}

TEST(BadInput, SimulateTapOptions) {
  const std::string f = scratch(".tap");
  const std::string tiny = "simulate -n 64 --steps 20 --equilibrate 10 -q ";
  expect_all_bad(tiny, {{"--tap-steps 11:20", "--tap-steps: needs --tap-words or --tap-zeta"},
                        {"--tap-zeta " + f + " --tap-steps 15", "--tap-steps: '15' is not A:B"},
                        {"--tap-zeta " + f + " --tap-steps 15:12", "--tap-steps '15:12'"},
                        {"--tap-zeta " + f + " --tap-steps 10:20", "outside the production steps 11:20"},
                        {"--tap-zeta " + f + " --tap-steps 11:21", "outside the production steps 11:20"},
                        {"--tap-zeta " + f + " --tap-steps -1:5", "--tap-steps"},
                        {"--tap-zeta ''", "--tap-zeta: an empty path"},
                        {"--tap-words " + f + " --tap-zeta " + f, "' is also --tap-words"},
                        {"--tap-words " + f + ".json --tap-zeta " + f, "is also --tap-words"},
                        {"--integrator shardlow --tap-zeta " + f, "--tap-zeta: --integrator shardlow"},
                        {"--integrator pnhln --tap-words " + f, "--tap-words: --integrator pnhln"},
                        {"--scene bilayer --tap-words " + f, "--tap-words: the water scene only"}});
  // 10^9 steps would run for days: the paths must be refused before the first one.
  const std::string dir = scratch(".tapdir");
  fs::create_directories(dir);
  expect_bad("simulate --steps 1000000000 -q --tap-zeta " + dir, "': is a directory");
  expect_bad("simulate --steps 1000000000 -q --tap-words " + dir + "/no/w", "': no directory");
  fs::create_directories(dir + "/w.json");
  expect_bad("simulate --steps 1000000000 -q --tap-words " + dir + "/w", "--tap-words's sidecar");
  EXPECT_FALSE(fs::exists(f));
  EXPECT_FALSE(fs::exists(f + ".json"));
  fs::remove_all(dir);
}

TEST(BadInput, UnstableSimulateHasNoObservables) {
  const Result j = run("simulate -n 64 --steps 20 --equilibrate 10 -q --dt 5 --json");
  ASSERT_EQ(j.code, 0) << j.err;
  const auto r = nlohmann::json::parse(j.out);
  ASSERT_EQ(r["status"].get<std::string>().rfind("unstable", 0), 0u);
  for (const char* k : {"temperature", "temperature_mean", "pressure_mean", "diffusion_coefficient",
                        "velocity_pdf_error_rate", "pressure_diag"})
    EXPECT_TRUE(r[k].is_null()) << k << " = " << r[k];
  EXPECT_TRUE(r["timings"].is_object());
  const Result t = run("simulate -n 64 --steps 20 --equilibrate 10 -q --dt 5");
  for (const char* row : {"temperature k_BT       n/a", "pressure               n/a", "diffusion coefficient  n/a"})
    EXPECT_NE(t.out.find(row), std::string::npos) << row << "\n" << t.out;
  const Result b = run("simulate --scene bilayer --steps 20 --equilibrate 10 -q --dt 5 --json");
  ASSERT_EQ(b.code, 0) << b.err;
  const auto rb = nlohmann::json::parse(b.out);
  EXPECT_TRUE(rb["membrane_tension"].is_null());
  EXPECT_TRUE(rb["temperature_mean"].is_null());
  EXPECT_EQ(rb["scene"], "bilayer");
}

TEST(BadInput, WriteErrorsExitOne) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const std::string f = file_with(".raw", random_bytes(8000, 8));
  const std::string cfg = std::string(DPDRNG_SOURCE_DIR) + "/study/ci.toml";
  const std::vector<std::string> commands = {"list",
                                             "gen --count 1000",
                                             "gen --count 1000 --format raw",
                                             "chi2 -f u64 -i " + f,
                                             "ttest -f u64 -i " + f,
                                             "corr -f u64 -i " + f,
                                             "nist -i " + f + " --format raw --tsv --tests runs",
                                             "nist runs -i " + f + " --format raw",
                                             "study cells " + cfg,
                                             "--help",
                                             "simulate -n 64 --steps 20 --equilibrate 10 -q --json"};
  for (const std::string& args : commands) {
    const std::string cmd = "\"" DPDRNG_CLI_PATH "\" " + args + " > /dev/full 2> " + scratch(".err");
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1) << args;
    EXPECT_NE(slurp(scratch(".err")).find("dpdrng: write error: standard output"), std::string::npos) << args;
  }
  // A closed pipe is the reader's choice, not a lost result.
  EXPECT_EQ(std::system("\"" DPDRNG_CLI_PATH "\" gen --count 100000000 | head -c 10 > /dev/null"), 0);
}

TEST(BadInput, ConfigOfTheOtherKind) {
  const std::string decomp = std::string(DPDRNG_SOURCE_DIR) + "/study/decomposition.toml";
  const std::string study = std::string(DPDRNG_SOURCE_DIR) + "/study/ci.toml";
  expect_bad("study run " + decomp + " --out " + scratch(".out"), "dpdrng decompose --study");
  expect_bad("study cells " + decomp, "this is a decomposition sweep");
  expect_bad("decompose --study " + study + " --out " + scratch(".out"), "dpdrng study run");
  EXPECT_FALSE(fs::exists(scratch(".out")));
}

TEST(BadInput, DecomposeTestsKeysNamed) {
  std::ifstream in(std::string(DPDRNG_SOURCE_DIR) + "/study/decomposition.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  int edits = 0;
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = text;
    const std::size_t at = s.find(from);
    if (at == std::string::npos) ADD_FAILURE() << "the shipped config lacks " << from;
    else s.replace(at, from.size(), to);
    std::string suffix = ".edit";
    suffix += std::to_string(++edits);
    suffix += ".toml";
    return file_with(suffix, s);
  };
  const std::string out = " --out " + scratch(".out");
  expect_bad("decompose --study " + with("alpha = 0.01", "alpha = 2") + out, "tests.alpha: must be within (0, 1)");
  expect_bad("decompose --study " + with("ttest_pairs = 32", "ttest_pairs = 100000") + out, "tests.ttest_pairs");
  expect_bad("decompose --study " + with("[scene]\nparticles = 256", "[scene]\nparticles = 16") + out,
             "tests.ttest_pairs");
  expect_bad("decompose --study " + with("[scene]\n", "[notscene]\n") + out, "notscene: unknown key");
  expect_bad("decompose --study " + file_with(".table.toml", "scene = 5\n[[generators]]\nname = \"tea32\"\n") + out,
             "scene: must be a table");
  EXPECT_FALSE(fs::exists(scratch(".out")));
}

// libstdc++ compiles a regular expression recursively: a pattern this long would overflow its stack (SIGSEGV). A
// refused pattern is quoted shortened, not echoed whole.
TEST(BadInput, BenchRngFilterTooLongOrInvalid) {
  expect_bad("bench rng --filter " + std::string(100000, 'a'), "at most 256");
  const Result r = run("bench rng --filter '" + std::string(200, '(') + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("not a valid regular expression: '((((("), std::string::npos) << r.err;
  EXPECT_LT(r.err.size(), 200u) << r.err;
}

TEST(BadInput, DirectoryGivenAsInput) {
  const std::string dir = ::testing::TempDir();
  expect_bad("nist -i " + dir, "is a directory, not an input file");
  expect_bad("chi2 -f u64 -i " + dir, "is a directory, not an input file");
  expect_bad("nist -i " + scratch(".none"), "cannot open");
  const std::string empty = file_with(".empty", "");
  expect_bad("nist -i " + empty, "no bits in the input");
}

TEST(BadInput, MomentsGofChi2dRefuseBadInput) {
  const std::string text = file_with(".txt", "0.1\n0.2\n0.3\n0.4\n0.5\n0.6\n");
  const std::string outside = file_with(".big", "0.1\n1.5\n");
  const std::string truncated = file_with(".raw", std::string(12, '\x01'));
  const std::string nan = file_with(".f64", doubles({0.1, std::nan(""), 0.3}));
  expect_all_bad("moments -f text -i " + text,
                 {{" --confidence 1", "--confidence"}, {" --second-moment nan", "--second-moment"}});
  expect_bad("moments -f f64 -i " + nan, "not a finite number");
  expect_bad("moments -f u64 -i " + truncated, "not a whole number of 8-byte words");
  expect_bad("gof -f text -i " + text + " --target cauchy", "--target");
  expect_bad("gof -f f64 -i " + nan, "not a finite number");
  expect_all_bad("chi2d -f text -i " + text, {{" --bins 1", "--bins"}, {" --pairs halves", "--pairs halves"},
                                              {" --pairs thirds", "--pairs"}});
  expect_bad("chi2d -f text -i " + outside, "outside [0,1)");
  expect_bad("chi2d -f u64 -i " + truncated, "not a whole number of 8-byte words");
  expect_bad("chi2d -f u64 -i " + scratch(".none"), "cannot open");
}

}  // namespace dpdrng_test::cli_test_bad_input
