#pragma once
// Helpers for the tests that feed study configs as text: build one, edit it, and catch what parsing it says.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study::config_text {

// One [[sweep.generator]] entry; `rounds` as TOML ("[1, 8]"), left out when empty; `extra`: further lines.
struct GeneratorText {
  std::string name = "tea32";
  std::string rounds = "[1, 8]";
  std::string extra{};
};

// A study config as TOML text: the skeleton every study test shares, with the fields they vary. Values are
// TOML as written; the `*_extra` strings, the scene and the tests are whole lines ("key = value\n").
struct StudyText {
  std::string name = "t";
  int replicas = 2;
  std::string study_extra{};
  std::string distributions = R"(["gauss"])";
  std::string sweep_extra{};
  std::vector<GeneratorText> generators{GeneratorText{}};
  std::string scene = "particles = 32\nsteps = 100\nequilibrate = 10\n";
  std::string tests = "ttest_pairs = 4\n";  // empty: no [tests] section

  std::string text() const {
    std::string s = "[study]\nname = \"" + name + "\"\nreplicas = " + std::to_string(replicas) + "\n" + study_extra;
    s += "[sweep]\ndistributions = " + distributions + "\n" + sweep_extra;
    for (const auto& g : generators)
      s += "[[sweep.generator]]\nname = \"" + g.name + "\"\n" +
           (g.rounds.empty() ? "" : "rounds = " + g.rounds + "\n") + g.extra;
    s += "[scene]\n" + scene;
    if (!tests.empty()) s += "[tests]\n" + tests;
    return s;
  }
};

// The message of the InputError that parsing `text` (as "cfg.toml") throws, or "" if it parses.
inline std::string error_of(const std::string& text) {
  try {
    parse_config(text, "cfg.toml");
  } catch (const dpdrng::InputError& e) {
    return e.what();
  }
  return "";
}

// `base` with its first `from` replaced by `to`; a `from` that is not there fails the test.
inline std::string with(const std::string& base, const std::string& from, const std::string& to) {
  std::string s = base;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

}  // namespace dpdrng::study::config_text
