// The decomposition sweep's cells in the cell store: records read back to the bit, resume, unreadable cells,
// shards, a store that refuses another sweep's cells, and the assembled study.h5.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"
#include "dpdrng/study/h5.hpp"
#include "../cli/run_cli.hpp"
#include "../temp_dir.hpp"

namespace dpdrng::study::test_decomposition_cell {
namespace {
namespace fs = std::filesystem;
using cli_test::slurp;

// Three cells of two rows each, a fraction of a second in all.
const char* kTiny = R"(
name = "tiny"
domains = ["2", "2,2,1"]
seedings = ["distance", "pair-step", "grid:20"]
[[generators]]
name = "tea32"
rounds = [1]
[scene]
particles = 128
steps = 20
equilibrate = 5
[tests]
chi2_every = 5
ttest_pairs = 4
)";

DecompSweep tiny() { return parse_decomp_sweep(kTiny, "<test>"); }

// A row without its wall-clock seconds, as text (every double in its shortest round-trip digits; NaN, which
// never equals itself, as null): what must agree to the bit.
std::string timeless(const DecompResult& r) {
  nlohmann::json j = to_json(r);
  j["decomposed"].erase("seconds");
  if (j.contains("reference")) j["reference"].erase("seconds");
  return j.dump();
}

// Rows through an HDF5 cell group and back, as the store keeps them.
std::vector<DecompResult> round_trip(const std::vector<DecompResult>& rows, std::string* id = nullptr) {
  std::lock_guard lock(h5::lock());
  h5::Handle f = h5::create_memory_file();
  h5::Handle g = h5::create_group(f.id(), "cell");
  write_decomp_rows(g.id(), "some-cell", rows);
  std::vector<DecompResult> back;
  const std::string held = read_decomp_rows(g.id(), &back);
  if (id) *id = held;
  return back;
}

// Every output file's bytes, results.json without the seconds of its runs.
std::map<std::string, std::string> outputs(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "results.json")
      out[fs::relative(e.path(), dir).string()] = slurp(e.path().string());
  auto j = nlohmann::json::parse(slurp((dir / "results.json").string()));
  for (auto& r : j) {
    r["decomposed"].erase("seconds");
    if (r.contains("reference")) r["reference"].erase("seconds");
  }
  out["results.json"] = j.dump();
  return out;
}

std::vector<std::string> stored_files(const CellStore& store) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(store.dir() / "cells")) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(DecompositionStore, CellIdsFollowTheConfig) {
  const auto cells = decomp_cells(tiny());
  ASSERT_EQ(cells.size(), 3u);
  EXPECT_EQ(cells[0].id(), "tea32-r01-distance-gauss");
  EXPECT_EQ(cells[2].id(), "tea32-r01-grid20-gauss");
  // The name and description do not decide results: the hash ignores them; the steps do.
  std::string renamed = kTiny;
  renamed.replace(renamed.find("\"tiny\""), 6, "\"other\"");
  EXPECT_EQ(parse_decomp_sweep(renamed, "<test>").hash, tiny().hash);
  std::string longer = kTiny;
  longer.replace(longer.find("steps = 20"), 10, "steps = 21");
  EXPECT_NE(parse_decomp_sweep(longer, "<test>").hash, tiny().hash);
}

TEST(DecompositionStore, RecordKeepsNonFiniteNumbersToTheBit) {
  DecompResult r;
  r.generator = "tea32(1)";
  r.has_reference = true;
  r.decomposed.diffusion = -std::numeric_limits<double>::quiet_NaN();
  r.reference.temperature.sem = -std::numeric_limits<double>::infinity();
  r.randomness.cross_pair_p = 0.1 + 0.2;
  r.decomposed.boundary.zeta_diff_sum = 4.9406564584124654e-324;  // the smallest subnormal
  r.decomposed.boundary.evaluations = ~std::uint64_t{0};
  std::string id;
  const auto back = round_trip({r}, &id);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(id, "some-cell");
  const DecompResult& b = back.front();
  EXPECT_EQ(std::bit_cast<std::uint64_t>(b.decomposed.diffusion), std::bit_cast<std::uint64_t>(r.decomposed.diffusion));
  EXPECT_EQ(b.reference.temperature.sem, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(b.randomness.cross_pair_p, 0.1 + 0.2);
  EXPECT_EQ(b.decomposed.boundary.zeta_diff_sum, 4.9406564584124654e-324);
  EXPECT_EQ(b.decomposed.boundary.evaluations, ~std::uint64_t{0});
  EXPECT_EQ(b.generator, "tea32(1)");
  EXPECT_TRUE(b.has_reference);
}

TEST(DecompositionStore, RecordLackingAFieldIsRefusedNamingIt) {
  DecompResult r;
  r.has_reference = true;
  std::lock_guard lock(h5::lock());
  h5::Handle f = h5::create_memory_file();
  h5::Handle g = h5::create_group(f.id(), "cell");
  write_decomp_rows(g.id(), "some-cell", {r});
  ASSERT_GE(H5Ldelete(g.id(), "row0/randomness", H5P_DEFAULT), 0);
  try {
    read_decomp_rows(g.id(), nullptr);
    ADD_FAILURE() << "read a record without its randomness";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("randomness"), std::string::npos) << e.what();
  }
}

