// The paper's two tests as pass fractions (χ² per tapped step, lag-1 t per tapped pair) and the correlation
// checks of ζ across neighbouring pairs and consecutive steps, all on what the engine tapped.
#include <algorithm>
#include <cmath>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/pass_fraction.hpp"
#include "dpdrng/stats/ttest.hpp"
#include "dpdrng/study/measure.hpp"

namespace dpdrng::study {
namespace {

// Output word k of a call is its own stream: 64TEA's a and b are judged apart, as the paper does.
const char* stream_name(int words_per_pair, int k) {
  if (words_per_pair == 1) return "x";
  return k == 0 ? "a" : "b";
}

void record_fraction(const std::string& base, const std::vector<stats::Verdict>& verdicts, double alpha,
                     CellResult& out) {
  // The interval at the level the report judges with: 1 − α.
  stats::PassFractionOptions o;
  o.alpha = alpha;
  o.confidence = 1.0 - alpha;
  const stats::PassFraction f = stats::pass_fraction(std::span<const stats::Verdict>(verdicts), o);
  out.scalars[base + ".trials"] = double(f.trials);
  out.scalars[base + ".passed"] = double(f.passed);
  out.scalars[base + ".not_applicable"] = double(f.not_applicable);
  out.scalars[base + ".fraction"] = f.fraction;
  out.scalars[base + ".ci_low"] = f.ci_low;
  out.scalars[base + ".ci_high"] = f.ci_high;
  out.scalars[base + ".binomial_p"] = f.binomial_p;
}

// The words' uniforms into u (one buffer for every pair of a cell, not an allocation each).
const std::vector<double>& to_unit(const std::vector<std::uint64_t>& words, std::vector<double>& u) {
  u.resize(words.size());
  std::transform(words.begin(), words.end(), u.begin(), [](std::uint64_t w) { return rng::to_unit(w); });
  return u;
}

}  // namespace

bool Chi2Steps::take(const dpd::RawTap& tap) {
  const bool nist = std::binary_search(plan_.nist_steps.begin(), plan_.nist_steps.end(), tap.step);
  if (!std::binary_search(plan_.chi2_steps.begin(), plan_.chi2_steps.end(), tap.step)) return false;
  words_ = std::max(words_, tap.words_per_pair);
  for (int k = 0; k < tap.words_per_pair; ++k)
    results_[std::size_t(k)].push_back(stats::chi2_uniform_words(tap.words[std::size_t(k)], {0, tests_.alpha}));
  return !nist;
}

void Chi2Steps::record(CellResult& out) const {
  for (int k = 0; k < words_; ++k) {
    const std::vector<stats::Chi2Result>& results = results_[std::size_t(k)];
    std::vector<stats::Verdict> verdicts;
    std::vector<double> p, stat;
    for (const stats::Chi2Result& r : results) {
      verdicts.push_back(r.verdict);
      p.push_back(r.verdict == stats::Verdict::not_applicable ? NAN : r.p_value);
      stat.push_back(r.statistic);
    }
    const std::string s = stream_name(words_, k);
    if (!results.empty()) out.scalars["chi2." + s + ".bins"] = results.front().bins;
    record_fraction("chi2." + s, verdicts, tests_.alpha, out);
    out.series["chi2/" + s + "/p"] = p;
    out.series["chi2/" + s + "/statistic"] = stat;
  }
}

void record_ttest(const dpd::Taps& taps, const TestParams& tests, CellResult& out) {
  if (taps.series.empty()) return;
  const int wpp = taps.series.front().words_per_pair;
  for (int k = 0; k < wpp; ++k) {
    std::vector<stats::Verdict> verdicts;
    std::vector<double> p, r, u;
    for (const auto& ps : taps.series) {
      const stats::Lag1Result t = stats::lag1_ttest(to_unit(ps.words[std::size_t(k)], u), tests.alpha);
      verdicts.push_back(t.verdict);
      p.push_back(t.verdict == stats::Verdict::not_applicable ? NAN : t.p_value);
      r.push_back(t.r);
    }
    const std::string s = stream_name(wpp, k);
    record_fraction("ttest." + s, verdicts, tests.alpha, out);
    out.scalars["ttest." + s + ".steps"] = double(taps.series.front().words[std::size_t(k)].size());
    out.series["ttest/" + s + "/p"] = p;
    out.series["ttest/" + s + "/r"] = r;
  }
}

void record_correlations(const dpd::Taps& taps, const TestParams& tests, CellResult& out) {
  if (taps.series.size() < 2) return;
  const std::size_t steps = taps.series.front().zeta.size();
  std::vector<double> zeta;
  zeta.reserve(taps.series.size() * steps);
  for (const auto& ps : taps.series) {
    if (ps.zeta.size() != steps) return;  // an unstable run can leave ragged series; nothing sound to pool
    zeta.insert(zeta.end(), ps.zeta.begin(), ps.zeta.end());
  }
  const auto m = stats::NoiseMatrix::pair_major(zeta, taps.series.size(), steps);
  // The tapped pairs come in couples (i, j), (i, j+1): rows 2c and 2c+1.
  std::vector<std::pair<std::size_t, std::size_t>> couples;
  for (std::size_t r = 0; r + 1 < taps.series.size(); r += 2)
    if (taps.series[r].i == taps.series[r + 1].i && taps.series[r + 1].j == taps.series[r].j + 1)
      couples.emplace_back(r, r + 1);
  if (!couples.empty()) {
    const auto c = stats::cross_pair_correlation(m, couples, tests.alpha);
    out.scalars["corr.pair.r"] = c.r;
    out.scalars["corr.pair.p"] = c.p_value;
    out.scalars["corr.pair.n"] = double(c.n);
  }
  const auto t = stats::across_time_correlation(m, 1, tests.alpha);
  out.scalars["corr.time.r"] = t.r;
  out.scalars["corr.time.p"] = t.p_value;
  out.scalars["corr.time.n"] = double(t.n);
}

}  // namespace dpdrng::study
