// dpdrng --validate-only: each subcommand checks its arguments as for a real run and stops before reading an
// input, writing a file or computing: exit 0 when valid, 2 with the usual one-line message when not.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../temp_dir.hpp"
#include "run_cli.hpp"

namespace dpdrng_test::cli_test_validate_only {

using namespace dpdrng::cli_test;
namespace fs = std::filesystem;

namespace {

const std::string kSource = DPDRNG_SOURCE_DIR;

// Exit 0 and nothing printed: no result, no progress, no output file in `dir`.
void expect_valid(const std::string& args, const fs::path& dir) {
  const Result r = run("--validate-only " + args);
  EXPECT_EQ(r.code, 0) << args << ": " << r.err;
  EXPECT_TRUE(r.out.empty()) << args << ": " << r.out;
  EXPECT_TRUE(r.err.empty()) << args << ": " << r.err;
  EXPECT_TRUE(fs::is_empty(dir)) << args << " created " << fs::directory_iterator(dir)->path();
}

}  // namespace

TEST(ValidateOnly, ValidArgumentsExitZeroWithoutWorkOrFiles) {
  TempDir t;
  const std::string d = t.path.string();
  const std::vector<std::string> valid = {
      "gen -g tea32 -r 1 --count 1000000000000 --format raw",
      "gen -g tea32 -r 1 --count inf --format raw",
      "simulate --steps 100000000 --tap-zeta " + d + "/z.f64 --tap-words " + d + "/w.u64 --tap-steps 600:700",
      "chi2 -i " + d + "/missing.u64 -f u64 --per 1000",
      "corr -i " + d + "/missing.f64 -f f64 --pairs 8 --offsets 1,2",
      "nist runs -i " + d + "/missing.bits --format raw",
      "simulate -g tea32 -r 1 --steps 100000000 --series " + d + "/series --compare mt19937",
      "simulate-bilayer --steps 100000000 --series " + d + "/bilayer",
      "decompose --study " + kSource + "/study/decomposition.toml --out " + d + "/decomp",
      "study run " + kSource + "/study/ci.toml --out " + d + "/study --shard 2/3",
      "study calibrate " + kSource + "/study/ci.toml --out " + d + "/calibration --null-studies 2",
      "study report " + d + "/no-such-study",
      "bench dpd --paper --generators tea32 --rounds 1,8",
  };
  for (const auto& args : valid) expect_valid(args, t.path);
}

TEST(ValidateOnly, InvalidArgumentsExitTwoWithoutFiles) {
  TempDir t;
  const std::string d = t.path.string();
  expect_bad("--validate-only gen --count -1", "--count");
  expect_bad("--validate-only corr -i " + d + "/missing -f f64 --offsets 1", "--offsets needs --pairs");
  expect_bad("--validate-only chi2d -i " + d + "/missing -f text --pairs halves", "--pairs halves");
  expect_bad("--validate-only simulate --dt nan --series " + d + "/series", "--dt");
  expect_bad("--validate-only simulate --tap-zeta " + d + "/z --tap-steps 1:2", "--tap-steps");
  expect_bad("--validate-only study run " + kSource + "/study/ci.toml --shard 0/1 --out " + d + "/study", "--shard");
  expect_bad("--validate-only study run " + d + "/missing.toml", "missing.toml");
  expect_bad("--validate-only bench dpd --scaling-only --no-scaling", "--scaling-only");
  EXPECT_TRUE(fs::is_empty(t.path));
}

// Whatever a message echoes stays one line of text: control bytes are shown as \xNN.
TEST(ValidateOnly, EchoedControlBytesArePrintable) {
  const Result r = run("--validate-only gen --count 1 --format \"$(printf 'a\\033[31mb\\nc')\"");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("a\\x1b[31mb\\x0ac"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\033'), std::string::npos) << r.err;
}

}  // namespace dpdrng_test::cli_test_validate_only