TEST(DecompositionStore, ResumeComputesOnlyTheMissingCellAndGivesTheSameOutputs) {
  const DecompSweep s = tiny();
  TempDir t;
  const CellStore store(t.path / "store");
  open_decomp_store(store, s);
  const DecompRunSummary first = run_decomp_sweep(s, store, {});
  EXPECT_EQ(first.computed, 3u);
  EXPECT_EQ(first.resumed, 0u);
  const auto cells = decomp_cells(s);
  // Stored rows are the computed rows, to the bit.
  const auto fresh = run_decomp_cell(s, cells[0]);
  const auto loaded = load_decomp_cell(store, cells[0]);
  ASSERT_EQ(fresh.size(), loaded.size());
  for (std::size_t i = 0; i < fresh.size(); ++i) EXPECT_EQ(timeless(fresh[i]), timeless(loaded[i]));
  write_decomp_outputs(s, load_decomp_rows(s, store, nullptr), (t.path / "a").string(), nullptr);

  const std::string kept0 = slurp(store.cell_path(cells[0].id()).string()), kept2 = slurp(store.cell_path(cells[2].id()).string());
  fs::remove(store.cell_path(cells[1].id()));
  std::ostringstream log;
  const DecompRunSummary second = run_decomp_sweep(s, store, {{}, &log});
  EXPECT_EQ(second.computed, 1u);
  EXPECT_EQ(second.resumed, 2u);
  EXPECT_NE(log.str().find("2 of 3 cells already stored: resuming"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("3/3 cells  tea32(1)"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("pair-step"), std::string::npos) << log.str();
  EXPECT_EQ(slurp(store.cell_path(cells[0].id()).string()), kept0);
  EXPECT_EQ(slurp(store.cell_path(cells[2].id()).string()), kept2);
  std::vector<std::string> missing;
  write_decomp_outputs(s, load_decomp_rows(s, store, &missing), (t.path / "b").string(), nullptr);
  EXPECT_TRUE(missing.empty());
  const auto a = outputs(t.path / "a"), b = outputs(t.path / "b");
  EXPECT_GE(a.size(), 3u);
  EXPECT_EQ(a, b);

  // Nothing left to do: a third run computes nothing.
  EXPECT_EQ(run_decomp_sweep(s, store, {}).computed, 0u);
}

TEST(DecompositionStore, UnreadableCellIsNamedAndComputedAgain) {
  const DecompSweep s = tiny();
  TempDir t;
  const CellStore store(t.path / "store");
  open_decomp_store(store, s);
  run_decomp_sweep(s, store, {});
  const auto cells = decomp_cells(s);
  const fs::path cut = store.cell_path(cells[0].id()), edited = store.cell_path(cells[1].id());
  const std::string whole = slurp(cut.string());
  std::ofstream(cut, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 2);
  std::string bytes = slurp(edited.string());
  bytes[bytes.size() - 100] ^= 1;  // one bit changed on disk: the same length, not what was written
  std::ofstream(edited, std::ios::binary | std::ios::trunc) << bytes;

  std::string why;
  EXPECT_EQ(decomp_cell_state(store, cells[0], &why), CellStore::State::unreadable);
  EXPECT_NE(why.find("cut short"), std::string::npos) << why;
  EXPECT_EQ(decomp_cell_state(store, cells[1], &why), CellStore::State::unreadable);
  EXPECT_NE(why.find("checksum"), std::string::npos) << why;
  EXPECT_THROW(load_decomp_cell(store, cells[0]), std::exception);
  std::vector<std::string> missing;
  EXPECT_EQ(load_decomp_rows(s, store, &missing).size(), 2u);
  EXPECT_EQ(missing, (std::vector<std::string>{cells[0].id(), cells[1].id()}));

  std::ostringstream log;
  const DecompRunSummary again = run_decomp_sweep(s, store, {{}, &log});
  EXPECT_EQ(again.computed, 2u);
  EXPECT_EQ(again.unreadable, (std::vector<std::string>{cut.string(), edited.string()}));
  EXPECT_NE(log.str().find(cut.string() + " is unreadable"), std::string::npos) << log.str();
  EXPECT_EQ(decomp_cell_state(store, cells[0]), CellStore::State::stored);
  EXPECT_EQ(decomp_cell_state(store, cells[1]), CellStore::State::stored);
}

TEST(DecompositionStore, ShardsPartitionTheCells) {
  const DecompSweep s = tiny();
  const auto cells = decomp_cells(s);
  TempDir t;
  const CellStore one(t.path / "one"), both(t.path / "both");
  open_decomp_store(one, s);
  open_decomp_store(both, s);
  EXPECT_EQ(run_decomp_sweep(s, one, {{1, 2}, nullptr}).computed, 2u);
  EXPECT_EQ(stored_files(one), (std::vector<std::string>{cells[0].id() + ".h5", cells[2].id() + ".h5"}));
  // Shards may share a directory: each writes only its own cells.
  EXPECT_EQ(run_decomp_sweep(s, both, {{2, 2}, nullptr}).computed, 1u);
  EXPECT_EQ(stored_files(both), (std::vector<std::string>{cells[1].id() + ".h5"}));
  const DecompRunSummary rest = run_decomp_sweep(s, both, {{1, 2}, nullptr});
  EXPECT_EQ(rest.computed, 2u);
  EXPECT_EQ(rest.resumed, 0u);
  std::vector<std::string> missing;
  EXPECT_EQ(load_decomp_rows(s, both, &missing).size(), 6u);
  EXPECT_TRUE(missing.empty());
}

TEST(DecompositionStore, RefusesAnotherSweepsDirectory) {
  TempDir t;
  const CellStore store(t.path / "store");
  open_decomp_store(store, tiny());
  std::string longer = kTiny;
  longer.replace(longer.find("steps = 20"), 10, "steps = 21");
  try {
    open_decomp_store(store, parse_decomp_sweep(longer, "<test>"));
    ADD_FAILURE() << "opened a store of another sweep";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different config"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(t.path / "store" / "decomposition.toml"));
}

TEST(DecompositionStore, BadKeysAreInputErrorsNamingTheKey) {
  const auto message = [](const std::string& from, const std::string& to) {
    std::string text = kTiny;
    text.replace(text.find(from), from.size(), to);
    try {
      parse_decomp_sweep(text, "<test>");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("steps = 20", "stepz = 20").find("scene.stepz"), std::string::npos);
  EXPECT_NE(message("steps = 20", "steps = -3").find("scene.steps"), std::string::npos);
  EXPECT_NE(message("chi2_every = 5", "chi2_every = \"5\"").find("tests.chi2_every"), std::string::npos);
  EXPECT_NE(message("\"grid:20\"", "\"grid:99\"").find("seedings"), std::string::npos);
}

TEST(DecompositionStore, CliResumesAndWritesTheOutputsOnceEveryCellIsStored) {
  TempDir t;
  const fs::path config = t.path / "tiny.toml", out = t.path / "out";
  std::ofstream(config) << kTiny;
  const std::string cmd = "decompose --study " + config.string() + " --out " + out.string();
  const cli_test::Result half = cli_test::run(cmd + " --shard 2/2");
  ASSERT_EQ(half.code, 0) << half.err;
  EXPECT_NE(half.err.find("1 computed, 0 resumed; 1 of 3 cells stored"), std::string::npos) << half.err;
  EXPECT_FALSE(fs::exists(out / "table.md"));
  const cli_test::Result rest = cli_test::run(cmd);
  ASSERT_EQ(rest.code, 0) << rest.err;
  EXPECT_NE(rest.err.find("1 of 3 cells already stored: resuming"), std::string::npos) << rest.err;
  EXPECT_NE(rest.err.find("2 computed, 1 resumed; 3 of 3 cells stored"), std::string::npos) << rest.err;
  EXPECT_EQ(rest.out, slurp((out / "table.md").string()));
  EXPECT_TRUE(fs::exists(out / "decomposition.toml"));
  // Every stored cell is assembled into study.h5 as the study's are: rows as groups, counts as integers.
  ASSERT_TRUE(fs::exists(out / "study.h5"));
  {
    std::lock_guard lock(h5::lock());
    h5::Handle f = h5::open_file((out / "study.h5").string());
    EXPECT_EQ(std::get<std::int64_t>(h5::read_attributes(f.id()).at("cells_stored")), 3);
    h5::Handle b = h5::open_group(f.id(), "cells/" + decomp_cells(tiny())[0].id() + "/row1/decomposed/boundary");
    const auto a = h5::read_attributes(b.id());
    EXPECT_GT(std::get<std::uint64_t>(a.at("evaluations")), 0u);
    EXPECT_TRUE(std::holds_alternative<double>(a.at("zeta_diff_max")));
  }
  EXPECT_EQ(cli_test::run(cmd + " --shard 3/2").code, 2);
  EXPECT_EQ(cli_test::run("decompose --shard 1/2 --steps 5").code, 2);
}

}  // namespace
}  // namespace dpdrng::study::test_decomposition_cell
