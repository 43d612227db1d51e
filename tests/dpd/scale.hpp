#pragma once
// Under the sanitizer preset (DPDRNG_TEST_SCALE=small) long runs shrink; tolerances derived from standard
// errors widen with them automatically, fixed systematic ones do not.
#include <cstdlib>
#include <string>

namespace dpdrng::dpd::test_scale {
inline bool small_scale() {
  const char* e = std::getenv("DPDRNG_TEST_SCALE");
  return e != nullptr && std::string(e) == "small";
}
inline long scaled(long full, long small) { return small_scale() ? small : full; }
}  // namespace dpdrng::dpd::test_scale
