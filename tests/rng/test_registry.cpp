// The generator table and the compiled round lists agree with each other and with the dispatch.
#include <gtest/gtest.h>

#include <type_traits>

#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng_test::rng_test_registry {

using namespace dpdrng::rng;

TEST(Registry, EveryGeneratorIsFoundAsItsFamily) {
  for (const GeneratorInfo& g : generator_table()) EXPECT_EQ(family_of(g.name), g.family) << g.name;
}

TEST(Registry, CompiledRoundsLieInTheFamilysRange) {
  for (const GeneratorInfo& g : generator_table())
    for (int r : compiled_round_list(g.family)) {
      EXPECT_GE(r, g.min_rounds) << g.name;
      EXPECT_LE(r, g.max_rounds) << g.name;
    }
  EXPECT_EQ(compiled_round_list(Family::tea32).size(), compiled_round_list(Family::tea64).size());
  EXPECT_TRUE(compiled_round_list(Family::splitmix64).empty());
}

// A compiled count reaches a fixed-rounds type; any other count the run-time-rounds one, carrying the count.
TEST(Registry, CompiledCountsDispatchToFixedRoundTypes) {
  for (int r : compiled_round_list(Family::philox4x32)) {
    const int fixed = with_hash(validated({"philox4x32", r}), [](const auto& g) {
      using G = std::decay_t<decltype(g)>;
      if constexpr (std::is_same_v<G, Philox4x32<0>> || !requires { g.rounds; })
        return 0;
      else
        return g.rounds;
    });
    EXPECT_EQ(fixed, r);
  }
  const int runtime = with_hash(validated({"tea32", 7}), [](const auto& g) {
    if constexpr (std::is_same_v<std::decay_t<decltype(g)>, Tea32<0>>)
      return g.rounds;
    else
      return 0;
  });
  EXPECT_EQ(runtime, 7);
}

// The one family list drives the table and the dispatch alike: each keyed generator's name reaches the type of
// that name, and the key check and the stream kind come from the same entry.
TEST(Registry, EveryKeyedGeneratorDispatchesToItsOwnType) {
  for (const GeneratorInfo& g : generator_table()) {
    if (!g.keyed_hash) continue;
    const std::string_view kind = with_hash(validated({std::string(g.name), g.default_rounds}), [](const auto& gen) {
      return std::string_view(std::decay_t<decltype(gen)>::kName);
    });
    EXPECT_EQ(kind, g.name);
  }
  EXPECT_FALSE(find_generator("mt19937").keyed_hash);
  EXPECT_TRUE(find_generator("tea32").takes_key);
  EXPECT_FALSE(find_generator("splitmix64").counter_stream);
}

}  // namespace dpdrng_test::rng_test_registry
