// dpdrng chi2d: χ² on a k × k grid of (u1, u2) pairs, the two uniforms Box–Muller combines.
#include <memory>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/chi2_2d.hpp"
#include "stats_cli.hpp"

namespace dpdrng::cli {
namespace cmd_chi2d {
namespace {

struct Chi2dArgs {
  StatsInput in;
  int bins = 16;
  std::string pairs;
};

void pairs_of(const Chi2dArgs& a, std::vector<double>& u1, std::vector<double>& u2) {
  const bool words = stats::parse_input_format(a.in.format) == stats::InputFormat::u64;
  if (!words && a.pairs == "halves") throw InputError("--pairs halves needs --format u64 (the 32-bit halves of words)");
  const auto how = stats::parse_word_pairing(a.pairs.empty() ? "halves" : a.pairs);
  begin_work();
  if (words) {
    stats::pair_words(stats::read_words(a.in.input), how, u1, u2);
    return;
  }
  const auto x = a.in.read();
  for (std::size_t i = 0; i + 1 < x.size(); i += 2) {
    u1.push_back(x[i]);
    u2.push_back(x[i + 1]);
  }
}

void run_chi2d(const Chi2dArgs& a) {
  std::vector<double> u1, u2;
  pairs_of(a, u1, u2);
  const auto r = stats::chi2_2d(u1, u2, a.bins, a.in.alpha);
  const std::string pairing = stats::parse_input_format(a.in.format) == stats::InputFormat::u64
                                  ? (a.pairs.empty() ? "halves" : a.pairs)
                                  : "consecutive values";
  if (a.in.json) {
    nlohmann::json j{{"test", "chi2d"}, {"pairs", pairing}, {"n", r.n},          {"bins", r.bins},
                     {"alpha", r.alpha}, {"verdict", stats::to_string(r.verdict)}};
    if (r.verdict == stats::Verdict::not_applicable) {
      j["reason"] = r.reason;
    } else {
      j["expected"] = r.expected;
      j["statistic"] = r.statistic;
      j["dof"] = r.dof;
      j["p"] = r.p_value;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << "2-D chi2 uniformity test on [0,1)^2\n"
            << "  pairs           " << r.n << " (" << pairing << ")\n"
            << "  grid            " << r.bins << " x " << r.bins << "\n";
  if (r.verdict == stats::Verdict::not_applicable) {
    std::cout << "  verdict         n/a: " << r.reason << "\n";
    return;
  }
  std::cout << "  expected/cell   " << fmt(r.expected) << "\n"
            << "  statistic       " << fmt(r.statistic) << "\n"
            << "  dof             " << r.dof << "\n"
            << "  p-value         " << fmt(r.p_value, "%.6g") << "\n"
            << "  alpha           " << r.alpha << "\n"
            << "  verdict         " << stats::to_string(r.verdict) << "\n";
}

const bool registered = register_command(30, [](CLI::App& root) {
  auto args = std::make_shared<Chi2dArgs>();
  CLI::App* sub = root.add_subcommand("chi2d", "2-D chi-squared test on (u1, u2) pairs, k x k cells");
  sub->footer(
      "Pairs from u64 words: --pairs halves (default) takes u1 = low 32 bits, u2 = high 32 bits of each word, as\n"
      "Box-Muller takes a one-word block (for 32TEA the output words x0', x1'); --pairs words takes consecutive\n"
      "words (53 bits each; an odd last word is left out). f64/text: consecutive values, which must lie in [0,1).\n"
      "A = sum (n_ij - N)^2 / N against chi2(k^2 - 1); fewer than 5 expected per cell: n/a.\n"
      "Example: dpdrng gen -g tea32 -r 1 --count 1000000 --format raw | dpdrng chi2d -i - -f u64 --bins 16\n");
  args->in.add_to(*sub);
  add_integer(*sub, "--bins", args->bins, "cells per axis, k", {2, 4096});
  sub->add_option("--pairs", args->pairs, "halves (of each word) or words (consecutive), for u64 input")
      ->check(CLI::IsMember({"halves", "words"}));
  sub->callback([args] { run_chi2d(*args); });
});

}  // namespace
}  // namespace cmd_chi2d
}  // namespace dpdrng::cli
