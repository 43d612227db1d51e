#pragma once
// What every harness shares: an invariant that does not hold is a finding, reported like a crash (libFuzzer keeps
// the input as crash-*), with the reason on stderr.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace dpdrng::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what.c_str());
  std::abort();
}

inline void require(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

// A P-value the tool prints as a result.
inline void require_probability(double p, const std::string& what) {
  require(p >= 0.0 && p <= 1.0, what + " (p = " + std::to_string(p) + ")");
}

}  // namespace dpdrng::fuzz
