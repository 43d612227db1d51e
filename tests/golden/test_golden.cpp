// Bitwise regression: CI-sized runs of every study kind (water, bilayer, decomposition), single simulate runs
// across pair modes, integrators, seedings, generators and thread counts, and the standalone streams, each
// flattened into named quantities and compared with the committed digests (tests/golden/*.digest). Timings are
// left out; everything else must agree to the bit. See tests/golden/README.md for when to regenerate.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"
#include "dpdrng/study/h5.hpp"
#include "dpdrng/study/measure.hpp"
#include "dpdrng/study/runner.hpp"
#include "dpdrng/study/store.hpp"
#include "quantities.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::golden_test_golden {

namespace fs = std::filesystem;
using namespace dpdrng;
using namespace dpdrng::golden;

namespace {

std::string source(const std::string& file) { return std::string(DPDRNG_SOURCE_DIR) + "/tests/golden/" + file; }

// Wall-clock figures and the CPU that made them: cell seconds, the cost.* timings (the pair count per step is a
// result, kept) and the cost.cpu note.
bool timing_attribute(const std::string& name) {
  return name == "seconds" || name == "note.cost.cpu" ||
         (name.rfind("cost.", 0) == 0 && name != "cost.numbers_per_step");
}

// Every attribute and dataset of one stored cell group, read from the file as h5py would.
void read_group(hid_t g, const std::string& prefix, Quantities& q) {
  for (const auto& [name, value] : study::h5::read_attributes(g)) {
    if (timing_attribute(name)) continue;
    if (const auto* d = std::get_if<double>(&value)) q[prefix + name] = f64(*d);
    if (const auto* i = std::get_if<std::int64_t>(&value)) q[prefix + name] = i64(*i);
    if (const auto* u = std::get_if<std::uint64_t>(&value)) q[prefix + name] = "u64 " + std::to_string(*u);
    if (const auto* s = std::get_if<std::string>(&value)) q[prefix + name] = str(*s);
  }
  for (const auto& name : study::h5::list(g)) {
    if (study::h5::is_group(g, name)) {
      study::h5::Handle sub = study::h5::open_group(g, name);
      read_group(sub.id(), prefix + name + "/", q);
    } else if (study::h5::is_string_dataset(g, name)) {
      q[prefix + name] = strs(study::h5::read_strings(g, name));
    } else {
      const auto dims = study::h5::shape(g, name);
      q[prefix + name] = f64s(study::h5::read_doubles(g, name), std::vector<std::size_t>(dims.begin(), dims.end()));
    }
  }
}

// The study as `dpdrng study run CONFIG --threads 2` does it, then every stored cell file.
Runs study_cells(const std::string& config_file) {
  const study::StudyConfig config = study::load_config(source(config_file));
  TempDir dir;
  study::Store store(dir.path);
  store.open_for(config);
  study::RunOptions options;
  options.threads = 2;
  const study::RunSummary summary = study::run_study(config, store, options, study::measure_cell);
  EXPECT_EQ(summary.failed, 0u);
  EXPECT_EQ(summary.computed, summary.cells);
  Runs runs;
  std::lock_guard lock(study::h5::lock());
  for (const auto& entry : fs::directory_iterator(dir.path / "cells")) {
    if (entry.path().extension() != ".h5") continue;
    study::h5::Handle file = study::h5::open_file(entry.path().string());
    study::h5::Handle cell = study::h5::open_group(file.id(), "cell");
    read_group(cell.id(), "", runs[entry.path().stem().string()]);
  }
  return runs;
}

// Quantities of one simulate run: its JSON record with arrays (timings aside, but the counts of numbers drawn;
// list_builds also counts the timed evaluations of the RNG-share estimate, whose number depends on the clock)
// and its taps.
Quantities simulate_quantities(const dpd::RunResult& r) {
  Quantities q;
  const auto keep = [](const std::string& path) {
    if (path.rfind("timings/", 0) != 0) return true;
    return path == "timings/random_numbers" || path == "timings/zetas";
  };
  flatten(dpd::to_json(r, true), "", q, keep);
  for (std::size_t k = 0; k < r.taps.raw.size(); ++k) {
    const auto& t = r.taps.raw[k];
    const std::string p = "taps/raw/" + std::to_string(k) + "/";
    q[p + "step"] = i64(t.step);
    q[p + "words_per_pair"] = i64(t.words_per_pair);
    for (int w = 0; w < t.words_per_pair; ++w) q[p + "word" + std::to_string(w)] = ints(t.words[w]);
  }
  for (std::size_t k = 0; k < r.taps.series.size(); ++k) {
    const auto& s = r.taps.series[k];
    const std::string p = "taps/pairs/" + std::to_string(k) + "/";
    q[p + "pair"] = str(std::to_string(s.i) + "," + std::to_string(s.j));
    q[p + "steps"] = ints(s.steps);
    for (int w = 0; w < s.words_per_pair; ++w) q[p + "word" + std::to_string(w)] = ints(s.words[w]);
    q[p + "zeta"] = f64s(s.zeta);
  }
  return q;
}

struct SimRun {
  std::string name;
  dpd::WaterConfig cfg;
  std::vector<int> threads{2};
};

dpd::WaterConfig cells_base() {
  dpd::WaterConfig c;
  c.particles = 3000;  // 10 z-layers of cells: two threads each own a block of layers
  c.gamma = 4.5;
  c.pairs = dpd::PairMode::cells;
  c.steps = 30;
  c.equilibrate = 10;
  c.sample_every = 5;
  c.series = true;
  c.seed = 5;
  c.init_seed = 77;
  c.taps.raw_steps = {12, 25};
  c.taps.pairs = {{0, 1}, {0, 2}, {5, 6}, {100, 2999}};
  return c;
}

dpd::WaterConfig all_base() {
  dpd::WaterConfig c;
  c.steps = 60;
  c.equilibrate = 20;
  c.sample_every = 5;
  c.series = true;
  c.seed = 9;
  c.init_seed = 31;
  c.taps.raw_steps = {30, 45};
  c.taps.pairs = {{0, 1}, {0, 2}, {17, 200}};
  return c;
}

SimRun run(std::string name, dpd::WaterConfig c, const char* gen, int rounds, rng::Seeding seeding,
           rng::Distribution dist, std::vector<int> threads = {2}) {
  c.generator = rng::GeneratorSpec{gen, rounds, rng::kPaperTeaKey};
  c.seeding = seeding;
  c.distribution = dist;
  return {std::move(name), std::move(c), std::move(threads)};
}

std::vector<SimRun> simulate_runs() {
  using D = rng::Distribution;
  using S = rng::Seeding;
  const auto cells = cells_base(), all = all_base();
  std::vector<SimRun> v{
      run("cells/tea32-r1-gauss-distance", cells, "tea32", 1, S::distance, D::gauss, {1, 2}),
      run("cells/mt19937-gauss", cells, "mt19937", 0, S::distance, D::gauss, {1, 2}),
      run("cells/tea64-r8-uniform-pair-step", cells, "tea64", 8, S::pair_step, D::uniform),
      run("cells/tea32-r7-gauss-distance", cells, "tea32", 7, S::distance, D::gauss),  // a round count run at run time
      run("cells/tea64-r1-gauss-distance", cells, "tea64", 1, S::distance, D::gauss),
      run("cells/philox4x32-r10-gauss-pair-step", cells, "philox4x32", 10, S::pair_step, D::gauss),
      run("cells/philox4x32-r4-uniform-distance", cells, "philox4x32", 4, S::distance, D::uniform),
      run("cells/threefry2x64-r20-gauss-distance", cells, "threefry2x64", 20, S::distance, D::gauss),
      run("cells/threefry2x64-r13-uniform-pair-step", cells, "threefry2x64", 13, S::pair_step, D::uniform),
      run("cells/splitmix64-gauss-distance", cells, "splitmix64", 0, S::distance, D::gauss),
      run("cells/splitmix64-uniform-pair-step", cells, "splitmix64", 0, S::pair_step, D::uniform),
      run("cells/saru-gauss-pair-step", cells, "saru", 0, S::pair_step, D::gauss),
      run("cells/saru-uniform-distance", cells, "saru", 0, S::distance, D::uniform),
      run("all/tea32-r1-gauss-distance", all, "tea32", 1, S::distance, D::gauss, {1, 2}),
      run("all/tea64-r1-uniform-pair-step", all, "tea64", 1, S::pair_step, D::uniform),
      run("all/mt19937-uniform", all, "mt19937", 0, S::distance, D::uniform),
      run("all/saru-gauss-distance", all, "saru", 0, S::distance, D::gauss),
  };
  // The benchmark's baselines: ζ = 0 without a generator, and the seed words unhashed.
  // The stream reference has no pair series in cells mode (a pair draws only while in range).
  for (SimRun& r : v)
    if (r.cfg.generator.name == "mt19937" && r.cfg.pairs == dpd::PairMode::cells) r.cfg.taps.pairs.clear();
  SimRun none = run("cells/baseline-none", cells, "tea32", 1, S::distance, D::gauss);
  none.cfg.noise_override = dpd::NoiseOverride::none;
  SimRun unhashed = run("cells/baseline-unhashed-gauss", cells, "tea32", 1, S::distance, D::gauss);
  unhashed.cfg.noise_override = dpd::NoiseOverride::unhashed;
  none.cfg.taps = unhashed.cfg.taps = {};
  v.push_back(none), v.push_back(unhashed);
  // Shardlow's S1 (no taps: it draws in its own sweep).
  dpd::WaterConfig s1 = all;
  s1.integrator = dpd::Integrator::shardlow;
  s1.taps = {};
  s1.dt = 0.06;
  v.push_back(run("shardlow/tea32-r1-gauss-distance", s1, "tea32", 1, S::distance, D::gauss, {1, 2}));
  v.push_back(run("shardlow/philox4x32-r10-uniform-pair-step", s1, "philox4x32", 10, S::pair_step, D::uniform));
  v.push_back(run("shardlow/mt19937-gauss", s1, "mt19937", 0, S::distance, D::gauss));
  s1.pairs = dpd::PairMode::cells;
  v.push_back(run("shardlow-cells/tea64-r8-gauss-distance", s1, "tea64", 8, S::distance, D::gauss));
  return v;
}

}  // namespace

