#pragma once
// Runs the built `dpdrng` binary (DPDRNG_CLI_PATH) through the shell for the CLI contract tests.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace dpdrng::cli_test {

struct Result {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A scratch path unique to the running test and process: suites of several checkouts may run at once.
inline std::string scratch(const std::string& suffix) {
  const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "dpdrng_" + t->test_suite_name() + "_" + t->name() + "_" +
         std::to_string(getpid()) + suffix;
}

// Runs `<shell_prefix>dpdrng <args>` (the prefix may set a directory or environment), stdout and stderr to
// files; code -1 if it did not exit normally (a crash).
inline Result run_after(const std::string& shell_prefix, const std::string& args) {
  const std::string out = scratch(".out"), err = scratch(".err");
  const std::string cmd =
      shell_prefix + "\"" DPDRNG_CLI_PATH "\" " + args + " > \"" + out + "\" 2> \"" + err + "\"";
  const int status = std::system(cmd.c_str());
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::remove(out.c_str());
  std::remove(err.c_str());
  return r;
}

// Runs `dpdrng <args>`, stdout and stderr to files; code -1 if it did not exit normally (a crash).
inline Result run(const std::string& args) { return run_after("", args); }

// Exit 2, nothing on standard output, one line on standard error that mentions `names`.
inline void expect_bad(const std::string& args, const std::string& names) {
  const Result r = run(args);
  EXPECT_EQ(r.code, 2) << args << ": " << r.err;
  EXPECT_TRUE(r.out.empty()) << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << args << ": " << r.err;
}

}  // namespace dpdrng::cli_test
