// Hostile but realistic input, second pass: each test is one class of docs/bad-input.md, its examples run through
// the built binary. Every case failed before the class was fixed at its root (named in each test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sys/wait.h>
#include <string>
#include <vector>

#include "run_cli.hpp"

namespace dpdrng_test::cli_test_hardening {

using namespace dpdrng::cli_test;
namespace fs = std::filesystem;

namespace {

std::string file_with(const std::string& suffix, const std::string& bytes) {
  const std::string p = scratch(suffix);
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

// A small study: 4 cells (MT19937 and tea32(1), 2 replicas), a fraction of a second.
std::string tiny_study(const std::string& dt = "[0.04]", const std::string& sweep_extra = "") {
  return "[study]\nname = \"tiny\"\nreplicas = 2\nseed = 7\n[sweep]\ndistributions = [\"gauss\"]\n" + sweep_extra +
         "[[sweep.generator]]\nname = \"tea32\"\nrounds = [1]\n[scene]\nparticles = 64\nsteps = 60\n"
         "equilibrate = 10\ndt = " +
         dt + "\n[tests]\nchi2_steps = 20\nttest_pairs = 20\nnist_generators = []\n";
}

}  // namespace

// SP800-22 rev1a states where each reference distribution holds; outside it the tool answered p = 1 for every
// input (overlapping, m = 2), p = 0 for /dev/urandom (overlapping M = 20, a periodic non-overlapping template,
// approximate entropy m = 16 on 1.3 Mbit). Root: only where the formulas stay finite was checked.
TEST(BadInput, NistParametersOutsideTheSpecsRanges) {
  const std::string bits = scratch(".bits");
  // 20 313 words: 1.3 Mbit of tea32(8).
  const Result gen = run("gen -g tea32 -r 8 --count 20313 --format raw");
  ASSERT_EQ(gen.code, 0) << gen.err;
  std::ofstream(bits, std::ios::binary) << gen.out;
  expect_bad("nist overlapping-template --format raw -i " + bits + " --template-length 2", "2.8.7");
  expect_bad("nist overlapping-template --format raw -i " + bits + " --block-length 20", "2.8.7");
  expect_bad("nist non-overlapping-template --format raw -i " + bits + " --template 111111111", "periodic");
  expect_bad("nist block-frequency --format raw -i " + bits + " --block-length 10", "2.2.7");
  expect_bad("nist linear-complexity --format raw -i " + bits + " --block-length 100", "2.10.7");
  expect_bad("nist --format raw -i " + bits + " --overlapping-m 2", "--overlapping-m 2");
  // Length rules depend on n: not applicable, with the rule, never a P-value.
  const Result ap = run("nist approximate-entropy --format raw -i " + bits + " --template-length 16 --json");
  ASSERT_EQ(ap.code, 0) << ap.err;
  const auto j = nlohmann::json::parse(ap.out);
  const std::string text = j.dump();
  EXPECT_NE(text.find("2.12.7"), std::string::npos) << text;
  EXPECT_EQ(text.find("\"p\":0.0"), std::string::npos) << text;
  const Result se = run("nist serial --format raw -i " + bits + " --template-length 19");
  EXPECT_EQ(se.code, 0) << se.err;
  EXPECT_NE(se.out.find("not applicable: m = 19 needs m < floor(log2 n) - 2 = 18 (SP800-22 rev1a 2.11.7)"),
            std::string::npos)
      << se.out;
  // Inside the ranges the same data give P-values (m = 15 < 20 - 5).
  const Result ok = run("nist approximate-entropy --format raw -i " + bits + " --template-length 14");
  EXPECT_EQ(ok.code, 0);
  EXPECT_EQ(ok.out.find("not applicable"), std::string::npos) << ok.out;
  fs::remove(bits);
}

// "Cannot be computed" is "not applicable: reason" (null in JSON), never 0, ± 0 or a made-up p.
TEST(BadInput, QuantitiesThatCannotBeComputedAreNotApplicable) {
  // Too few MSD frames: was "diffusion coefficient 0 ± 0".
  const Result d = run("simulate -n 64 --steps 50 --equilibrate 0 -q");
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_NE(d.out.find("diffusion coefficient  not applicable: fewer than 8 MSD frames"), std::string::npos) << d.out;
  const Result dj = run("simulate -n 64 --steps 50 --equilibrate 0 -q --json");
  ASSERT_EQ(dj.code, 0) << dj.err;
  const auto jd = nlohmann::json::parse(dj.out);
  EXPECT_TRUE(jd["diffusion_coefficient"].is_null()) << jd["diffusion_coefficient"];
  EXPECT_TRUE(jd["diffusion_coefficient_sem"].is_null());
  // One production step: was "temperature … ± 0".
  const Result one = run("simulate -n 64 --steps 1 --equilibrate 0 -q");
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(one.out.find("± 0 "), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("error not applicable: 1 sample"), std::string::npos) << one.out;
  const auto j1 = nlohmann::json::parse(run("simulate -n 64 --steps 1 --equilibrate 0 -q --json").out);
  EXPECT_TRUE(j1["temperature_sem"].is_null()) << j1["temperature_sem"];
  // No randomness test asked for: was pass fractions 0.0 and min p 1.0.
  const Result dc = run("decompose -n 64 --steps 40 --equilibrate 10 --chi2-every 0 --ttest-pairs 0 -q --json");
  ASSERT_EQ(dc.code, 0) << dc.err;
  const auto jr = nlohmann::json::parse(dc.out)["randomness"];
  for (const char* k : {"chi2_pass_fraction", "chi2_min_p", "lag1_pass_fraction", "lag1_max_abs_r"})
    EXPECT_TRUE(jr[k].is_null()) << k << " = " << jr[k];
  const Result dt = run("decompose -n 64 --steps 40 --equilibrate 10 --chi2-every 0 --ttest-pairs 0 -q");
  EXPECT_NE(dt.out.find("chi2 (one step, all pairs) not applicable"), std::string::npos) << dt.out;
  // r_c below the closeness guard: no pair is seen, so none is "closer than 1e-05" (was: r = r_c printed).
  const Result rc = run("simulate -n 64 --steps 20 --equilibrate 10 -q --rc 5e-6 --json");
  ASSERT_EQ(rc.code, 0) << rc.err;
  EXPECT_EQ(nlohmann::json::parse(rc.out)["status"], "ok") << rc.out;
}

// Output paths are checked before the first step: a directory named series.csv was found after the whole run.
TEST(BadInput, SeriesFileThatIsADirectory) {
  const std::string dir = scratch(".series");
  fs::create_directories(dir + "/series.csv");
  expect_bad("simulate --steps 1000000000 -q --series " + dir, "series.csv exists and is not a regular file");
  fs::create_directories(dir + "/b/order.csv");
  expect_bad("simulate --scene bilayer --steps 1000000000 -q --series " + dir + "/b", "order.csv");
  fs::remove_all(dir);
}

// moments on a Gaussian sample scaled by 1e-200 and 1e200 (was: a zero-width CI and -nan skewness; CI [-inf, inf]
// and <x^2> null beside p = 0): the scale-free figures are those of the unscaled sample, the others scale.
TEST(BadInput, MomentsOfTinyAndHugeValues) {
  std::mt19937_64 g(5);
  std::normal_distribution<double> n01;
  std::vector<double> x(2000);
  for (auto& v : x) v = n01(g);
  auto moments = [&](double scale) {
    std::vector<double> y = x;
    for (auto& v : y) v *= scale;
    const std::string f = file_with(".f64", std::string(reinterpret_cast<const char*>(y.data()), y.size() * 8));
    const Result r = run("moments -f f64 --json -i " + f);
    fs::remove(f);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto base = moments(1.0);
  for (const double scale : {1e-200, 1e200}) {
    const auto m = moments(scale);
    EXPECT_NEAR(m["skewness"].get<double>(), base["skewness"].get<double>(), 1e-12) << scale;
    EXPECT_NEAR(m["kurtosis"].get<double>(), base["kurtosis"].get<double>(), 1e-12) << scale;
    for (int k : {0, 1})
      EXPECT_NEAR(m["mean_ci"][k].get<double>() / scale, base["mean_ci"][k].get<double>(), 1e-12) << scale;
    EXPECT_LT(m["mean_ci"][0].get<double>(), m["mean_ci"][1].get<double>());
    // <x^2> of 1e200-sized values is 1e400: not a double. Null with the reason, and the test of <x^2> = 1
    // (computed on scaled values) rejects it, as it rejects 1e-400.
    EXPECT_TRUE(m["second_moment"].is_null()) << m;
    EXPECT_TRUE(m["out_of_range"].is_string()) << m;
    EXPECT_EQ(m["verdict"], "fail");
  }
  // A scale at which every figure is a double: the variance scales by its square.
  const auto m = moments(1e-100);
  EXPECT_NEAR(m["variance"].get<double>() / 1e-200, base["variance"].get<double>(), 1e-12);
  EXPECT_FALSE(m.contains("out_of_range"));
}

// An option that changes nothing for the chosen combination is refused with the reason, and every list refuses
// a value given twice, naming it.
TEST(BadInput, OptionsThatDoNothingAndRepeatedValues) {
  expect_bad("simulate -g splitmix64 --key 1,2,3,4 --steps 2", "--key: splitmix64 takes no key");
  expect_bad("simulate --integrator shardlow --lambda 0.6 --steps 2", "--lambda");
  expect_bad("simulate -g mt19937 --seeding pair-step --steps 2", "--seeding: mt19937");
  expect_bad("gen --start 18446744073709551615 --count 2", "wrap");
  EXPECT_EQ(run("gen --start 18446744073709551615 --count 1").code, 0);
  expect_bad("nist --tests runs,runs -i /dev/null", "twice");
  expect_bad("decompose --domains 64,64,64 -q", "domains: 64 domains along x");
  const std::string cfg = file_with(".toml", tiny_study());
  expect_bad("study calibrate " + cfg + " --variance 0.01,0.01 --out " + scratch(".cal"), "--variance: lists 0.01 twice");
  expect_bad("study calibrate " + cfg + " --variance -1 --out " + scratch(".cal"), "--variance");
  EXPECT_FALSE(fs::exists(scratch(".cal")));
  const std::string dts = file_with(".dt.toml", tiny_study("[0.04, 0.04]"));
  expect_bad("study cells " + dts, "scene.dt: lists 0.04 twice");
  const std::string integ =
      file_with(".integ.toml", tiny_study("[0.04]", "integrators = [\"mvv:0.5\", \"mvv:0.50\"]\n"));
  expect_bad("study cells " + integ, "name the same integrator");
  for (const auto& f : {cfg, dts, integ}) fs::remove(f);
}

// Messages print numbers as %g and escape what they echo.
TEST(BadInput, MessagesPrintNumbersAndEchoesReadably) {
  const Result tiny = run("simulate --kT -1e-300 --steps 2");
  EXPECT_EQ(tiny.code, 2);
  EXPECT_NE(tiny.err.find("-1e-300"), std::string::npos) << tiny.err;
  EXPECT_EQ(tiny.err.find("0.000000"), std::string::npos) << tiny.err;
  const Result huge = run("simulate --lambda 1e308 --steps 2");
  EXPECT_EQ(huge.code, 2);
  EXPECT_NE(huge.err.find("1e+308"), std::string::npos) << huge.err;
  EXPECT_LT(huge.err.size(), 200u) << huge.err;
  // Binary garbage and a doubled quote.
  const Result junk = run("nist --tests \"$(printf 'ru\\001\\377\\376ns')\" -i /dev/null");
  EXPECT_EQ(junk.code, 2);
  EXPECT_NE(junk.err.find("'ru\\x01\\xff\\xfens'"), std::string::npos) << junk.err;
  EXPECT_EQ(junk.err.find('\x01'), std::string::npos);
  const Result defect = run("simulate -g defect: --steps 2");
  EXPECT_EQ(defect.code, 2);
  EXPECT_EQ(defect.err.find("''"), std::string::npos) << defect.err;
  // The hidden cap of --bins, stated.
  expect_bad("chi2 --bins 99999999999 -f u64 -i /dev/null", "2^31 - 1");
  // A directory without a study, given as a study config.
  const std::string dir = scratch(".nostudy");
  fs::create_directories(dir);
  expect_bad("study cells " + dir, "is a directory, not a study config");
  fs::remove_all(dir);
}

// Cell ids carry the exact Δt: two Δt that agree to 6 digits were one id ("8 computed", study.h5 "holds 4 of 8").
TEST(BadInput, CellIdsAreExact) {
  const std::string cfg = file_with(".toml", tiny_study("[0.04, 0.0400000001]"));
  const Result cells = run("study cells " + cfg);
  ASSERT_EQ(cells.code, 0) << cells.err;
  EXPECT_NE(cells.out.find("mt19937-gauss-dt0.04-rep00\n"), std::string::npos) << cells.out;  // names kept
  EXPECT_NE(cells.out.find("mt19937-gauss-dt0.0400000001-rep00\n"), std::string::npos) << cells.out;
  const std::string out = scratch(".store");
  const Result r = run("study run " + cfg + " --out " + out + " -t 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("holds 8 of 8 cells"), std::string::npos) << r.err;
  fs::remove_all(out);
  fs::remove(cfg);
}

// A cell file copied under another cell's name was merged into study.h5 under the wrong key; it must be refused
// (left out of study.h5, recomputed by study run).
TEST(BadInput, CellFileUnderAnotherNameIsRefused) {
  const std::string cfg = file_with(".toml", tiny_study());
  const std::string out = scratch(".store");
  ASSERT_EQ(run("study run " + cfg + " --out " + out + " -t 1").code, 0);
  const std::string a = out + "/cells/mt19937-gauss-dt0.04-rep00.h5", b = out + "/cells/mt19937-gauss-dt0.04-rep01.h5";
  fs::copy_file(a, b, fs::copy_options::overwrite_existing);
  const Result rep = run("study report " + out + " --no-charts");
  EXPECT_EQ(rep.code, 0) << rep.err;
  EXPECT_NE(rep.err.find("holds cell mt19937-gauss-dt0.04-rep00"), std::string::npos) << rep.err;
  const Result ls = run("study merge " + out);
  EXPECT_NE(ls.err.find("holds 3 of 4 cells"), std::string::npos) << ls.err;
  // Merged into another store: not copied, named.
  const std::string merged = scratch(".merged");
  const Result m = run("study merge " + out + " --out " + merged);
  EXPECT_EQ(m.code, 0) << m.err;
  EXPECT_NE(m.err.find("rep01.h5 is unreadable (holds cell mt19937-gauss-dt0.04-rep00): not merged"),
            std::string::npos)
      << m.err;
  EXPECT_FALSE(fs::exists(merged + "/cells/mt19937-gauss-dt0.04-rep01.h5"));
  fs::remove_all(merged);
  const Result again = run("study run " + cfg + " --out " + out + " -t 1");
  EXPECT_EQ(again.code, 0);
  EXPECT_NE(again.err.find("1 computed, 3 resumed"), std::string::npos) << again.err;
  EXPECT_NE(slurp(a), slurp(b));
  fs::remove_all(out);
  fs::remove(cfg);
}

// Writes that fail part-way, without privileges: a file-size limit (RLIMIT_FSIZE, SIGXFSZ ignored) makes every
// write past 12 KiB fail with EFBIG, so a store's config files are written and its cells are not. Was: "write
// error" and then SIGSEGV in HDF5's shutdown, or in H5Ocopy under `study report`, with study.h5.tmp* left behind.
// The ENOSPC/EIO matrix over study run, report, merge, simulate --series and nist is tests/fault/run.sh (ctest
// write_faults).
TEST(BadInput, WritesThatFailPartWay) {
  const std::string cfg = file_with(".toml", tiny_study());
  const std::string out = scratch(".store"), log = scratch(".log");
  auto limited = [&](const std::string& args) {
    const std::string cmd = "ulimit -f 24; trap '' XFSZ; \"" DPDRNG_CLI_PATH "\" " + args + " >/dev/null 2>" + log;
    const int status = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = slurp(log);
    return r;
  };
  auto temporaries = [&] {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(out))
      if (e.path().filename().string().find(".tmp") != std::string::npos) found.push_back(e.path().string());
    return found;
  };
  const Result run1 = limited("study run " + cfg + " --out " + out + " -t 1");
  EXPECT_EQ(run1.code, 1) << run1.err;  // not a signal (-1)
  EXPECT_NE(run1.err.find("write error"), std::string::npos) << run1.err;
  EXPECT_EQ(temporaries(), std::vector<std::string>{});
  const Result whole = run("study run " + cfg + " --out " + out + " -t 1");
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_NE(whole.err.find("holds 4 of 4 cells"), std::string::npos) << whole.err;
  // study.h5 (over 12 KiB) cannot be replaced: the old one and every cell stay as they were.
  const std::string before = slurp(out + "/study.h5");
  const std::vector<std::string> writers = {"study report " + out + " --no-charts", "study merge " + out};
  for (const std::string& args : writers) {
    const Result r = limited(args);
    EXPECT_EQ(r.code, 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("write error"), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(temporaries(), std::vector<std::string>{}) << args;
    EXPECT_EQ(slurp(out + "/study.h5"), before) << args;
  }
  fs::remove_all(out);
  fs::remove(cfg);
  fs::remove(log);
}

}  // namespace dpdrng_test::cli_test_hardening
