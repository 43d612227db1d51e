#pragma once
// An MPFR number at 160 bits that frees itself: the slow exact reference of the rng kernels' tests.
#include <mpfr.h>

class Mp {
 public:
  Mp() { mpfr_init2(v, 160); }
  ~Mp() { mpfr_clear(v); }
  Mp(const Mp&) = delete;
  Mp& operator=(const Mp&) = delete;
  mpfr_t v;
};
