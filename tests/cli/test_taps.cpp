// `dpdrng simulate --tap-words / --tap-zeta / --tap-steps`, run as the built binary: the ζ tapped are exactly
// the run's zeta block (dpdrng moments on them reproduces it), the words are those the ζ came from, the order
// is canonical and the files are the same bit for bit whatever the thread count or pair mode allows.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dpdrng/rng/distribution.hpp"
#include "run_cli.hpp"

namespace dpdrng_test::cli_test_taps {

using namespace dpdrng::cli_test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

template <class T>
std::vector<T> values_of(const std::string& path) {
  const std::string bytes = slurp(path);
  std::vector<T> v(bytes.size() / sizeof(T));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
  return v;
}

json json_file(const std::string& path) { return json::parse(slurp(path)); }

template <dpdrng::rng::Distribution D>
double zeta_from(const std::uint64_t* w, int words, dpdrng::rng::Feed f) {
  using dpdrng::rng::draw;
  if (f == dpdrng::rng::Feed::blocks)  // the block's words, then the second block's
    return words == 2 ? draw<D>(f, std::array{w[0]}, std::array{w[1]})
                      : draw<D>(f, std::array{w[0], w[1]}, std::array{w[2], w[3]});
  return words == 1 ? draw<D>(f, std::array{w[0]}, std::array{w[0]})
                    : draw<D>(f, std::array{w[0], w[1]}, std::array{w[0], w[1]});
}

// A scratch directory for the test's files, removed at its end.
struct Scratch {
  std::string dir = scratch(".taps");
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return dir + "/" + name; }
};

void expect_close(double got, double want, double rel, const std::string& what) {
  EXPECT_LE(std::abs(got - want), rel * std::abs(want)) << what << ": " << got << " vs " << want;
}

// The run's zeta block against dpdrng moments on the tapped ζ: the same n, the same moments.
void expect_moments_reproduce_zeta_block(const std::string& run_args) {
  Scratch s;
  const Result run = dpdrng::cli_test::run(run_args + " --json --tap-zeta " + (s / "z.f64"));
  ASSERT_EQ(run.code, 0) << run_args << ": " << run.err;
  const json zeta = json::parse(run.out)["zeta"];
  const Result m = dpdrng::cli_test::run("moments --input " + (s / "z.f64") + " --format f64 --json");
  ASSERT_EQ(m.code, 0) << m.err;
  const json mom = json::parse(m.out);
  ASSERT_GT(zeta["n"].get<std::uint64_t>(), 1000u) << run_args;
  EXPECT_EQ(mom["n"], zeta["n"]) << run_args;
  EXPECT_EQ(json_file(s / "z.f64.json")["count"], zeta["n"]) << run_args;
  // The engine sums powers in its own order, moments in another: they agree to rounding. The mean is near 0, so
  // its rounding is measured against the standard deviation; skewness and the excess kurtosis are standardised
  // already, and measured against 1.
  const double sd = std::sqrt(zeta["variance"].get<double>());
  EXPECT_LE(std::abs(mom["mean"].get<double>() - zeta["mean"].get<double>()), 1e-12 * sd) << run_args;
  for (const char* k : {"variance", "second_moment"})
    expect_close(mom[k].get<double>(), zeta[k].get<double>(), 1e-12, run_args + " " + k);
  for (int e = 0; e < 2; ++e) {
    expect_close(mom["variance_ci"][e].get<double>(), zeta["variance_ci"][e].get<double>(), 1e-12, "variance_ci");
    expect_close(mom["second_moment_ci"][e].get<double>(), zeta["second_moment_ci"][e].get<double>(), 1e-12,
                 "second_moment_ci");
  }
  EXPECT_LE(std::abs(mom["skewness"].get<double>() - zeta["skewness"].get<double>()), 1e-12) << run_args;
  EXPECT_LE(std::abs(mom["kurtosis"].get<double>() - zeta["excess_kurtosis"].get<double>()), 1e-12) << run_args;
}

}  // namespace

TEST(CliTaps, TappedZetaReproducesTheRunsZetaBlock) {
  const std::string base = "simulate -n 64 --steps 120 --equilibrate 20 -q";
  expect_moments_reproduce_zeta_block(base);
  expect_moments_reproduce_zeta_block(base + " --pairs cells --generator philox4x32 --seeding pair-step");
  expect_moments_reproduce_zeta_block(base + " --integrator scmvv:3 --generator mt19937");
  expect_moments_reproduce_zeta_block(base + " --generator tea64 --feed blocks --distribution gauss");
  expect_moments_reproduce_zeta_block(base + " --distribution uniform");
}