TEST(Golden, WaterStudyCells) {
  check("water.digest", study_cells("water.toml"), true, "tests/golden/water.toml's cells");
}

TEST(Golden, BilayerStudyCells) {
  check("bilayer.digest", study_cells("bilayer.toml"), true, "tests/golden/bilayer.toml's cells");
}

// The sweep as `dpdrng decompose --study CONFIG` does it, every row read back from the stored cell files.
TEST(Golden, DecompositionSweep) {
  const study::DecompSweep sweep = study::load_decomp_sweep(source("decomposition.toml"));
  TempDir dir;
  const study::CellStore store(dir.path / "out");
  study::open_decomp_store(store, sweep);
  study::run_decomp_sweep(sweep, store, {});
  std::vector<std::string> missing;
  const auto rows = study::load_decomp_rows(sweep, store, &missing);
  EXPECT_TRUE(missing.empty());
  Runs runs;
  for (const auto& r : rows) {
    const std::string name = r.generator + "/" + r.seeding + "/" + r.distribution + "/" + r.domains;
    EXPECT_FALSE(runs.count(name)) << name;
    flatten(study::to_json(r), "", runs[name], [](const std::string& path) {
      return path != "seconds" && !path.ends_with("/seconds");
    });
  }
  check("decomposition.digest", runs, true, "tests/golden/decomposition.toml's sweep");
}

