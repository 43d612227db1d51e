// Plug-in generators (dpdrng/plugin.h, `ext:PATH`): the loader's checks, the library's identity, and the example
// that re-implements 32TEA(n) in plain C giving bitwise the built-in's words, ζ and simulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "../cli/run_cli.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/sha256.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/stream.hpp"

namespace dpdrng_test::plugin {

using dpdrng::InputError;
using nlohmann::json;
namespace rng = dpdrng::rng;

namespace {

std::string library(const std::string& name) { return std::string(DPDRNG_PLUGIN_DIR) + "/lib" + name + ".so"; }
std::string ext(const std::string& name) { return "ext:" + library(name); }

std::string sha(const std::string& text) {
  return dpdrng::sha256_hex({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

// FIPS 180-2, Appendix B (SHA-256 examples) and the one-million-'a' message of its B.3.
TEST(Sha256, PublishedExamples) {
  EXPECT_EQ(sha(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmn"
                "opqrstnopqrstu"),
            "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
  EXPECT_EQ(sha(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// coreutils' sha256sum as the outside reference for a file (a plug-in library, several 64 KiB read chunks).
TEST(Sha256, FileDigestEqualsSha256sum) {
  const std::string file = library("tea32_1");
  FILE* p = popen(("sha256sum '" + file + "' 2>/dev/null").c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[65] = {};
  const std::size_t got = std::fread(buf, 1, 64, p);
  const int status = pclose(p);
  if (got != 64 || status != 0) GTEST_SKIP() << "sha256sum not available";
  EXPECT_EQ(dpdrng::sha256_file(file), std::string(buf, 64));
  EXPECT_THROW(dpdrng::sha256_file(library("no_such_plugin")), InputError);
}

TEST(Plugin, LoadsOncePerPathAndNamesItsLibrary) {
  const rng::LoadedPlugin& p = rng::load_plugin(ext("tea32_1"));
  EXPECT_EQ(p.name, "tea32c(1)");
  EXPECT_EQ(p.api->words, 1u);
  EXPECT_EQ(p.sha256, dpdrng::sha256_file(library("tea32_1")));
  EXPECT_EQ(&rng::load_plugin(ext("tea32_1")), &p);
  EXPECT_EQ(rng::find_generator(ext("tea32_1")).family, rng::Family::plugin);
  EXPECT_EQ(rng::validated({ext("tea32_1"), 0}).rounds, 1);
  EXPECT_THROW(rng::validated({ext("tea32_1"), 2}), InputError);
  EXPECT_EQ(rng::words_per_call({ext("fmix64"), 0}), 2);
}

TEST(Plugin, RefusesWhatItCannotRunWithTheReason) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"broken_1", "ABI 2"},          {"broken_2", "words = 3"},         {"broken_3", "supports no seeding"},
      {"broken_4", "name is NULL"},   {"broken_5", "returned NULL"},     {"no_such_plugin", "No such file"},
  };
  for (const auto& [name, reason] : cases) {
    try {
      rng::load_plugin(ext(name));
      ADD_FAILURE() << name << " loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << name << ": " << e.what();
    }
  }
  EXPECT_THROW(rng::load_plugin("ext:"), InputError);
  EXPECT_THROW(rng::load_plugin("ext:" DPDRNG_SOURCE_DIR "/README.md"), InputError);  // not a shared library
  // A valid plug-in without a distance entry runs pair-step and counter seedings, and says so under distance.
  const rng::GeneratorSpec partial{ext("broken_6"), 0};
  EXPECT_NO_THROW(rng::check_seeding(partial, rng::Seeding::pair_step));
  EXPECT_NO_THROW(rng::check_seeding(partial, rng::Seeding::counter));
  EXPECT_THROW(rng::check_seeding(partial, rng::Seeding::distance), InputError);
  EXPECT_THROW(rng::with_pair_noise(partial, rng::Seeding::distance, rng::Distribution::gauss, 1, [](auto) {}),
               InputError);
}

// Every seeding, both blocks of the blocks feed, and the counter stream, against the built-in Tea32<R>.
template <int R>
void expect_tea32_words(const std::string& plugin) {
  const rng::GeneratorSpec mine{ext(plugin), 0}, builtin{"tea32", R};
  std::vector<std::uint64_t> a(5000), b(5000);
  for (std::uint64_t start : {0ull, 123456789ull, ~0ull - 6000}) {
    rng::fill_stream(mine, start, 17, a);
    rng::fill_stream(builtin, start, 17, b);
    EXPECT_EQ(a, b) << plugin << " start " << start;
  }
  std::mt19937_64 draw(42);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (int t = 0; t < 2000; ++t) {
    const std::uint32_t i = std::uint32_t(draw() % 100000), j = i + 1 + std::uint32_t(draw() % 1000);
    const rng::PairInput p{i, j, d(draw), d(draw), d(draw), draw() >> 1};
    const std::uint64_t seed = draw();
    for (const rng::PairInput& q : {p, rng::second_input(p)})
      for (rng::Seeding s : {rng::Seeding::distance, rng::Seeding::pair_step})
        for (rng::Feed f : {rng::Feed::halves, rng::Feed::blocks})
          EXPECT_EQ(rng::with_pair_noise(mine, s, rng::Distribution::gauss, seed, [&](auto n) { return n(q); }, f),
                    rng::with_pair_noise(builtin, s, rng::Distribution::gauss, seed, [&](auto n) { return n(q); }, f))
              << plugin << " pair " << i << "," << j;
  }
}

TEST(Plugin, Tea32ExampleGivesTheBuiltinsWordsAndZeta) {
  expect_tea32_words<1>("tea32_1");
  expect_tea32_words<4>("tea32_4");
}

// The simulation's physics (everything but the generator's name and the timings) bit for bit, through the
// engine's batched plug-in path: both seedings, the blocks feed's second blocks, all-pairs rows and cells' layers,
// two threads.
TEST(Plugin, Tea32ExampleSimulatesBitForBitAsTheBuiltin) {
  using dpdrng::cli_test::run;
  const std::string base = "simulate -n 256 --steps 60 --equilibrate 20 --threads 2 --json ";
  for (const std::string opts : {"--seeding distance --feed halves --pairs all",
                                 "--seeding distance --feed blocks --pairs cells",
                                 "--seeding pair-step --feed halves --pairs cells",
                                 "--seeding pair-step --feed blocks --pairs all --distribution gauss"}) {
    const auto mine = run(base + opts + " -g " + ext("tea32_4"));
    const auto builtin = run(base + opts + " -g tea32 -r 4");
    ASSERT_EQ(mine.code, 0) << mine.err;
    ASSERT_EQ(builtin.code, 0) << builtin.err;
    EXPECT_NE(mine.err.find("loaded plug-in 'tea32c(4)'"), std::string::npos) << mine.err;
    json a = json::parse(mine.out), b = json::parse(builtin.out);
    EXPECT_EQ(a["generator"], ext("tea32_4"));
    EXPECT_EQ(a["plugin"]["name"], "tea32c(4)");
    EXPECT_EQ(a["plugin"]["sha256"], dpdrng::sha256_file(library("tea32_4")));
    EXPECT_FALSE(b.contains("plugin"));
    for (json* j : {&a, &b}) j->erase("generator"), j->erase("plugin"), j->erase("timings"), j->erase("inputs");
    EXPECT_EQ(a.dump(), b.dump()) << opts;
  }
}

// The two-word example runs the engine and the stream. Its ζ's second moment is within 2 % of 1 (the run's 95 %
// CI is ±0.6 %; 32TEA(1)'s halves feed, the defect of the default study, gives 0.965 here).
TEST(Plugin, TwoWordExampleRuns) {
  using dpdrng::cli_test::run;
  const auto sim = run("simulate -n 256 --steps 200 --equilibrate 50 --json -g " + ext("fmix64"));
  ASSERT_EQ(sim.code, 0) << sim.err;
  const json z = json::parse(sim.out)["zeta"];
  EXPECT_NEAR(z["second_moment"].get<double>(), 1.0, 0.02);
  const auto gen = run("gen --count 3 -g " + ext("fmix64"));
  EXPECT_EQ(gen.code, 0);
  EXPECT_EQ(std::count(gen.out.begin(), gen.out.end(), '\n'), 6) << gen.out;  // two words per call
}

TEST(Plugin, CommandsRefuseAPluginThatCannotRunTheirSeeding) {
  using dpdrng::cli_test::run;
  const auto r = run("simulate -n 64 --steps 20 --equilibrate 10 -g " + ext("broken_6"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("does not support seeding 'distance'"), std::string::npos) << r.err;
  const auto bad = run("gen --count 2 -g " + ext("broken_1"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("ABI"), std::string::npos) << bad.err;
  const auto key = run("gen --count 2 --key 1,2,3,4 -g " + ext("tea32_1"));
  EXPECT_EQ(key.code, 2);
  EXPECT_NE(key.err.find("--key"), std::string::npos) << key.err;
}

}  // namespace
}  // namespace dpdrng_test::plugin