// The words are those each ζ came from: ζ made again from them by the library's distribution is the tapped ζ,
// bit for bit; the sidecars count what the files hold.
TEST(CliTaps, WordsAreThoseTheZetaCameFrom) {
  using dpdrng::rng::Distribution;
  using dpdrng::rng::Feed;
  struct Case {
    std::string args;
    int words;
    Feed feed;
    Distribution distribution;
  };
  const std::vector<Case> cases = {
      {"--generator tea32 --rounds 8", 1, Feed::halves, Distribution::gauss},
      {"--generator tea64 --feed blocks", 4, Feed::blocks, Distribution::gauss},
      {"--generator philox4x32 --pairs cells --feed inverse", 2, Feed::inverse, Distribution::gauss},
      {"--generator threefry2x64 --distribution uniform", 2, Feed::halves, Distribution::uniform},
      {"--generator mt19937 --feed blocks", 2, Feed::blocks, Distribution::gauss}};
  for (const Case& c : cases) {
    Scratch s;
    const Result r = run("simulate -n 64 --steps 30 --equilibrate 10 -q " + c.args + " --tap-words " + (s / "w") +
                         " --tap-zeta " + (s / "z") + " --tap-steps 15:24");
    ASSERT_EQ(r.code, 0) << c.args << ": " << r.err;
    const auto words = values_of<std::uint64_t>(s / "w");
    const auto zeta = values_of<double>(s / "z");
    const json wj = json_file(s / "w.json"), zj = json_file(s / "z.json");
    ASSERT_EQ(wj["words_per_pair"], c.words) << c.args;
    ASSERT_EQ(words.size(), zeta.size() * std::size_t(c.words)) << c.args;
    EXPECT_EQ(wj["count"], words.size());
    EXPECT_EQ(zj["count"], zeta.size());
    EXPECT_EQ(zj["pairs"], zeta.size());
    EXPECT_EQ(zj["pairs_per_step"].size(), 10u);
    EXPECT_EQ(zj["steps"]["first"], 15);
    EXPECT_EQ(zj["steps"]["last"], 24);
    std::uint64_t sum = 0;
    for (const auto& n : zj["pairs_per_step"]) sum += n.get<std::uint64_t>();
    EXPECT_EQ(sum, zeta.size());
    EXPECT_EQ(wj["pairs_per_step"], zj["pairs_per_step"]);
    EXPECT_EQ(wj["dtype"], "uint64");
    EXPECT_EQ(zj["dtype"], "float64");
    for (const char* k : {"generator", "seeding", "distribution", "feed", "key", "seed"})
      EXPECT_FALSE(wj[k].is_null()) << k;
    std::size_t mismatches = 0;
    for (std::size_t p = 0; p < zeta.size(); ++p) {
      const std::uint64_t* w = words.data() + p * std::size_t(c.words);
      const double again = c.distribution == Distribution::uniform
                               ? zeta_from<Distribution::uniform>(w, c.words, c.feed)
                               : zeta_from<Distribution::gauss>(w, c.words, c.feed);
      mismatches += again != zeta[p];
    }
    EXPECT_EQ(mismatches, 0u) << c.args << " of " << zeta.size();
  }
}

// Pair-step seeding makes a pair's ζ a function of (i, j, step) alone: the all-pairs loop and the linked cells,
// which meet the pairs in different orders, must write the same file.
TEST(CliTaps, PairsInTheCanonicalOrderWhateverThePairMode) {
  Scratch s;
  for (const char* mode : {"all", "cells"}) {
    const Result r = run(std::string("simulate -n 500 --steps 3 --equilibrate 0 -q --seeding pair-step --pairs ") +
                         mode + " --tap-steps 1:1 --tap-words " + (s / mode));
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const std::string all = slurp(s / "all"), cells = slurp(s / "cells");
  EXPECT_GT(all.size(), 8000u);
  EXPECT_TRUE(all == cells) << all.size() << " vs " << cells.size() << " bytes";
}

// 1100 beads: above the size at which the engine shares a step among threads.
TEST(CliTaps, BitwiseIdenticalForAnyThreadCount) {
  Scratch s;
  for (const char* mode : {"all", "cells"}) {
    std::string first_words, first_zeta;
    for (const int threads : {1, 2, 3}) {
      const std::string t = std::to_string(threads);
      const Result r = run(std::string("simulate -n 1100 --steps 5 --equilibrate 1 -q --pairs ") + mode +
                           " --threads " + t + " --tap-words " + (s / "w" + t) + " --tap-zeta " + (s / "z" + t));
      ASSERT_EQ(r.code, 0) << r.err;
      if (threads == 1) {
        first_words = slurp(s / "w1"), first_zeta = slurp(s / "z1");
        ASSERT_GT(first_zeta.size(), 4 * 8 * 1000u);
        continue;
      }
      EXPECT_TRUE(slurp(s / ("w" + t)) == first_words) << mode << ", " << t << " threads";
      EXPECT_TRUE(slurp(s / ("z" + t)) == first_zeta) << mode << ", " << t << " threads";
    }
  }
}

// A step that blows up is left out, as the zeta block leaves it out.
TEST(CliTaps, AStepThatBlowsUpIsNotWritten) {
  Scratch s;
  const Result r = run("simulate -n 64 --steps 400 --equilibrate 0 -q --dt 0.3 --json --tap-zeta " + (s / "z"));
  ASSERT_EQ(r.code, 0) << r.err;
  const json run = json::parse(r.out);
  const std::int64_t done = run["steps_done"];
  ASSERT_LT(done, 400) << "the run was meant to blow up: " << run["status"];
  const json side = json_file(s / "z.json");
  EXPECT_EQ(side["steps"]["last"], done - 1);
  EXPECT_EQ(side["pairs_per_step"].size(), std::size_t(done - 1));
  EXPECT_EQ(side["run"]["status"], run["status"]);
  EXPECT_EQ(values_of<double>(s / "z").size(), side["pairs"].get<std::size_t>());
}

// The words file is what the tests on words take, as it is.
TEST(CliTaps, FilesFeedTheTestsDirectly) {
  Scratch s;
  ASSERT_EQ(run("simulate -n 64 --steps 60 --equilibrate 10 -q --tap-words " + (s / "w") + " --tap-zeta " +
                (s / "z"))
                .code,
            0);
  for (const std::string& cmd : {"chi2 --input " + (s / "w") + " --format u64",
                                 "ttest --input " + (s / "w") + " --format u64",
                                 "nist --input " + (s / "w") + " --format raw --tests frequency,runs",
                                 "gof --input " + (s / "z") + " --format f64 --target gauss"}) {
    const Result r = run(cmd);
    EXPECT_EQ(r.code, 0) << cmd << ": " << r.err;
  }
}

}  // namespace dpdrng_test::cli_test_taps
