#pragma once
// Internal to src/dpd: the checks the scene configs' validate() share, each throwing InputError that names the field.
#include <cmath>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"

namespace dpdrng::dpd::validate {

[[noreturn]] inline void bad(const std::string& field, const std::string& why) {
  throw InputError("invalid " + field + ": " + why);
}

// Written as !(v > 0) so that NaN fails too.
inline void positive(double v, const char* field) {
  if (!(v > 0) || !std::isfinite(v)) bad(field, exact_decimal(v) + " (must be a positive finite number)");
}

}  // namespace dpdrng::dpd::validate
