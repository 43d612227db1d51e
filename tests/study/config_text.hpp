#pragma once
// Helpers for the tests that feed study configs as text: edit a config, and catch what parsing it says.
#include <gtest/gtest.h>

#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study::config_text {

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
