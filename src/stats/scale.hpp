#pragma once
// Scaling before sums of squares: values near ±1e300 would overflow (x − m)² to inf and give r = NaN, or r = +1
// for an alternating sequence. A correlation does not change when a series is multiplied by a positive constant,
// and multiplying by a power of two is exact, so the statistics computed on the scaled values are the same bits
// as on the raw ones wherever the raw computation did not overflow or underflow.
#include <cmath>

namespace dpdrng::stats::detail {

// The power of two that brings max_abs into [0.5, 1); 1 for 0 (and for max_abs already in [0.5, 1)). Below
// 2^-1000 the factor stops at 2^1000 (2^1024 would overflow): such values then sit near 2^-24 or above, where
// their squares are still normal numbers.
inline double unit_scale(double max_abs) {
  if (!(max_abs > 0) || !std::isfinite(max_abs)) return 1.0;
  int e = 0;
  std::frexp(max_abs, &e);
  return std::ldexp(1.0, e < -1000 ? 1000 : -e);
}

}  // namespace dpdrng::stats::detail
