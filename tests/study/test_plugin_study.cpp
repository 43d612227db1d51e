// A study of a plug-in generator (`ext:PATH` in [[sweep.generator]]): it loads native code only when the config
// pins the library's SHA-256 or the command line allows the path, it stores the digest in each cell, and it
// refuses to resume under a changed library.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <variant>

#include "../temp_dir.hpp"
#include "config_text.hpp"
#include "dpdrng/common/sha256.hpp"
#include "dpdrng/study/h5.hpp"
#include "dpdrng/study/store.hpp"

namespace dpdrng_test::study_test_plugin_study {

using namespace dpdrng::study;
namespace fs = std::filesystem;

namespace {

const fs::path kPlugins = DPDRNG_PLUGIN_DIR;

// A two-cell study: the plug-in's one variant and the MT19937 reference, one replica of 100 steps.
std::string config(const std::string& extra = "") {
  return config_text::StudyText{.name = "plug",
                                .replicas = 1,
                                .generators = {{"ext:./libmine.so", "", extra}},
                                .scene = "particles = 32\nsteps = 100\nequilibrate = 10\n",
                                .tests = "ttest_pairs = 4\nchi2_steps = 4\nnist_generators = []\n"}
      .text();
}

int run_in(const fs::path& dir, const std::string& args, std::string* err = nullptr) {
  const std::string cmd = "cd '" + dir.string() + "' && '" DPDRNG_CLI_PATH "' " + args + " >/dev/null 2>err.txt";
  const int rc = std::system(cmd.c_str());
  if (err) {
    std::ifstream in(dir / "err.txt");
    *err = std::string(std::istreambuf_iterator<char>(in), {});
  }
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string cell_digest(const fs::path& file) {
  auto f = h5::open_file(file.string());
  auto g = h5::open_group(f.id(), "cell");
  const auto attrs = h5::read_attributes(g.id());
  const auto it = attrs.find("cell.generator_sha256");
  return it == attrs.end() ? "" : std::get<std::string>(it->second);
}

}  // namespace

TEST(PluginStudy, RunsOnlyWithConsentStoresTheDigestAndRefusesAChangedLibrary) {
  TempDir tmp;
  fs::copy_file(kPlugins / "libtea32_4.so", tmp.path / "libmine.so");
  const std::string digest = dpdrng::sha256_file((tmp.path / "libmine.so").string());
  std::ofstream(tmp.path / "s.toml") << config();
  std::string err;

  // Neither pinned nor allowed: nothing loads, nothing is written, and the message gives the pin to add.
  EXPECT_EQ(run_in(tmp.path, "study run s.toml --out out", &err), 2);
  EXPECT_NE(err.find("sha256 = \"" + digest + "\""), std::string::npos) << err;
  EXPECT_NE(err.find("--allow-plugin"), std::string::npos) << err;
  EXPECT_EQ(err.find("loaded plug-in"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(tmp.path / "out"));

  // Allowed on the command line: two cells, the plug-in's with its library's digest.
  ASSERT_EQ(run_in(tmp.path, "study run s.toml --out out --allow-plugin ./libmine.so", &err), 0) << err;
  EXPECT_NE(err.find("loaded plug-in 'tea32c(4)'"), std::string::npos) << err;
  const auto cells = Store(tmp.path / "out").load_all();
  ASSERT_EQ(cells.size(), 2u);
  const fs::path mine = tmp.path / "out" / "cells" / "ext-libmine-r01-gauss-distance-dt0.04-rep00.h5";
  ASSERT_TRUE(fs::exists(mine));
  EXPECT_EQ(cell_digest(mine), digest);
  EXPECT_EQ(cell_digest(tmp.path / "out" / "cells" / "mt19937-gauss-dt0.04-rep00.h5"), "");

  // Another library under the same path: the config's hash changes, so the directory refuses to resume.
  fs::copy_file(kPlugins / "libtea32_1.so", tmp.path / "libmine.so", fs::copy_options::overwrite_existing);
  EXPECT_EQ(run_in(tmp.path, "study run s.toml --out out --allow-plugin ./libmine.so", &err), 2);
  EXPECT_NE(err.find("different config"), std::string::npos) << err;

  // A pin is checked before anything loads; the right pin needs no --allow-plugin.
  std::ofstream(tmp.path / "s.toml") << config("sha256 = \"" + digest + "\"\n");
  EXPECT_EQ(run_in(tmp.path, "study run s.toml --out pinned", &err), 2);
  EXPECT_NE(err.find("refusing to load a library other than the one the config names"), std::string::npos) << err;
  EXPECT_EQ(err.find("loaded plug-in"), std::string::npos) << err;
  fs::copy_file(kPlugins / "libtea32_4.so", tmp.path / "libmine.so", fs::copy_options::overwrite_existing);
  EXPECT_EQ(run_in(tmp.path, "study run s.toml --out pinned", &err), 0) << err;
}

TEST(PluginStudy, ConfigRefusesAPinOnABuiltinAndTwoLibrariesWithOneCellTag) {
  EXPECT_NE(config_text::error_of(config_text::StudyText{.generators = {{"tea32", "[1]", "sha256 = \"00\"\n"}}}.text())
                .find("built-in"),
            std::string::npos);
  TempDir tmp;
  fs::create_directories(tmp.path / "a");
  fs::create_directories(tmp.path / "b");
  fs::copy_file(kPlugins / "libtea32_1.so", tmp.path / "a" / "libmine.so");
  fs::copy_file(kPlugins / "libtea32_4.so", tmp.path / "b" / "libmine.so");
  allow_plugin((tmp.path / "a" / "libmine.so").string());
  allow_plugin((tmp.path / "b" / "libmine.so").string());
  const std::string text = config_text::StudyText{
      .generators = {{"ext:" + (tmp.path / "a" / "libmine.so").string(), "", ""},
                     {"ext:" + (tmp.path / "b" / "libmine.so").string(), "", ""}}}
                               .text();
  EXPECT_NE(config_text::error_of(text).find("would share the cell ids"), std::string::npos) << config_text::error_of(text);
}

}  // namespace dpdrng_test::study_test_plugin_study
