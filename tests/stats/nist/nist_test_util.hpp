#pragma once
// Shared by the SP800-22 tests: the Appendix B data sets, built with MPFR instead of shipping data files.
#include <mpfr.h>

#include <cstdlib>
#include <string>
#include <string_view>

#include "dpdrng/stats/nist/bitseq.hpp"

namespace dpdrng::stats::nist::testing_ {

enum class Constant { e, pi, sqrt2, sqrt3 };

// The first n binary digits of the constant, integer part included, as in the reference's data/data.e,
// data.pi, data.sqrt2, data.sqrt3 (data.pi starts 11001001..., data.e 10101101...).
inline BitSequence binary_expansion(Constant c, std::size_t n = 1000000) {
  mpfr_t x;
  mpfr_init2(x, static_cast<mpfr_prec_t>(n + 64));
  switch (c) {
    case Constant::e: mpfr_set_ui(x, 1, MPFR_RNDN), mpfr_exp(x, x, MPFR_RNDN); break;
    case Constant::pi: mpfr_const_pi(x, MPFR_RNDN); break;
    case Constant::sqrt2: mpfr_sqrt_ui(x, 2, MPFR_RNDN); break;
    case Constant::sqrt3: mpfr_sqrt_ui(x, 3, MPFR_RNDN); break;
  }
  mpfr_exp_t exponent;
  char* digits = mpfr_get_str(nullptr, &exponent, 2, n + 8, x, MPFR_RNDZ);
  BitSequence s = BitSequence::from_ascii(std::string_view(digits, n));
  mpfr_free_str(digits);
  mpfr_clear(x);
  return s;
}

// Computed once per process and constant (ctest runs each test in its own process).
inline const BitSequence& cached_expansion(Constant c) {
  switch (c) {
    case Constant::e: { static const BitSequence s = binary_expansion(c); return s; }
    case Constant::pi: { static const BitSequence s = binary_expansion(c); return s; }
    case Constant::sqrt2: { static const BitSequence s = binary_expansion(c); return s; }
    case Constant::sqrt3: break;
  }
  static const BitSequence s = binary_expansion(Constant::sqrt3);
  return s;
}

// DPDRNG_TEST_SCALE=small (the sanitizer run) shrinks the expensive tests.
inline bool small_scale() {
  const char* v = std::getenv("DPDRNG_TEST_SCALE");
  return v && std::string_view(v) == "small";
}

}  // namespace dpdrng::stats::nist::testing_
