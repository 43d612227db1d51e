// The results store: records round-trip, interrupted runs resume without recomputing finished cells, shards
// merge into what one run gives, and a store refuses cells of another config.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/runner.hpp"
#include "dpdrng/study/store.hpp"
#include "fake_measure.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::study_test_store {

using namespace dpdrng::study;
namespace fs = std::filesystem;

namespace {

const std::string kConfig = fake::small_config_toml("store-test", 3);

// A fresh store of kConfig in its own directory.
struct OpenStore {
  TempDir tmp;
  StudyConfig cfg = parse_config(kConfig, "c.toml");
  Store store{tmp.path};
  OpenStore() { store.open_for(cfg); }
};

MeasureFn as_fn(fake::FakeMeasure& f) {
  return [&f](const Cell& c, const StudyConfig& cfg, int t) { return f(c, cfg, t); };
}

// Everything a cell holds, as text: two stores are equal when these agree for every cell.
std::string fingerprint(const CellResult& r) {
  std::string s = r.cell.id() + "|" + std::string(to_string(r.status)) + "|" + r.reason;
  for (const auto& [k, v] : r.scalars) s += "|" + k + "=" + std::to_string(v);
  for (const auto& [k, v] : r.series) {
    s += "|" + k + ":";
    for (double x : v) s += std::to_string(x) + ",";
  }
  return s;
}

std::vector<std::string> fingerprints(const std::vector<CellResult>& cells) {
  std::vector<std::string> out;
  for (const auto& c : cells) out.push_back(fingerprint(c));
  return out;
}

struct FileId {
  ino_t inode;
  timespec mtime;
  bool operator==(const FileId& o) const {
    return inode == o.inode && mtime.tv_sec == o.mtime.tv_sec && mtime.tv_nsec == o.mtime.tv_nsec;
  }
};
FileId file_id(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
  return {st.st_ino, st.st_mtim};
}

}  // namespace

TEST(StudyStore, CellRoundTripsThroughHdf5) {
  OpenStore s;
  const StudyConfig& cfg = s.cfg;
  Store& store = s.store;
  CellResult r;
  r.cell = enumerate_cells(cfg)[1];
  r.status = CellStatus::unstable;
  r.unstable_step = 17;
  r.reason = "unstable at step 17: NaN in the forces";
  r.scalars["temperature_mean"] = 1.0312;
  r.scalars["chi2.a.trials"] = 100;
  r.notes["nist"] = "not applicable: too few bits";
  r.series["vpdf/p"] = {0.1, 0.2, 0.3};
  r.series["empty"] = {};
  r.matrices["nist/histogram"] = dpdrng::study::h5::Matrix{2, 3, {1, 2, 3, 4, 5, 6}};
  r.strings["nist/test"] = {"Frequency", "BlockFrequency"};
  store.save(r);
  ASSERT_TRUE(store.has(r.cell));
  const CellResult back = store.load(r.cell);
  EXPECT_EQ(fingerprint(back), fingerprint(r));
  EXPECT_EQ(back.cell.seed, r.cell.seed);
  EXPECT_EQ(back.unstable_step, 17);
  EXPECT_EQ(back.notes.at("nist"), r.notes.at("nist"));
  EXPECT_EQ(back.matrices.at("nist/histogram").cols, 3u);
  EXPECT_EQ(back.matrices.at("nist/histogram").data, r.matrices.at("nist/histogram").data);
  EXPECT_EQ(back.strings.at("nist/test"), r.strings.at("nist/test"));
  EXPECT_TRUE(back.series.at("empty").empty());
}

TEST(StudyStore, ResumeRecomputesOnlyMissingOrDamagedCells) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  const std::size_t n = enumerate_cells(cfg).size();

  TempDir ref_dir;
  fake::FakeMeasure ref_measure;
  Store ref(ref_dir.path);
  ref.open_for(cfg);
  run_study(cfg, ref, RunOptions{}, as_fn(ref_measure));

  TempDir tmp;
  fake::FakeMeasure m;
  Store store(tmp.path);
  store.open_for(cfg);
  RunOptions o;
  o.threads = 2;
  RunSummary s = run_study(cfg, store, o, as_fn(m));
  EXPECT_EQ(s.computed, n);
  const auto cells = enumerate_cells(cfg);
  const fs::path kept = store.cell_path(cells[0]);
  const FileId before = file_id(kept);

  // An interrupted run: one cell never finished, one was cut short mid-write, and a temp file was left behind.
  fs::remove(store.cell_path(cells[2]));
  fs::resize_file(store.cell_path(cells[4]), fs::file_size(store.cell_path(cells[4])) / 2);
  std::ofstream(tmp.path / "cells" / ".stray.h5.tmp123") << "partial";

  s = run_study(cfg, store, o, as_fn(m));
  EXPECT_EQ(s.resumed, n - 2);
  EXPECT_EQ(s.computed, 2u);
  for (const auto& c : cells) {
    const int expect = (c.id() == cells[2].id() || c.id() == cells[4].id()) ? 2 : 1;
    EXPECT_EQ(m.calls[c.id()], expect) << c.id();
  }
  EXPECT_TRUE(file_id(kept) == before) << "a finished cell was rewritten";
  EXPECT_EQ(fingerprints(store.load_all()), fingerprints(ref.load_all()));

  // A third run has nothing to do.
  s = run_study(cfg, store, o, as_fn(m));
  EXPECT_EQ(s.computed, 0u);
  EXPECT_EQ(store.assemble(cfg), n);
}

