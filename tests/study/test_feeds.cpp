// The feed as a study factor: [sweep] feeds multiplies the Gaussian cells (not the uniform ones), a halves cell
// keeps the id it has in a study without the factor, a config without feeds keeps its hash, a stored cell without
// a feed reads as halves, and the analysis pairs each feed with its own reference and pools ζ over replicas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <unistd.h>

#include "config_text.hpp"
#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/h5.hpp"
#include "dpdrng/study/report.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng_test::study_test_feeds {

using namespace dpdrng::study;
namespace rng = dpdrng::rng;
using config_text::error_of;
using config_text::with;

namespace {

const std::string kConfig = config_text::StudyText{.name = "f",
                                                   .distributions = R"(["gauss", "uniform"])",
                                                   .tests = "ttest_pairs = 4\nnist_generators = [\"tea32\"]\n"}
                                .text();

const std::string kFeeds = with(kConfig, "[[sweep.generator]]", "feeds = [\"halves\", \"blocks\", \"inverse\"]\n[[sweep.generator]]");

TEST(StudyFeeds, DefaultIsHalvesAndKeepsTheHashAndIds) {
  const StudyConfig c = parse_config(kConfig, "cfg.toml");
  EXPECT_EQ(c.feeds, std::vector<rng::Feed>{rng::Feed::halves});
  const StudyConfig explicit_halves = parse_config(with(kConfig, "[[sweep.generator]]",
                                                        "feeds = [\"halves\"]\n[[sweep.generator]]"), "cfg.toml");
  EXPECT_EQ(c.hash, explicit_halves.hash);
  const auto cells = enumerate_cells(c);
  EXPECT_EQ(cells.size(), 2u * (3 + 3));
  EXPECT_EQ(cells[0].id(), "mt19937-gauss-dt0.04-rep00");
  EXPECT_EQ(cells[1].id(), "tea32-r01-gauss-distance-dt0.04-rep00");
  for (const auto& cell : cells) EXPECT_EQ(cell.feed, rng::Feed::halves);
}

TEST(StudyFeeds, FeedsMultiplyGaussianCellsOnly) {
  const StudyConfig c = parse_config(kFeeds, "cfg.toml");
  EXPECT_NE(c.hash, parse_config(kConfig, "cfg.toml").hash);
  const auto cells = enumerate_cells(c);
  EXPECT_EQ(cells.size(), 2u * (3 * 3 + 3));
  std::set<std::string> ids;
  for (const auto& cell : cells) {
    ids.insert(cell.id());
    if (cell.distribution == rng::Distribution::uniform) {
      EXPECT_EQ(cell.feed, rng::Feed::halves);
    }
    // NIST reads the first block: only the first feed's cells run it.
    if (cell.feed != rng::Feed::halves) {
      EXPECT_FALSE(cell.nist) << cell.id();
    }
  }
  EXPECT_EQ(ids.size(), cells.size());
  EXPECT_TRUE(ids.count("tea32-r01-gauss-blocks-distance-dt0.04-rep01"));
  EXPECT_TRUE(ids.count("mt19937-gauss-inverse-dt0.04-rep00"));
  EXPECT_TRUE(ids.count("tea32-r08-uniform-distance-dt0.04-rep00"));
}

// A cell record without a cell.feed attribute reads as halves, with the id of a halves cell.
TEST(StudyFeeds, StoredCellWithoutAFeedReadsAsHalves) {
  const StudyConfig c = parse_config(kFeeds, "cfg.toml");
  CellResult r;
  r.cell = enumerate_cells(c)[1];
  ASSERT_EQ(r.cell.feed, rng::Feed::halves);
  std::string tmpl = (std::filesystem::temp_directory_path() / "dpdrng-feed-XXXXXX").string();
  const std::filesystem::path dir = mkdtemp(tmpl.data());
  {
    std::lock_guard lock(h5::lock());
    h5::Handle f = h5::create_file((dir / "cell.h5").string());
    h5::Handle g = h5::create_group(f.id(), "cell");
    write_cell(g.id(), r);
    ASSERT_TRUE(h5::read_attributes(g.id()).count("cell.feed"));
    ASSERT_GE(H5Adelete(g.id(), "cell.feed"), 0);
    const CellResult back = read_cell(g.id());
    EXPECT_EQ(back.cell.feed, rng::Feed::halves);
    EXPECT_EQ(back.cell.id(), r.cell.id());
  }
  std::filesystem::remove_all(dir);
}

TEST(StudyFeeds, BadFeedsNameTheKey) {
  EXPECT_NE(error_of(with(kFeeds, "\"inverse\"]", "\"pairs\"]")).find("feeds"), std::string::npos);
  EXPECT_NE(error_of(with(kFeeds, "\"inverse\"]", "\"blocks\"]")).find("feeds"), std::string::npos);
  EXPECT_NE(error_of(with(kFeeds, "[\"halves\", \"blocks\", \"inverse\"]", "[]")).find("feeds"), std::string::npos);
}

// Cells with ζ power sums: each feed compares with MT of its own feed, and ⟨ζ²⟩ pools the replicas' sums.
TEST(StudyFeeds, AnalysisPairsFeedsWithTheirReferenceAndPoolsZeta) {
  const StudyConfig c = parse_config(with(kFeeds, "distributions = [\"gauss\", \"uniform\"]",
                                          "distributions = [\"gauss\"]"), "cfg.toml");
  std::vector<CellResult> cells;
  for (const auto& cell : enumerate_cells(c)) {
    CellResult r;
    r.cell = cell;
    // A variance of 0.965 for 32TEA(1) under halves, 1 otherwise; 10⁶ draws a cell.
    const double m2 = cell.generator == "tea32" && cell.rounds == 1 && cell.feed == rng::Feed::halves ? 0.965 : 1.0;
    const double n = 1e6;
    r.scalars["zeta_n"] = n, r.scalars["zeta_s1"] = 0, r.scalars["zeta_s2"] = m2 * n;
    r.scalars["zeta_s3"] = 0, r.scalars["zeta_s4"] = 3 * m2 * m2 * n;
    r.scalars["temperature_mean"] = 1.03 * m2 + 0.001 * cell.replica;
    r.scalars["temperature_sem"] = 0.001;
    r.scalars["temperature_sem_dof"] = 100;
    cells.push_back(r);
  }
  const Analysis a = analyse(c, cells);
  int checked = 0;
  for (const auto& v : a.variants) {
    const VariantReport* ref = a.reference_for(v.key);
    ASSERT_NE(ref, nullptr);
    EXPECT_EQ(ref->key.feed, v.key.feed);
    EXPECT_EQ(v.zeta.n, 2000000u);
    if (v.key.generator == "tea32" && v.key.rounds == 1 && v.key.feed == rng::Feed::halves) {
      EXPECT_NEAR(v.zeta.second_moment, 0.965, 1e-12);
      EXPECT_NEAR(v.zeta_predicted_shift, -0.035, 1e-12);
      EXPECT_TRUE(v.zeta_decision.differs);
      ++checked;
    } else if (!v.key.reference) {
      EXPECT_NEAR(v.zeta_predicted_shift, 0.0, 1e-12);
      EXPECT_FALSE(v.zeta_decision.differs);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 6);
  const std::string md = zeta_markdown(a);
  EXPECT_NE(md.find("gauss-blocks"), std::string::npos);
  EXPECT_NE(md.find("**0.9650**"), std::string::npos) << md;
  EXPECT_NE(md.find("-3.50 %"), std::string::npos) << md;
  const std::string flags = flags_markdown(a);
  EXPECT_NE(flags.find("**flags** (0.9650)"), std::string::npos) << flags;
}

}  // namespace

}  // namespace dpdrng_test::study_test_feeds
