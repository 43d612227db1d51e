#include "dpdrng/stats/nist/battery.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>

#include "common.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::stats::nist {

std::vector<Test> all_tests() {
  std::vector<Test> t;
  for (int i = 0; i < kTestCount; ++i) t.push_back(static_cast<Test>(i));
  return t;
}

namespace {

TestResult dispatch(Test t, const BitSequence& s, const Parameters& p, const PatternCounts* counts) {
  switch (t) {
    case Test::Frequency: return frequency(s);
    case Test::BlockFrequency: return block_frequency(s, p.block_frequency_M);
    case Test::CumulativeSums: return cumulative_sums(s);
    case Test::Runs: return runs(s);
    case Test::LongestRun: return longest_run(s);
    case Test::Rank: return rank(s);
    case Test::FFT: return fft(s);
    case Test::NonOverlappingTemplate:
      return non_overlapping_template(s, p.non_overlapping_m, p.non_overlapping_templates, p.non_overlapping_blocks);
    case Test::OverlappingTemplate: return overlapping_template(s, p.overlapping_m, p.overlapping_M, p.overlapping_K);
    case Test::Universal: return universal(s, p.universal_L, p.universal_Q);
    case Test::ApproximateEntropy: return approximate_entropy(s, p.approximate_entropy_m, counts);
    case Test::RandomExcursions: return random_excursions(s);
    case Test::RandomExcursionsVariant: return random_excursions_variant(s);
    case Test::Serial: return serial(s, p.serial_m, counts);
    case Test::LinearComplexity: return linear_complexity(s, p.linear_complexity_M);
  }
  throw std::logic_error("unknown SP800-22 test");
}

// Serial and Approximate Entropy from one table of pattern counts (PatternCounts), when both run on a sequence
// long enough for both, with valid parameters (an invalid one is the test's own error), and the larger table's
// prefix sums (2^m additions) cost no more than counting the smaller one again (n).
std::optional<PatternCounts> shared_counts(const BitSequence& s, const Parameters& p, std::span<const Test> tests) {
  const auto has = [&tests](Test t) { return std::find(tests.begin(), tests.end(), t) != tests.end(); };
  if (!has(Test::Serial) || !has(Test::ApproximateEntropy)) return std::nullopt;
  if (check_serial(p.serial_m) || check_approximate_entropy(p.approximate_entropy_m)) return std::nullopt;
  const int m = std::max(p.serial_m, p.approximate_entropy_m + 1);
  if (s.size() < static_cast<std::size_t>(m) || (std::size_t{1} << m) > s.size()) return std::nullopt;
  return pattern_counts(s, m);
}

TestResult run_test(Test t, const BitSequence& s, const Parameters& p, const PatternCounts* counts) {
  TestResult r = dispatch(t, s, p, counts);
  // Outside SP800-22's length rules the statistic does not follow its reference distribution: no P-value.
  if (r.applicable)
    if (const auto why = check_length(t, p, s.size())) detail::not_applicable(r, why->reason, why->min_bits);
  return r;
}

}  // namespace

TestResult run_test(Test t, const BitSequence& s, const Parameters& p) { return run_test(t, s, p, nullptr); }

std::vector<TestResult> run_battery(const BitSequence& s, const Parameters& p, std::span<const Test> tests) {
  const std::vector<Test> all = all_tests();
  if (tests.empty()) tests = all;
  const std::optional<PatternCounts> counts = shared_counts(s, p, tests);
  std::vector<TestResult> out;
  out.reserve(tests.size());
  for (Test t : tests) out.push_back(run_test(t, s, p, counts ? &*counts : nullptr));
  return out;
}

