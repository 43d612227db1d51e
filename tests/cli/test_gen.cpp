// The CLI contract of `dpdrng gen` (and the smaller `list` and `bench rng`), run as the built binary.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "dpdrng/rng/stream.hpp"
#include "dpdrng/rng/tea.hpp"
#include "run_cli.hpp"
#include "../rng/every_generator.hpp"

namespace dpdrng_test::cli_test_gen {

using namespace dpdrng::rng;
using namespace dpdrng::cli_test;

namespace {

GeneratorSpec spec(const char* name, int rounds) {
  GeneratorSpec s;
  s.name = name;
  s.rounds = rounds;
  return validated(s);
}

std::string hex_lines(const std::vector<std::uint64_t>& words) {
  std::string text;
  char line[24];
  for (auto w : words) {
    std::snprintf(line, sizeof line, "%016llx\n", static_cast<unsigned long long>(w));
    text += line;
  }
  return text;
}

// The stream contract for tea32, written out: call i hashes S+i, low word -> x0, output (x1'<<32)|x0'.
TEST(CliGen, HexTea32FollowsTheContract) {
  const Result r = run("gen --generator tea32 --rounds 8 --seeding counter --start 5 --count 40");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::uint64_t> want;
  for (std::uint64_t i = 0; i < 40; ++i) {
    std::uint32_t x0 = lo32(5 + i), x1 = hi32(5 + i);
    tea_encrypt<8>(x0, x1, kPaperTeaKey);
    want.push_back(join32(x1, x0));
  }
  EXPECT_EQ(r.out, hex_lines(want));
}

// Every generator's hex output equals the library stream (tea64 and the 2x generators: two lines a call).
TEST(CliGen, HexEqualsLibraryStreamForEveryGenerator) {
  for (const GeneratorSpec& s : dpdrng_test::every_generator(false, true)) {
    const std::string name = s.name;
    const Result r = run(std::string("gen -g ") + name + " -r " + std::to_string(s.rounds) +
                         " --start 1234567 --count 37 --format hex");
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    std::vector<std::uint64_t> want(37 * words_per_call(s));
    fill_stream(s, 1234567, 0, want);
    EXPECT_EQ(r.out, hex_lines(want)) << name;
  }
}

TEST(CliGen, KeyOptionReachesTheHash) {
  // The key 0x01234567, 0x12345678, 0x23456789, 0x3456789A, in decimal (numbers on the command line are decimal).
  const Result r = run("gen -g tea32 -r 32 --key 19088743,305419896,591751049,878082202 --start 0 --count 1");
  ASSERT_EQ(r.code, 0) << r.err;
  // Bouncy Castle's TEA vector for this key and a zero block: 34e943b0 900f5dcb (x0', x1').
  EXPECT_EQ(r.out, "900f5dcb34e943b0\n");
}

// raw: little-endian 64-bit words, byte 8k+b is bits 8b..8b+7 of word k, as dieharder -g 200 reads them.
TEST(CliGen, RawIsLittleEndianWords) {
  const Result r = run("gen -g tea64 -r 4 --start 99 --count 10 --format raw");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::uint64_t> want(20);
  fill_stream(spec("tea64", 4), 99, 0, want);
  ASSERT_EQ(r.out.size(), 8 * want.size());
  for (std::size_t k = 0; k < want.size(); ++k)
    for (int b = 0; b < 8; ++b)
      ASSERT_EQ(static_cast<unsigned char>(r.out[8 * k + b]), (want[k] >> (8 * b)) & 0xff) << "word " << k;
}

TEST(CliGen, CountZeroWritesNothing) {
  const Result r = run("gen --count 0");
  EXPECT_EQ(r.code, 0);
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(r.err.empty());
}

// A reader that stops early (head) is a normal end: exit 0, at once. Ten billion calls would take minutes if
// gen did not notice the closed pipe; 60 s is far above the fraction of a second it takes, even on a busy host.
TEST(CliGen, ClosedPipeIsANormalEnd) {
  const std::string bytes = scratch(".bytes"), status = scratch(".status");
  const std::string cmd = "bash -c '\"" DPDRNG_CLI_PATH "\" gen --format raw --count 10000000000 | head -c 16 > \"" +
                          bytes + "\"; echo ${PIPESTATUS[0]} > \"" + status + "\"'";
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(slurp(status), "0\n");
  EXPECT_EQ(slurp(bytes).size(), 16u);
  EXPECT_LT(seconds, 60.0);
  std::remove(bytes.c_str());
  std::remove(status.c_str());
}

// --count inf writes the stream until the reader stops: `| head -c 1000000` gets the stream's first million bytes
// (the words of --count 125000) and gen exits 0, not by SIGPIPE; a full device ends it with exit 1; a count that
// is neither a number nor inf is refused.
TEST(CliGen, EndlessCountStreamsUntilThePipeCloses) {
  const std::string bytes = scratch(".bytes"), status = scratch(".status");
  for (const char* format : {"raw", "hex"}) {
    const std::string cmd = std::string("bash -c '\"" DPDRNG_CLI_PATH "\" gen -g tea32 -r 4 --count inf --format ") +
                            format + " | head -c 1000000 > \"" + bytes + "\"; echo ${PIPESTATUS[0]} > \"" + status +
                            "\"'";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(slurp(status), "0\n") << format << ": gen's exit status (141 = killed by SIGPIPE)";
    const Result finite = run(std::string("gen -g tea32 -r 4 --count 125000 --format ") + format);
    ASSERT_EQ(finite.code, 0);
    EXPECT_TRUE(slurp(bytes) == finite.out.substr(0, 1000000)) << format;
  }
  // Not through run(), whose own redirection would send the endless stream to a file; `timeout` bounds a hang.
  const std::string full_err = scratch(".full");
  const int full = std::system(("timeout 60 \"" DPDRNG_CLI_PATH "\" gen --count inf --format raw > /dev/full 2> \"" +
                                full_err + "\"").c_str());
  EXPECT_EQ(WIFEXITED(full) ? WEXITSTATUS(full) : -1, 1);
  EXPECT_NE(slurp(full_err).find("write error: standard output"), std::string::npos) << slurp(full_err);
  std::remove(full_err.c_str());
  expect_bad("gen --count infinity", "--count");
  expect_bad("gen --count -1", "or inf");
  std::remove(bytes.c_str());
  std::remove(status.c_str());
}

// raw to a terminal is refused; util-linux `script` gives the command a pseudo-terminal as stdout.
TEST(CliGen, RawToATerminalIsRefused) {
  if (std::system("command -v script > /dev/null 2>&1") != 0) GTEST_SKIP() << "util-linux script not installed";
  const std::string log = scratch(".log");
  const std::string cmd =
      "script -qec '\"" DPDRNG_CLI_PATH "\" gen --count 4 --format raw' /dev/null > \"" + log + "\" 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(slurp(log).find("terminal"), std::string::npos) << slurp(log);
  std::remove(log.c_str());
}

// Bad input: exit 2, one line on stderr naming the problem, nothing on stdout.
TEST(CliGen, BadArgumentsExitTwoWithOneLine) {
  const char* cases[] = {
      "gen -g nope --count 1",         "gen -g tea32 --rounds 0 --count 1", "gen -g tea32 --rounds 65 --count 1",
      "gen -g philox4x32 -r 17 --count 1", "gen --key 1,2,3 --count 1",     "gen --key 1,2,3,x --count 1",
      "gen --key 1,2,3,4294967296 --count 1", "gen --key=-1,2,3,4 --count 1", "gen --count 1 --format bin",
      "gen",                           "gen --count -1",                   "gen --count 1 --start -5",
      "gen --count 1 --seeding distance", "gen --count 1 --seeding nope",   "gen -g mt19937 --count 1 --rounds 2",
  };
  for (const char* args : cases) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    ASSERT_FALSE(r.err.empty()) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

TEST(CliList, NamesEveryGeneratorWithItsRounds) {
  const Result r = run("list --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), generator_table().size());
  for (std::size_t k = 0; k < j.size(); ++k) {
    EXPECT_EQ(j[k]["name"], generator_table()[k].name);
    EXPECT_EQ(j[k]["max_rounds"], generator_table()[k].max_rounds);
    EXPECT_FALSE(j[k]["safe_rounds"].get<std::string>().empty());
  }
  const Result text = run("generators");
  ASSERT_EQ(text.code, 0);
  EXPECT_NE(text.out.find("philox4x32"), std::string::npos);
}

// A tiny `bench rng` run: the JSON carries the run context, every repetition, and mt19937 as the ratio base.
TEST(CliBenchRng, JsonHasContextRowsAndRatios) {
  const Result r = run("bench rng --json --min-time 0.001 --repetitions 2 --filter 'tea32\\(8\\)/batch$'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"host", "compiler", "build_type", "dpdrng_version", "date"})
    EXPECT_TRUE(j["context"].contains(key)) << key;
  bool tea = false, mt = false;
  for (const auto& row : j["results"]) {
    EXPECT_EQ(row["repetitions_ns"].size(), 2u);
    EXPECT_GT(row["median_ns"].get<double>(), 0.0);
    if (row["label"] == "tea32(8)" && row["mode"] == "batch") tea = row["ratio_vs_mt19937"].get<double>() > 0;
    if (row["label"] == "mt19937" && row["mode"] == "batch") mt = row["ratio_vs_mt19937"].get<double>() == 1.0;
  }
  EXPECT_TRUE(tea);
  EXPECT_TRUE(mt);
  EXPECT_EQ(run("bench rng --min-time 0").code, 2);
}

}  // namespace

}  // namespace dpdrng_test::cli_test_gen
