#pragma once
// Many small tests instead of one lucky sample: the fraction of chunks (steps, pairs) that pass a test at level
// alpha, its central Clopper–Pearson interval, and whether it is consistent with the 1 − alpha a good generator
// gives (the central exact binomial test of binomial.hpp, which agrees with that interval).
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dpdrng/stats/binomial.hpp"
#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

struct PassFractionOptions {
  double alpha = 0.01;        // the level each individual test used: a good generator passes 1 − alpha of them
  double confidence = 0.99;   // of the Clopper–Pearson interval; 1 − confidence is the binomial test's level
};

struct PassFraction {
  std::size_t trials = 0;          // applicable tests
  std::size_t passed = 0;
  std::size_t not_applicable = 0;  // counted apart, never as passes or failures
  double fraction = 0.0;           // passed / trials
  double ci_low = 0.0, ci_high = 1.0;
  double confidence = 0.99;
  double expected = 0.99;          // 1 − alpha
  double binomial_p = 1.0;         // central exact test of "pass probability = 1 − alpha" (binomial.hpp)
  // pass = consistent with 1 − alpha at level 1 − confidence, i.e. the interval above contains 1 − alpha
  Verdict verdict = Verdict::not_applicable;
  std::string reason;
};

PassFraction pass_fraction(std::size_t passed, std::size_t trials, const PassFractionOptions& options = {});
PassFraction pass_fraction(std::span<const Verdict> verdicts, const PassFractionOptions& options = {});

// Runs `test` on consecutive chunks of `per` values (a trailing partial chunk is not tested; the caller sees it
// as x.size() % per) and returns the per-chunk results in order.
template <class Test>
auto per_chunk(std::span<const double> x, std::size_t per, Test&& test) {
  using Result = decltype(test(x.first(0)));
  std::vector<Result> out;
  if (per == 0) return out;
  out.reserve(x.size() / per);
  for (std::size_t at = 0; at + per <= x.size(); at += per) out.push_back(test(x.subspan(at, per)));
  return out;
}

template <class Result>
std::vector<Verdict> verdicts_of(const std::vector<Result>& results) {
  std::vector<Verdict> v;
  v.reserve(results.size());
  for (const auto& r : results) v.push_back(r.verdict);
  return v;
}

}  // namespace dpdrng::stats
