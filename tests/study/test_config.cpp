// Study configs: every shipped config parses, and every kind of mistake names its key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/sweep.hpp"
#include "config_text.hpp"

namespace dpdrng_test::study_test_config {

using namespace dpdrng::study;
namespace rng = dpdrng::rng;

namespace {

const std::string kMinimal = config_text::StudyText{}.text();

using config_text::error_of;
using config_text::with;

}  // namespace

TEST(StudyConfig, MinimalParsesWithDefaults) {
  const StudyConfig c = parse_config(kMinimal, "cfg.toml");
  EXPECT_EQ(c.name, "t");
  EXPECT_EQ(c.reference, "mt19937");
  ASSERT_EQ(c.generators.size(), 1u);
  EXPECT_EQ(c.generators[0].rounds, (std::vector<int>{1, 8}));
  EXPECT_DOUBLE_EQ(c.scene.density, 3.0);
  EXPECT_EQ(c.scene.dt, std::vector<double>{0.04});
  EXPECT_EQ(c.hash.size(), 16u);
}

TEST(StudyConfig, HashIgnoresCommentsAndLayoutButNotValues) {
  const StudyConfig a = parse_config(kMinimal, "a");
  const StudyConfig b = parse_config("# a comment\n" + kMinimal + "\n\n", "b");
  const StudyConfig c = parse_config(with(kMinimal, "replicas = 2", "replicas = 3"), "c");
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_NE(a.hash, c.hash);
}

TEST(StudyConfig, ErrorsNameTheKey) {
  EXPECT_NE(error_of(with(kMinimal, "replicas = 2", "replicas = 2\nreplica = 3")).find("replica: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "steps = 100", "steps = 100\ndensty = 3.0")).find("scene.densty: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "particles = 32", "particles = 32\ndensity = nan")).find("scene.density"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "particles = 32", "particles = 32\ndt = -0.01")).find("scene.dt: out of range"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "particles = 32", "particles = 32\ndt = inf")).find("scene.dt: must be finite"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "rounds = [1, 8]", "rounds = [0]")).find("sweep.generator[0].rounds"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "name = \"tea32\"", "name = \"tea33\"")).find("sweep.generator[0].name"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "name = \"tea32\"", "name = \"mt19937\"")).find("not a pair-keyed hash"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "[\"gauss\"]", "[\"gauss\", \"gauss\"]")).find("sweep.distributions"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "[\"gauss\"]", "[\"normal\"]")).find("sweep.distributions"), std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "equilibrate = 10", "equilibrate = 100")).find("scene.equilibrate"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "ttest_pairs = 4", "ttest_pairs = 4\nnist_generators = [\"philox4x32\"]"))
                .find("tests.nist_generators"),
            std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "ttest_pairs = 4", "nist_bits = 100")).find("tests.nist_bits"), std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "name = \"t\"", "name = \"../x\"")).find("study.name"), std::string::npos);
  EXPECT_NE(error_of(with(kMinimal, "replicas = 2", "replicas = \"2\"")).find("study.replicas: must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of("[study\nname = 1").find("cfg.toml:1"), std::string::npos);
  // The reference never has fewer replicas than the variants it judges.
  EXPECT_NE(error_of(with(kMinimal, "replicas = 2", "replicas = 2\nreference_replicas = 1"))
                .find("study.reference_replicas: out of range"),
            std::string::npos);
}

// reference_replicas: absent, or equal to replicas, leaves the canonical form (and the hash) as it was; more
// reference replicas are part of it.
TEST(StudyConfig, ReferenceReplicasKeepOldHashes) {
  const auto base = parse_config(kMinimal, "c.toml");
  EXPECT_EQ(base.reference_replica_count(), base.replicas);
  EXPECT_EQ(parse_config(with(kMinimal, "replicas = 2", "replicas = 2\nreference_replicas = 2"), "c.toml").hash,
            base.hash);
  const auto more = parse_config(with(kMinimal, "replicas = 2", "replicas = 2\nreference_replicas = 5"), "c.toml");
  EXPECT_NE(more.hash, base.hash);
  EXPECT_EQ(more.reference_replica_count(), 5);
}

// The error-control rule: study-wide by default; "variant" on request; anything else names the key. The
// default adds nothing to the canonical form, so a config without the key keeps its result directory's hash.
TEST(StudyConfig, ErrorControlIsReadStrictly) {
  const StudyConfig def = parse_config(kMinimal, "cfg.toml");
  EXPECT_EQ(def.tests.error_control, ErrorControl::study);
  EXPECT_FALSE(def.canonical()["tests"].contains("error_control"));
  const StudyConfig study = parse_config(kMinimal + "error_control = \"study\"\n", "cfg.toml");
  EXPECT_EQ(study.hash, def.hash);
  const StudyConfig variant = parse_config(kMinimal + "error_control = \"variant\"\n", "cfg.toml");
  EXPECT_EQ(variant.tests.error_control, ErrorControl::variant);
  EXPECT_NE(variant.hash, def.hash);
  const std::string e = error_of(kMinimal + "error_control = \"none\"\n");
  EXPECT_NE(e.find("tests.error_control"), std::string::npos) << e;
  EXPECT_NE(e.find("\"variant\""), std::string::npos) << e;
  EXPECT_NE(error_of(kMinimal + "error_control = 1\n").find("tests.error_control: must be a string"),
            std::string::npos);
}

TEST(StudyConfig, ShippedConfigsParse) {
  for (const char* name : {"okada2021", "ci", "peers"}) {
    const std::string path = std::string(DPDRNG_SOURCE_DIR) + "/study/" + name + ".toml";
    StudyConfig c;
    ASSERT_NO_THROW(c = load_config(path)) << path;
    EXPECT_EQ(c.name, name);
    EXPECT_FALSE(enumerate_cells(c).empty());
  }
}

// `./study/reproduce.sh study/NAME.toml` writes into results/NAME and refuses a directory that holds another
// config's results: each shipped config must hash as the committed results it produced, or the main command
// exits 2 on a fresh clone.
TEST(StudyConfig, ShippedConfigsMatchTheirCommittedResults) {
  for (const char* name : {"okada2021", "peers", "stability", "bilayer"}) {
    const std::string dir = std::string(DPDRNG_SOURCE_DIR) + "/results/" + name;
    std::ifstream in(dir + "/config.hash");
    ASSERT_TRUE(in) << dir << "/config.hash";
    std::string stored;
    in >> stored;
    EXPECT_EQ(load_config(std::string(DPDRNG_SOURCE_DIR) + "/study/" + name + ".toml").hash, stored) << name;
  }
}

TEST(StudyConfig, PaperStudyCoversBothTeaFamiliesAtAllRounds) {
  const StudyConfig c = load_config(std::string(DPDRNG_SOURCE_DIR) + "/study/okada2021.toml");
  const std::vector<int> rounds{1, 2, 3, 4, 5, 6, 8, 16, 32};
  ASSERT_EQ(c.generators.size(), 2u);
  for (const auto& g : c.generators) EXPECT_EQ(g.rounds, rounds) << g.name;
  EXPECT_EQ(c.distributions, (std::vector<rng::Distribution>{rng::Distribution::gauss, rng::Distribution::uniform}));
  EXPECT_EQ(c.feeds, (std::vector<rng::Feed>{rng::Feed::halves, rng::Feed::blocks, rng::Feed::inverse}));
  EXPECT_EQ(c.replicas, 4);
  EXPECT_EQ(c.reference_replica_count(), 16);
  EXPECT_EQ(c.scene.steps, 10000);
  EXPECT_EQ(c.scene.equilibrate, 500);
  EXPECT_EQ(c.tests.margins.at("temperature"), 0.01);
  EXPECT_EQ(c.tests.nist_sequences, 1000);
  EXPECT_EQ(c.tests.nist_bits, 1 << 20);
  std::size_t nist_tea32 = 0;
  for (const auto& cell : enumerate_cells(c)) nist_tea32 += cell.nist && cell.generator == "tea32";
  EXPECT_EQ(nist_tea32, rounds.size());  // every 32TEA variant, once
}

}  // namespace dpdrng_test::study_test_config

namespace dpdrng_test::study_test_config {

// [tests.margins]: a config without the table takes the documented defaults; a key sets its observable's margin
// and leaves the hash alone (margins judge cells, they do not make them); an unknown key or a margin that is not
// positive is an error naming the key.
TEST(StudyConfig, MarginsDefaultAndNameTheirKey) {
  const StudyConfig plain = parse_config(kMinimal, "cfg.toml");
  EXPECT_EQ(plain.tests.margins.at("temperature"), 0.005);
  EXPECT_EQ(plain.tests.margins.at("pressure"), 0.005);
  EXPECT_EQ(plain.tests.margins.at("diffusion"), 0.03);
  EXPECT_EQ(plain.tests.margins.size(), 10u);
  EXPECT_EQ(plain.tests.margins.at("temperature_components"), 0.01);
  EXPECT_EQ(plain.tests.margins.at("pressure_components"), 0.005);
  const StudyConfig set = parse_config(kMinimal + "[tests.margins]\ntemperature = 0.01\n", "cfg.toml");
  EXPECT_EQ(set.tests.margins.at("temperature"), 0.01);
  EXPECT_EQ(set.tests.margins.at("pressure"), 0.005);
  EXPECT_EQ(set.hash, plain.hash);
  EXPECT_NE(error_of(kMinimal + "[tests.margins]\ntemperatur = 0.01\n").find("tests.margins.temperatur: unknown key"),
            std::string::npos);
  for (const char* bad : {"0", "-0.01", "nan", "\"x\""})
    EXPECT_NE(error_of(kMinimal + "[tests.margins]\npressure = " + bad + "\n").find("tests.margins.pressure"),
              std::string::npos)
        << bad;
}

}  // namespace dpdrng_test::study_test_config
