// The sweep: cell ids are unique and stable, shards partition the cells.
#include <gtest/gtest.h>

#include <set>

#include "config_text.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng_test::study_test_sweep {

using namespace dpdrng::study;

namespace {
StudyConfig two_by_two() {
  const config_text::StudyText text{
      .name = "s",
      .replicas = 3,
      .distributions = R"(["gauss", "uniform"])",
      .sweep_extra = "seedings = [\"distance\", \"pair-step\"]\n",
      .generators = {{}, {.name = "splitmix64", .rounds = "", .extra = "seedings = [\"pair-step\"]\n"}},
      .scene = "particles = 16\nsteps = 50\nequilibrate = 5\ndt = [0.02, 0.04]\n",
      .tests = "ttest_pairs = 2\nnist_generators = [\"tea32\"]\nnist_distributions = [\"gauss\"]\nnist_replicas = 1\n"};
  return parse_config(text.text(), "s.toml");
}
}  // namespace

TEST(StudySweep, EnumeratesEveryCombinationOnceWithUniqueIds) {
  const auto cells = enumerate_cells(two_by_two());
  // dt(2) × replicas(3) × dist(2) × [reference + tea32 (2 seedings × 2 rounds) + splitmix64 (1)]
  EXPECT_EQ(cells.size(), 2u * 3 * 2 * (1 + 4 + 1));
  std::set<std::string> ids;
  for (const auto& c : cells) EXPECT_TRUE(ids.insert(c.id()).second) << c.id();
  std::size_t nist = 0;
  for (const auto& c : cells) nist += c.nist;
  EXPECT_EQ(nist, 2u * 4);  // tea32 × gauss × replica 0 × both Δt
}

TEST(StudySweep, ReplicasShareTheirSeedAcrossGenerators) {
  std::map<int, std::set<std::uint64_t>> seeds;
  for (const auto& c : enumerate_cells(two_by_two())) seeds[c.replica].insert(c.seed);
  ASSERT_EQ(seeds.size(), 3u);
  for (const auto& [rep, s] : seeds) EXPECT_EQ(s.size(), 1u) << rep;
  EXPECT_NE(*seeds[0].begin(), *seeds[1].begin());
}

TEST(StudySweep, ShardsPartitionTheCells) {
  const auto cells = enumerate_cells(two_by_two());
  std::multiset<std::string> seen;
  for (int k = 1; k <= 5; ++k)
    for (const auto& c : select_shard(cells, Shard{k, 5})) seen.insert(c.id());
  EXPECT_EQ(seen.size(), cells.size());
  for (const auto& c : cells) EXPECT_EQ(seen.count(c.id()), 1u);
}

TEST(StudySweep, ShardSyntax) {
  EXPECT_EQ(parse_shard("3/16").index, 3);
  EXPECT_EQ(parse_shard("3/16").count, 16);
  for (const char* bad : {"0/4", "5/4", "1/0", "1", "a/b", "1/2x", "-1/2"})
    EXPECT_THROW(parse_shard(bad), dpdrng::InputError) << bad;
}

}  // namespace dpdrng_test::study_test_sweep
