#pragma once
// The three outcomes every statistical test of this module reports: a failed test is data, and a test that
// cannot be run on the given input says so instead of returning a made-up P-value.
#include <string_view>

namespace dpdrng::stats {

enum class Verdict { pass, fail, not_applicable };

constexpr std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::pass: return "pass";
    case Verdict::fail: return "fail";
    case Verdict::not_applicable: return "n/a";
  }
  return "n/a";
}

// One convention for every test here: the null hypothesis is rejected when p < alpha (p == alpha passes).
constexpr Verdict verdict_at(double p_value, double alpha) { return p_value < alpha ? Verdict::fail : Verdict::pass; }

}  // namespace dpdrng::stats