// Every thread count of a run must give the same quantities; the first is compared with the digests.
TEST(Golden, SimulateRuns) {
  Runs runs;
  for (const SimRun& s : simulate_runs()) {
    for (int t : s.threads) {
      dpd::WaterConfig c = s.cfg;
      c.threads = t;
      c.team_beads = 0;  // the paper's 256 beads too: every count must give the digests
      Quantities q = simulate_quantities(dpd::run_water(c));
      if (!runs.count(s.name)) {
        runs[s.name] = std::move(q);
        continue;
      }
      const auto diffs = differences({{s.name, runs[s.name]}}, {{s.name, q}}, true);
      EXPECT_TRUE(diffs.empty()) << s.name << " with " << t << " threads differs from " << s.threads.front()
                                 << " thread(s): " << diffs.front();
    }
  }
  check("simulate.digest", runs, true, "the simulate runs of test_golden.cpp");
}

TEST(Golden, Streams) {
  const std::vector<rng::GeneratorSpec> specs{
      {"tea32", 1}, {"tea32", 8}, {"tea32", 7}, {"tea32", 32}, {"tea64", 1}, {"tea64", 3}, {"tea64", 11},
      {"philox4x32", 10}, {"philox4x32", 4}, {"threefry2x64", 13}, {"threefry2x64", 5}, {"splitmix64", 0},
      {"saru", 0}, {"mt19937", 0}};
  Runs runs;
  for (rng::GeneratorSpec spec : specs) {
    spec = rng::validated(spec);
    Quantities& q = runs[rng::describe(spec)];
    std::vector<std::uint64_t> words(1000);
    rng::fill_stream(spec, 0x123456789ull, 3, words);
    q["words"] = ints(words);
    std::vector<double> z(1000);
    rng::fill_noise(spec, rng::Distribution::gauss, 0x123456789ull, 5, z);
    q["gauss"] = f64s(z);
    rng::fill_noise(spec, rng::Distribution::uniform, 0x123456789ull, 5, z);
    q["uniform"] = f64s(z);
    rng::fill_unit(spec, 77, 1, z);
    q["unit"] = f64s(z);
  }
  check("streams.digest", runs, true, "the standalone streams of test_golden.cpp");
}

}  // namespace dpdrng_test::golden_test_golden
