// `dpdrng study` as a user meets it: bad configs change nothing on disk, and a run killed at a random moment
// resumes to the same store as an uninterrupted run, without recomputing the cells it had finished.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "config_text.hpp"
#include "dpdrng/study/store.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::study_test_cli_study {

using namespace dpdrng::study;
namespace fs = std::filesystem;

namespace {

// A real (engine-backed) study small enough for a unit test.
const std::string kTiny = config_text::StudyText{.name = "tiny",
                                                 .replicas = 3,
                                                 .scene = "particles = 32\nsteps = 240\nequilibrate = 40\n",
                                                 .tests = "chi2_steps = 4\nttest_pairs = 4\nnist_sequences = 2\n"
                                                          "nist_bits = 65536\nnist_generators = [\"tea32\"]\n"}
                              .text();

int run_cli(const std::string& args, std::string* err = nullptr, const fs::path& err_file = {}) {
  const fs::path e = err_file.empty() ? fs::temp_directory_path() / ("dpdrng-cli-err-" + std::to_string(getpid())) : err_file;
  const std::string cmd = std::string(DPDRNG_CLI_PATH) + " " + args + " >/dev/null 2>'" + e.string() + "'";
  const int rc = std::system(cmd.c_str());
  if (err) {
    std::ifstream in(e);
    *err = std::string(std::istreambuf_iterator<char>(in), {});
  }
  fs::remove(e);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// A cell's physics and test results; timings differ from run to run and are left out.
std::string fingerprint(const CellResult& r) {
  std::string s = r.cell.id() + "|" + std::string(to_string(r.status));
  for (const auto& [k, v] : r.scalars)
    if (k.rfind("cost.", 0) != 0) s += "|" + k + "=" + std::to_string(v);
  for (const auto& [k, v] : r.series) {
    s += "|" + k + ":";
    for (double x : v) s += std::to_string(x) + ",";
  }
  return s;
}

std::map<std::string, std::string> fingerprints(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& c : Store(dir).load_all()) out[c.cell.id()] = fingerprint(c);
  return out;
}

std::vector<fs::path> cell_files(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::exists(dir / "cells")) return out;
  for (const auto& e : fs::directory_iterator(dir / "cells"))
    if (e.path().extension() == ".h5" && e.path().filename().string()[0] != '.') out.push_back(e.path());
  return out;
}

}  // namespace