std::vector<std::vector<TestResult>> run_battery(std::span<const BitSequence> sequences, const Parameters& p,
                                                 std::span<const Test> tests, int threads) {
  std::vector<std::vector<TestResult>> out(sequences.size());
  std::vector<std::exception_ptr> errors(sequences.size());
  const long count = static_cast<long>(sequences.size());
  // Each sequence is independent and writes only its own slot, so the thread count cannot change a result.
  // An exception may not leave an OpenMP region: keep it and rethrow the first one afterwards.
  auto one = [&](long i) {
    try {
      out[i] = run_battery(sequences[i], p, tests);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  if (threads > 0) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (long i = 0; i < count; ++i) one(i);
  } else {
#pragma omp parallel for schedule(dynamic, 1)
    for (long i = 0; i < count; ++i) one(i);
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

namespace {

// The reference writes each P-value with "%f" and reads it back as a float before judging it.
double as_reference_reads(double p) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%f", p);
  return static_cast<double>(std::strtof(buf, nullptr));
}

int bin_of(double p) {
  const int pos = static_cast<int>(std::floor(p * 10));
  return pos >= 10 ? 9 : (pos < 0 ? 0 : pos);
}

double uniformity(const std::array<int, 10>& bins, double expected) {
  double chi2 = 0;
  for (int b : bins) chi2 += (b - expected) * (b - expected) / expected;
  return detail::igamc(9.0 / 2.0, chi2 / 2.0);
}

Assessment assess_column(std::span<const std::vector<TestResult>> per_sequence, std::size_t ti, std::size_t vi,
                         double alpha) {
  const TestResult& first = per_sequence.front()[ti];
  Assessment a;
  a.test = first.test;
  a.variant = first.values[vi].variant;
  std::vector<double> ps, ref_ps;
  for (const auto& results : per_sequence) {
    if (ti >= results.size() || vi >= results[ti].values.size()) continue;
    const double p = results[ti].values[vi].p;
    if (!results[ti].applicable || std::isnan(p)) continue;
    ps.push_back(p);
    ref_ps.push_back(as_reference_reads(p));
  }
  const int m = static_cast<int>(ps.size());
  a.sample_size = m;
  if (m == 0) return a;
  std::array<int, 10> ref_bins{};
  for (int i = 0; i < m; ++i) {
    a.passed += ps[i] >= alpha;
    a.reference_passed += ref_ps[i] >= alpha;
    ++a.bins[bin_of(ps[i])];
    ++ref_bins[bin_of(ref_ps[i])];
  }
  const ProportionRange range = proportion_range(alpha, m);
  a.proportion_low = range.low;
  a.proportion_high = range.high;
  a.proportion_ok = a.passed >= a.proportion_low * m && a.passed <= a.proportion_high * m;
  a.reference_min_pass = static_cast<int>(range.low * m);
  a.reference_max_pass = static_cast<int>(range.high * m);
  a.reference_proportion_ok =
      a.reference_passed >= a.reference_min_pass && a.reference_passed <= a.reference_max_pass;
  a.uniformity_p = uniformity(a.bins, m / 10.0);
  a.uniformity_ok = a.uniformity_p >= 0.0001;
  const int ref_expected = m / 10;
  if (ref_expected > 0) {
    a.reference_uniformity_p = uniformity(ref_bins, ref_expected);
    a.reference_uniformity_ok = a.reference_uniformity_p >= 0.0001;
  } else {
    a.reference_uniformity_ok = true;  // the reference prints "----" and does not judge
  }
  return a;
}

}  // namespace

ProportionRange proportion_range(double alpha, double m) {
  const double p_hat = 1.0 - alpha, spread = 3.0 * std::sqrt(p_hat * alpha / m);
  return {p_hat - spread, p_hat + spread};
}

std::vector<Assessment> assess(std::span<const std::vector<TestResult>> per_sequence, double alpha) {
  std::vector<Assessment> out;
  if (per_sequence.empty()) return out;
  const auto& first = per_sequence.front();
  for (std::size_t ti = 0; ti < first.size(); ++ti)
    for (std::size_t vi = 0; vi < first[ti].values.size(); ++vi)
      out.push_back(assess_column(per_sequence, ti, vi, alpha));
  return out;
}

}  // namespace dpdrng::stats::nist
