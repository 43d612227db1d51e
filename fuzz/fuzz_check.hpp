#pragma once
// What every harness shares: an invariant that does not hold is a finding, reported like a crash (libFuzzer keeps
// the input as crash-*), with the reason on stderr.
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "dpdrng/common/error.hpp"

namespace dpdrng::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what.c_str());
  std::abort();
}

inline void require(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

// A config read from the input as text under the name "fuzz.toml": the result, or nothing when it was refused
// with an InputError that names the file.
template <class Parse>
auto parse_or_refuse(const std::uint8_t* data, std::size_t size, Parse&& parse)
    -> std::optional<decltype(parse(std::string(), std::string()))> {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    return parse(text, std::string("fuzz.toml"));
  } catch (const InputError& e) {
    require(std::string(e.what()).rfind("fuzz.toml", 0) == 0, "a config error that does not name the file");
    return std::nullopt;
  }
}

// A P-value the tool prints as a result.
inline void require_probability(double p, const std::string& what) {
  require(p >= 0.0 && p <= 1.0, what + " (p = " + std::to_string(p) + ")");
}

}  // namespace dpdrng::fuzz