TEST(StudyCli, BadConfigExitsTwoAndWritesNothing) {
  TempDir tmp;
  std::string bad = kTiny;
  bad.replace(bad.find("particles = 32"), 14, "particles = 32\ngama = 4.5");
  write(tmp.path / "bad.toml", bad);
  std::string err;
  EXPECT_EQ(run_cli("study run '" + (tmp.path / "bad.toml").string() + "' --out '" + (tmp.path / "out").string() + "'",
                    &err),
            2);
  EXPECT_NE(err.find("scene.gama: unknown key"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(tmp.path / "out"));

  write(tmp.path / "nan.toml", [] {
    std::string s = kTiny;
    return s.replace(s.find("particles = 32"), 14, "particles = 32\ndt = nan");
  }());
  EXPECT_EQ(run_cli("study run '" + (tmp.path / "nan.toml").string() + "' --out '" + (tmp.path / "out").string() + "'",
                    &err),
            2);
  EXPECT_NE(err.find("scene.dt"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(tmp.path / "out"));
  EXPECT_EQ(run_cli("study run '" + (tmp.path / "missing.toml").string() + "'", &err), 2);
  // Valid TOML, but a box the engine refuses (L = 2 r_c): caught before the run, not as failed cells.
  write(tmp.path / "small.toml", [] {
    std::string s = kTiny;
    return s.replace(s.find("particles = 32"), 14, "particles = 24");
  }());
  EXPECT_EQ(run_cli("study run '" + (tmp.path / "small.toml").string() + "' --out '" + (tmp.path / "out").string() + "'",
                    &err),
            2);
  EXPECT_NE(err.find("scene"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(tmp.path / "out"));
  EXPECT_EQ(run_cli("study run '" + (tmp.path / "bad.toml").string() + "' --shard 3/2", &err), 2);
}

TEST(StudyCli, KilledRunResumesToTheUninterruptedResult) {
  TempDir tmp;
  write(tmp.path / "tiny.toml", kTiny);
  const std::string cfg = "'" + (tmp.path / "tiny.toml").string() + "'";
  const fs::path whole = tmp.path / "whole", killed = tmp.path / "killed";
  ASSERT_EQ(run_cli("study run " + cfg + " --threads 2 --out '" + whole.string() + "'"), 0);
  const auto expected = fingerprints(whole);
  ASSERT_EQ(expected.size(), 9u);  // 3 replicas × (mt19937, tea32(1), tea32(8))
  for (const auto& c : Store(whole).load_all()) ASSERT_EQ(c.status, CellStatus::ok) << c.cell.id() << ": " << c.reason;

  // Start the run and kill it (SIGKILL: no chance to clean up) once it has finished some cells.
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl(DPDRNG_CLI_PATH, DPDRNG_CLI_PATH, "study", "run", (tmp.path / "tiny.toml").c_str(), "--threads", "1",
          "--out", killed.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto t0 = std::chrono::steady_clock::now();
  while (cell_files(killed).size() < 3 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  auto finished = cell_files(killed);
  ASSERT_GE(finished.size(), 3u);
  // If the run won the race and finished, take cells away as an interruption would have left them.
  while (finished.size() > 5) {
    fs::remove(finished.back());
    finished.pop_back();
  }
  std::map<fs::path, std::pair<ino_t, long>> before;
  for (const auto& f : finished) {
    struct stat st {};
    ASSERT_EQ(stat(f.c_str(), &st), 0);
    before[f] = {st.st_ino, st.st_mtim.tv_nsec + 1'000'000'000L * (st.st_mtim.tv_sec % 1000)};
  }

  std::string err;
  ASSERT_EQ(run_cli("study run " + cfg + " --threads 2 --out '" + killed.string() + "'", &err), 0) << err;
  EXPECT_NE(err.find("already stored: resuming"), std::string::npos) << err;
  for (const auto& [f, id] : before) {
    struct stat st {};
    ASSERT_EQ(stat(f.c_str(), &st), 0) << f;
    EXPECT_EQ(st.st_ino, id.first) << f << " was recomputed";
    EXPECT_EQ(st.st_mtim.tv_nsec + 1'000'000'000L * (st.st_mtim.tv_sec % 1000), id.second) << f << " was rewritten";
  }
  EXPECT_EQ(fingerprints(killed), expected);
  EXPECT_TRUE(fs::exists(killed / "study.h5"));

  // The report of the resumed store is complete.
  ASSERT_EQ(run_cli("study report --no-charts '" + killed.string() + "'", &err), 0) << err;
  std::ifstream md(killed / "report" / "report.md");
  const std::string text(std::istreambuf_iterator<char>(md), {});
  EXPECT_NE(text.find("cells stored: **9 of 9**"), std::string::npos);
}

TEST(StudyCli, ShardsRunApartMergeIntoOneStore) {
  TempDir tmp;
  write(tmp.path / "tiny.toml", kTiny);
  const std::string cfg = "'" + (tmp.path / "tiny.toml").string() + "'";
  const fs::path a = tmp.path / "a", b = tmp.path / "b", whole = tmp.path / "whole";
  ASSERT_EQ(run_cli("study run " + cfg + " --shard 1/2 --out '" + a.string() + "'"), 0);
  ASSERT_EQ(run_cli("study run " + cfg + " --shard 2/2 --out '" + b.string() + "'"), 0);
  EXPECT_LT(cell_files(a).size(), 9u);
  std::string err;
  ASSERT_EQ(run_cli("study merge '" + a.string() + "' '" + b.string() + "'", &err), 0) << err;
  ASSERT_EQ(run_cli("study run " + cfg + " --out '" + whole.string() + "'"), 0);
  EXPECT_EQ(fingerprints(a), fingerprints(whole));
}

TEST(StudyCli, ABlownUpRunIsRecordedAsUnstableAndTheSweepGoesOn) {
  TempDir tmp;
  std::string s = kTiny;
  s.replace(s.find("particles = 32"), 14, "particles = 32\ndt = 0.5");  // far beyond DPD's stable Δt
  write(tmp.path / "hot.toml", s);
  std::string err;
  ASSERT_EQ(run_cli("study run '" + (tmp.path / "hot.toml").string() + "' --out '" + (tmp.path / "o").string() + "'",
                    &err),
            0)
      << err;
  const auto cells = Store(tmp.path / "o").load_all();
  ASSERT_EQ(cells.size(), 9u);
  for (const auto& c : cells) {
    EXPECT_EQ(c.status, CellStatus::unstable) << c.cell.id();
    EXPECT_GT(c.unstable_step, 0) << c.cell.id();
    EXPECT_NE(c.reason.find("unstable at step"), std::string::npos) << c.reason;
  }
  ASSERT_EQ(run_cli("study report --no-charts '" + (tmp.path / "o").string() + "'", &err), 0) << err;
  std::ifstream md(tmp.path / "o" / "report" / "report.md");
  const std::string text(std::istreambuf_iterator<char>(md), {});
  EXPECT_NE(text.find("unstable: 9"), std::string::npos);
}

// A cell file cut short or overwritten is named in a warning: `study run` computes it again, `study report`
// lists it as unreadable (in the report too) instead of silently counting it as missing.
TEST(StudyCli, UnreadableCellsAreNamedRecomputedAndReported) {
  TempDir tmp;
  // Two cells: tea32(1) and its reference, no NIST.
  using config_text::with;
  write(tmp.path / "two.toml",
        with(with(with(kTiny, "replicas = 3", "replicas = 1"), "rounds = [1, 8]", "rounds = [1]"),
             "nist_generators = [\"tea32\"]", "nist_generators = []"));
  const std::string out = (tmp.path / "out").string();
  const std::string run = "study run '" + (tmp.path / "two.toml").string() + "' --out '" + out + "'";
  std::string err;
  ASSERT_EQ(run_cli(run, &err), 0) << err;
  auto files = cell_files(out);
  ASSERT_EQ(files.size(), 2u);
  std::sort(files.begin(), files.end());
  fs::resize_file(files[0], fs::file_size(files[0]) / 2);
  ASSERT_EQ(run_cli(run, &err), 0) << err;
  EXPECT_NE(err.find("warning: " + files[0].string() + " is unreadable"), std::string::npos) << err;
  EXPECT_NE(err.find("1 computed, 1 resumed"), std::string::npos) << err;
  EXPECT_EQ(Store(out).load_all().size(), 2u);

  std::ofstream(files[1], std::ios::trunc) << "garbage";
  ASSERT_EQ(run_cli("study report --no-charts '" + out + "'", &err), 0) << err;
  EXPECT_NE(err.find(files[1].string() + " is unreadable"), std::string::npos) << err;
  std::ifstream md(fs::path(out) / "report" / "report.md");
  const std::string report((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(report.find("Unreadable cell files"), std::string::npos);
  EXPECT_NE(report.find(files[1].filename().string()), std::string::npos);
}

}  // namespace dpdrng_test::study_test_cli_study
