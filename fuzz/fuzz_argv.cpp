// The command line, validate-only: the input is an argument vector (arguments separated by NUL bytes, which no
// real argument holds). A first argument that names a subcommand path ("study run") selects it; any other
// non-empty first argument selects a path by its hash, so that every subcommand is reached; an empty one leaves
// the rest at the top level. run_cli must then exit 0 (valid, nothing printed on standard error) or 2 (one
// printable line on standard error), never crash, and create nothing: it runs with a scratch directory
// ($DPDRNG_FUZZ_TMP/argv-PID, with a study and a decomposition config to name) as its working directory, which
// must stay as it was.
// Standard input is /dev/null, standard output goes to /dev/null.
#include <fcntl.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "argv_tree.hpp"
#include "dpdrng/cli/run.hpp"
#include "dpdrng/common/error.hpp"
#include "fuzz_check.hpp"

namespace fs = std::filesystem;
using namespace dpdrng;
using fuzz::require;

namespace {

std::vector<std::string> paths;
fs::path scratch;
std::size_t scratch_entries = 0;

std::size_t entries_in(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

// The working directory of each run, with configs the commands can name by a short path. libFuzzer itself keeps
// the original one (its corpus and artifact paths are relative to it).
void make_scratch() {
  const char* tmp = std::getenv("DPDRNG_FUZZ_TMP");
  const fs::path dir = fs::path(tmp ? tmp : fs::temp_directory_path().string()) / ("argv-" + std::to_string(getpid()));
  fs::create_directories(dir);
  fs::copy_file(DPDRNG_SOURCE_DIR "/study/ci.toml", dir / "study.toml", fs::copy_options::overwrite_existing);
  fs::copy_file(DPDRNG_SOURCE_DIR "/study/decomposition.toml", dir / "decomp.toml",
                fs::copy_options::overwrite_existing);
  scratch = dir;
  scratch_entries = entries_in(dir);
}

void quiet_standard_streams() {
  const int null = open("/dev/null", O_RDWR);
  require(null >= 0 && dup2(null, STDIN_FILENO) >= 0 && dup2(null, STDOUT_FILENO) >= 0, "cannot open /dev/null");
  close(null);
}

std::vector<std::string> split_arguments(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> out(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0)
      out.emplace_back();
    else
      out.back() += static_cast<char>(data[i]);
  }
  return out;
}

// "dpdrng", the selected subcommand's words, then the remaining arguments.
std::vector<std::string> argument_vector(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"dpdrng"};
  if (!args.front().empty()) {
    std::string path = paths[std::hash<std::string>{}(args.front()) % paths.size()];
    for (const std::string& p : paths)
      if (p == args.front()) path = p;
    std::istringstream words(path);
    for (std::string w; words >> w;) argv.push_back(w);
  }
  argv.insert(argv.end(), args.begin() + 1, args.end());
  return argv;
}

void check_message(int code, const std::string& err, const std::string& args) {
  require(code == kExitOk || code == kExitBadInput, "exit code " + std::to_string(code) + " for " + args + ": " + err);
  if (code == kExitOk) {
    require(err.empty(), "a valid command line with a message on standard error: " + err);
    return;
  }
  require(err.rfind("dpdrng: ", 0) == 0 && err.find('\n') == err.size() - 1, "not one 'dpdrng: ' line: " + err);
  for (const char c : err.substr(0, err.size() - 1)) {
    const auto b = static_cast<unsigned char>(c);
    require(b >= 0x20 && b != 0x7f, "a control byte echoed in: " + err);
  }
}

}  // namespace

// Building the app allocates thousands of small strings and functions a run; with ASan's default 30-frame stack
// recorded at each allocation, that unwinding took a quarter of the time. Eight frames still place a finding.
extern "C" const char* __asan_default_options() { return "malloc_context_size=8"; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (paths.empty()) {
    quiet_standard_streams();
    make_scratch();
    fuzz::subcommand_paths(*cli::make_app(), "", paths);
  }
  const std::vector<std::string> args = argument_vector(split_arguments(data, size));
  std::vector<char*> argv;
  std::string shown;
  for (const std::string& a : args) {
    argv.push_back(const_cast<char*>(a.c_str()));
    shown += (shown.empty() ? "" : " ") + a;
  }
  argv.push_back(nullptr);
  const fs::path home = fs::current_path();
  fs::current_path(scratch);
  std::ostringstream err;
  std::streambuf* const saved = std::cerr.rdbuf(err.rdbuf());
  const int code = cli::run_cli(static_cast<int>(args.size()), argv.data(), cli::RunMode::validate_only);
  std::cerr.rdbuf(saved);
  fs::current_path(home);
  check_message(code, err.str(), shown);
  require(entries_in(scratch) == scratch_entries, "a file or directory created by: " + shown);
  return 0;
}
