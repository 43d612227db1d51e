// The NIST SP 800-22 battery on a cell's own outputs: the raw words of the tapped steps, in pair order (two-word
// generators interleaved a, b as `dpdrng gen` writes them), cut into sequences as the reference suite would
// read the same words from a raw file.
#include <algorithm>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/report.hpp"
#include "dpdrng/study/measure.hpp"

namespace dpdrng::study {

void record_nist(const dpd::Taps& taps, const TapPlan& plan, const TestParams& tests, int threads, CellResult& out) {
  std::vector<std::uint64_t> words;
  for (const auto& t : taps.raw) {
    if (!std::binary_search(plan.nist_steps.begin(), plan.nist_steps.end(), t.step)) continue;
    const std::size_t n = t.words[0].size();
    for (std::size_t p = 0; p < n; ++p)
      for (int k = 0; k < t.words_per_pair; ++k) words.push_back(t.words[std::size_t(k)][p]);
  }
  const std::size_t per_seq = static_cast<std::size_t>(tests.nist_bits / 64);
  const std::size_t available = per_seq ? words.size() / per_seq : 0;
  const std::size_t m = std::min<std::size_t>(available, static_cast<std::size_t>(tests.nist_sequences));
  if (m < static_cast<std::size_t>(tests.nist_sequences))
    out.notes["nist"] = "only " + std::to_string(m) + " of " + std::to_string(tests.nist_sequences) +
                        " sequences: the run's tapped steps hold " + std::to_string(words.size() * 64) + " bits";
  if (m == 0) return;
  std::vector<stats::nist::BitSequence> seqs;
  seqs.reserve(m);
  for (std::size_t s = 0; s < m; ++s)
    seqs.push_back(stats::nist::BitSequence::from_words_le(std::span(words).subspan(s * per_seq, per_seq)));
  words = {};
  // The cell's share of the study's threads: more would crowd the cells running beside it.
  const auto results = stats::nist::run_battery(seqs, {}, {}, threads);
  seqs = {};
  const auto rows = stats::nist::assess(results, tests.alpha);

  std::vector<std::string> test, variant;
  std::vector<double> passed, applicable, p_uniformity, ref_passed, ref_p_uniformity, ok, ref_ok;
  h5::Matrix hist{rows.size(), 10, {}};
  std::size_t failed = 0, failed_exact = 0;
  for (const auto& r : rows) {
    test.emplace_back(stats::nist::test_name(r.test));
    variant.push_back(r.variant);
    passed.push_back(r.passed);
    ref_passed.push_back(r.reference_passed);
    applicable.push_back(r.sample_size);
    p_uniformity.push_back(r.uniformity_p);
    ref_p_uniformity.push_back(r.reference_uniformity_p);
    ok.push_back(r.ok());
    ref_ok.push_back(r.reference_ok());
    for (int b : r.bins) hist.data.push_back(b);
    failed += r.sample_size > 0 && !r.reference_ok();
    failed_exact += r.sample_size > 0 && !r.ok();
  }
  out.strings["nist/test"] = test;
  out.strings["nist/variant"] = variant;
  out.series["nist/passed"] = ref_passed;  // the reference's count is what its report prints
  out.series["nist/passed_exact"] = passed;
  out.series["nist/applicable"] = applicable;
  out.series["nist/p_uniformity"] = ref_p_uniformity;
  out.series["nist/p_uniformity_exact"] = p_uniformity;
  out.series["nist/ok"] = ref_ok;
  out.series["nist/ok_exact"] = ok;
  out.matrices["nist/histogram"] = std::move(hist);
  const std::string title =
      out.cell.label() + " " + std::string(rng::to_string(out.cell.distribution)) + " (" + out.cell.id() + ")";
  out.strings["nist/final_analysis_report"] = {stats::nist::final_analysis_report(rows, title, tests.alpha)};
  out.scalars["nist.sequences"] = double(m);
  out.scalars["nist.bits"] = double(tests.nist_bits);
  out.scalars["nist.columns"] = double(rows.size());
  out.scalars["nist.failed_columns"] = double(failed);
  out.scalars["nist.failed_columns_exact"] = double(failed_exact);
}

}  // namespace dpdrng::study