TEST(StudyStore, RefusesAnotherConfigsDirectory) {
  TempDir tmp;
  const StudyConfig a = parse_config(kConfig, "a.toml");
  std::string other = kConfig;
  other.replace(other.find("replicas = 3"), 12, "replicas = 2");
  const StudyConfig b = parse_config(other, "b.toml");
  Store(tmp.path).open_for(a);
  try {
    Store(tmp.path).open_for(b);
    FAIL() << "a store made with another config was accepted";
  } catch (const dpdrng::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different config"), std::string::npos);
  }
  EXPECT_NO_THROW(Store(tmp.path).open_for(a));
}

TEST(StudyStore, ShardsMergeIntoWhatOneRunGives) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  TempDir whole_dir, s1, s2, s3;
  fake::FakeMeasure m;
  Store whole(whole_dir.path);
  whole.open_for(cfg);
  run_study(cfg, whole, RunOptions{}, as_fn(m));

  std::vector<fs::path> shard_dirs{s1.path, s2.path, s3.path};
  for (int k = 1; k <= 3; ++k) {
    Store s(shard_dirs[std::size_t(k - 1)]);
    s.open_for(cfg);
    RunOptions o;
    o.shard = Shard{k, 3};
    const RunSummary sum = run_study(cfg, s, o, as_fn(m));
    EXPECT_GT(sum.computed, 0u);
    EXPECT_LT(sum.computed, enumerate_cells(cfg).size());
  }
  Store merged(s1.path);
  merged.merge_from(Store(s2.path));
  merged.merge_from(Store(s3.path));
  EXPECT_EQ(merged.assemble(cfg), enumerate_cells(cfg).size());
  EXPECT_EQ(fingerprints(merged.load_all()), fingerprints(whole.load_all()));
}

TEST(StudyStore, AssembledFileIsPlainHdf5WithConfigAndOneGroupPerCell) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  TempDir tmp;
  fake::FakeMeasure m;
  Store store(tmp.path);
  store.open_for(cfg);
  run_study(cfg, store, RunOptions{}, as_fn(m));
  store.assemble(cfg);
  std::lock_guard lk(h5::lock());
  h5::Handle f = h5::open_file(store.study_file().string());
  const auto attrs = h5::read_attributes(f.id());
  EXPECT_EQ(std::get<std::string>(attrs.at("config_hash")), cfg.hash);
  EXPECT_EQ(std::get<std::string>(attrs.at("config_toml")), kConfig);
  h5::Handle cells = h5::open_group(f.id(), "cells");
  EXPECT_EQ(h5::list(cells.id()).size(), enumerate_cells(cfg).size());
  if (std::system("command -v h5dump >/dev/null 2>&1") == 0) {
    const std::string cmd = "h5dump -A '" + store.study_file().string() + "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << "h5dump cannot read study.h5";
  }
}

TEST(StudyStore, AFailingCellIsRecordedAndTheSweepGoesOn) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  TempDir tmp;
  Store store(tmp.path);
  store.open_for(cfg);
  fake::FakeMeasure m;
  const MeasureFn flaky = [&](const Cell& c, const StudyConfig& k, int t) {
    if (c.generator == "tea64") throw std::runtime_error("engine exploded");
    return m(c, k, t);
  };
  const RunSummary s = run_study(cfg, store, RunOptions{}, flaky);
  EXPECT_EQ(s.failed, 3u);  // tea64 × 3 replicas
  EXPECT_EQ(s.computed, enumerate_cells(cfg).size());
  for (const auto& r : store.load_all())
    if (r.cell.generator == "tea64") {
      EXPECT_EQ(r.status, CellStatus::failed);
      EXPECT_EQ(r.reason, "engine exploded");
    }
}

