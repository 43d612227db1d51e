#include "dpdrng/stats/chi2_2d.hpp"

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/stats/chi2.hpp"

namespace dpdrng::stats {

namespace {
std::size_t cell(double u, int k, std::size_t index) {
  if (!(u >= 0.0 && u < 1.0))  // written so that NaN fails too
    throw InputError("chi2d: value " + std::to_string(index) + " is " + format_g(u) + ", outside [0,1)");
  const auto i = static_cast<std::size_t>(u * k);  // u < 1 keeps u·k below k in round-to-nearest
  return i < static_cast<std::size_t>(k) ? i : static_cast<std::size_t>(k) - 1;
}
}  // namespace

Chi2Grid chi2_2d(std::span<const double> u1, std::span<const double> u2, int bins, double alpha) {
  if (bins < 2) throw InputError("chi2d: the bin count per axis must be at least 2");
  if (bins > 4096) throw InputError("chi2d: at most 4096 bins per axis");
  if (!(alpha > 0.0 && alpha < 1.0)) throw InputError("chi2d: alpha must lie in (0,1)");
  if (u1.size() != u2.size()) throw InputError("chi2d: u1 and u2 differ in length");
  Chi2Grid r;
  r.n = u1.size();
  r.bins = bins;
  r.alpha = alpha;
  const std::size_t k = static_cast<std::size_t>(bins);
  r.counts.assign(k * k, 0);
  for (std::size_t i = 0; i < r.n; ++i) ++r.counts[cell(u1[i], bins, 2 * i) * k + cell(u2[i], bins, 2 * i + 1)];
  r.expected = static_cast<double>(r.n) / static_cast<double>(k * k);
  r.dof = static_cast<int>(k * k) - 1;
  if (r.expected < kMinExpectedPerBin) {
    r.reason = "fewer than " + std::to_string(static_cast<int>(kMinExpectedPerBin)) + " pairs expected per cell (" +
               std::to_string(r.n) + " pairs, " + std::to_string(k * k) + " cells)";
    return r;
  }
  r.statistic = chi2_statistic_equal(r.counts, r.expected);
  r.p_value = chi2_upper_tail(r.statistic, r.dof);
  r.verdict = verdict_at(r.p_value, alpha);
  return r;
}

WordPairing parse_word_pairing(std::string_view name) {
  if (name == "halves") return WordPairing::halves;
  if (name == "words") return WordPairing::words;
  throw InputError("unknown pairing '" + std::string(name) + "' (halves or words)");
}

std::string_view to_string(WordPairing p) { return p == WordPairing::halves ? "halves" : "words"; }

void pair_words(std::span<const std::uint64_t> words, WordPairing how, std::vector<double>& u1,
                std::vector<double>& u2) {
  u1.clear();
  u2.clear();
  if (how == WordPairing::halves) {
    for (const std::uint64_t w : words) {
      u1.push_back(static_cast<double>(w & 0xffffffffu) * 0x1p-32);
      u2.push_back(static_cast<double>(w >> 32) * 0x1p-32);
    }
    return;
  }
  for (std::size_t i = 0; i + 1 < words.size(); i += 2) {
    u1.push_back(rng::to_unit(words[i]));
    u2.push_back(rng::to_unit(words[i + 1]));
  }
}

}  // namespace dpdrng::stats
