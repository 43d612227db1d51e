#pragma once
// Helpers shared by the test implementations (not part of the public API).
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_erf.h>
#include <gsl/gsl_sf_gamma.h>

#include <cmath>
#include <string>

#include "dpdrng/stats/nist/result.hpp"

namespace dpdrng::stats::nist::detail {

// Upper regularized incomplete gamma Q(a, x). Like the reference's cephes_igamc, x <= 0 gives 1.
inline double igamc(double a, double x) {
  if (!(x > 0)) return 1.0;
  gsl_sf_result r;
  if (gsl_sf_gamma_inc_Q_e(a, x, &r) != 0) return x > a ? 0.0 : 1.0;  // underflow far in the tail
  return r.val;
}

inline double erfc(double x) {
  // GSL gives NaN at +inf (Runs on a constant sequence of at most 16 bits divides by pi(1 - pi) = 0); the
  // reference's cephes_erfc underflows to 0 there.
  if (std::isinf(x)) return x > 0 ? 0.0 : 2.0;
  gsl_sf_result r;
  if (gsl_sf_erfc_e(x, &r) != 0) return x > 0 ? 0.0 : 2.0;
  return r.val;
}

inline double normal_cdf(double x) { return gsl_cdf_ugaussian_P(x); }

inline TestResult make(Test t, std::size_t n) {
  TestResult r;
  r.test = t;
  r.n = n;
  return r;
}

// Marks r not applicable; its P-values (already listed with their variant names) become NaN.
inline TestResult& not_applicable(TestResult& r, std::string reason, std::size_t min_bits) {
  r.applicable = false;
  r.reason = std::move(reason);
  r.min_bits = min_bits;
  for (auto& v : r.values) v.p = NAN;
  if (r.values.empty()) r.values.push_back({"-", NAN, NAN});
  return r;
}

inline TestResult& too_short(TestResult& r, std::size_t min_bits, const std::string& why = "") {
  return not_applicable(r,
                        "needs at least " + std::to_string(min_bits) + " bits, got " + std::to_string(r.n) +
                            (why.empty() ? "" : " (" + why + ")"),
                        min_bits);
}

}  // namespace dpdrng::stats::nist::detail