TEST(StudyStore, UnreadableCellFilesAreNamedWithTheirReason) {
  OpenStore s;
  const StudyConfig& cfg = s.cfg;
  Store& store = s.store;
  fake::FakeMeasure m;
  run_study(cfg, store, RunOptions{}, as_fn(m));
  const auto cells = enumerate_cells(cfg);
  const std::size_t n = cells.size();
  ASSERT_GE(n, 4u);
  // Cut short, garbage, another config's, and a cell stored under another cell's name.
  fs::resize_file(store.cell_path(cells[0]), fs::file_size(store.cell_path(cells[0])) / 3);
  std::ofstream(store.cell_path(cells[1]), std::ios::trunc) << "not an HDF5 file at all";
  {
    TempDir other;
    StudyConfig changed = parse_config(fake::small_config_toml("other", 3), "o.toml");
    Store o(other.path);
    o.open_for(changed);
    CellResult r;
    r.cell = cells[2];
    o.save(r);
    fs::copy_file(o.cell_path(cells[2]), store.cell_path(cells[2]), fs::copy_options::overwrite_existing);
  }
  fs::copy_file(store.cell_path(cells[4]), store.cell_path(cells[3]), fs::copy_options::overwrite_existing);

  std::string why;
  EXPECT_EQ(store.state(cells[0], &why), Store::State::unreadable);
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(store.state(cells[2], &why), Store::State::unreadable);
  EXPECT_NE(why.find("another config"), std::string::npos) << why;
  EXPECT_EQ(store.state(cells[3], &why), Store::State::unreadable);
  EXPECT_NE(why.find(cells[4].id()), std::string::npos) << why;
  EXPECT_EQ(store.state(cells[4]), Store::State::stored);
  fs::remove(store.cell_path(cells[5]));
  EXPECT_EQ(store.state(cells[5]), Store::State::missing);

  std::vector<UnreadableCell> bad;
  EXPECT_EQ(store.load_all(&bad).size(), n - 5);
  ASSERT_EQ(bad.size(), 4u);
  std::set<fs::path> named, expected;
  for (const auto& u : bad) {
    named.insert(u.file);
    EXPECT_FALSE(u.reason.empty()) << u.file;
  }
  for (std::size_t k = 0; k < 4; ++k) expected.insert(store.cell_path(cells[k]));
  EXPECT_EQ(named, expected);

  // The next run names each in a warning and computes it again.
  std::ostringstream progress;
  RunOptions o;
  o.progress = &progress;
  const RunSummary sum = run_study(cfg, store, o, as_fn(m));
  EXPECT_EQ(sum.computed, 5u);
  EXPECT_EQ(sum.unreadable.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_NE(progress.str().find("warning: " + store.cell_path(cells[k]).string() + " is unreadable"),
              std::string::npos)
        << progress.str();
  bad.clear();
  EXPECT_EQ(store.load_all(&bad).size(), n);
  EXPECT_TRUE(bad.empty());
}

// Fuzzing found HDF5's parser copying 21 GB out of a cell file with one damaged length (memcpy-param-overlap in
// H5HG_read): a file whose bytes differ from its checksum block is unreadable before HDF5 sees it.
TEST(StudyStore, AlteredCellFileNeverReachesHdf5) {
  OpenStore s;
  Store& store = s.store;
  CellResult r;
  r.cell = enumerate_cells(s.cfg)[0];
  r.reason = std::string(300, 'x');
  store.save(r);
  const fs::path p = store.cell_path(r.cell);
  std::string bytes;
  {
    std::ifstream in(p, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_EQ(bytes.compare(0, 22, "dpdrng-cell 1 fnv1a64 "), 0);
  std::string why;
  for (const std::size_t at : {std::size_t{600}, bytes.size() / 2, bytes.size() - 1}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    std::ofstream(p, std::ios::binary | std::ios::trunc) << flipped;
    EXPECT_EQ(store.state(r.cell, &why), Store::State::unreadable) << at;
    EXPECT_NE(why.find("do not match its checksum"), std::string::npos) << why;
  }
  // The same file without its block, as an earlier dpdrng wrote it: HDF5 would read it, the store does not.
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes.substr(512);
  EXPECT_EQ(store.state(r.cell, &why), Store::State::unreadable);
  EXPECT_NE(why.find("no checksum block"), std::string::npos) << why;
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_EQ(store.state(r.cell), Store::State::stored);
}

}  // namespace dpdrng_test::study_test_store
