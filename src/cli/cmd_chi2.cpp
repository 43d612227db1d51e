// dpdrng chi2: the paper's uniformity test, once on the whole input or as a pass fraction over chunks.
#include <memory>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/chi2.hpp"
#include "stats_cli.hpp"

namespace dpdrng::cli {
namespace cmd_chi2 {
namespace {

struct Chi2Args {
  StatsInput in;
  ChunkOptions chunks;
  std::string bins = "sturges";
};

// The one number parser, so that the cap (the bin count is an int) is stated in the message.
int parse_bins(const std::string& s) {
  if (s == "sturges") return 0;
  return parse_number<int>(s, "--bins ('sturges' or a bin count)", {2, kIntMax});
}

nlohmann::json to_json(const stats::Chi2Result& r) {
  nlohmann::json j{{"n", r.n}, {"bins", r.bins}, {"alpha", r.alpha}, {"verdict", stats::to_string(r.verdict)}};
  if (r.verdict == stats::Verdict::not_applicable) {
    j["reason"] = r.reason;
    return j;
  }
  j["expected"] = r.expected;
  j["counts"] = r.counts;
  j["statistic"] = r.statistic;
  j["dof"] = r.dof;
  j["p"] = r.p_value;
  return j;
}

void print_single(const stats::Chi2Result& r, bool sturges) {
  std::cout << "chi2 uniformity test on [0,1)\n"
            << "  n               " << r.n << "\n"
            << "  bins            " << r.bins << (sturges ? " (Sturges: ceil(log2 n) + 1)" : "") << "\n";
  if (r.verdict == stats::Verdict::not_applicable) {
    std::cout << "  verdict         n/a: " << r.reason << "\n";
    return;
  }
  std::cout << "  expected/bin    " << fmt(r.expected) << "\n"
            << "  counts         ";
  for (const auto c : r.counts) std::cout << ' ' << c;
  std::cout << "\n  statistic A     " << fmt(r.statistic) << "\n"
            << "  dof             " << r.dof << "\n"
            << "  p-value         " << fmt(r.p_value, "%.6g") << "\n"
            << "  alpha           " << r.alpha << "\n"
            << "  verdict         " << stats::to_string(r.verdict) << "\n";
}

void run_chunked(const Chi2Args& a, const std::vector<double>& x, const stats::Chi2Options& opt) {
  const auto results = stats::per_chunk(x, a.chunks.per, [&](std::span<const double> c) {
    return stats::chi2_uniform(c, opt);
  });
  const auto pf = stats::pass_fraction(stats::verdicts_of(results), {a.in.alpha, a.chunks.confidence});
  const std::size_t unused = x.size() % a.chunks.per;
  const int bins = opt.bins > 0 ? opt.bins : stats::sturges_bins(a.chunks.per);
  if (a.in.json) {
    nlohmann::json p = nlohmann::json::array();
    for (const auto& r : results)
      p.push_back(r.verdict == stats::Verdict::not_applicable ? nlohmann::json(nullptr) : nlohmann::json(r.p_value));
    nlohmann::json j{{"test", "chi2"}, {"n", x.size()}, {"per", a.chunks.per}, {"chunks", results.size()},
                     {"unused", unused}, {"bins", bins}, {"alpha", a.in.alpha}, {"pass_fraction", pass_fraction_json(pf)},
                     {"p_values", p}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << "chi2 uniformity test on [0,1), pass fraction over chunks\n"
            << "  n               " << x.size() << "\n"
            << "  bins            " << bins << (opt.bins == 0 ? " (Sturges: ceil(log2 N) + 1)" : "") << "\n"
            << "  alpha           " << a.in.alpha << "\n";
  print_pass_fraction(pf, results.size(), a.chunks.per, unused);
}

void run_chi2(const Chi2Args& a) {
  const stats::Chi2Options opt{parse_bins(a.bins), a.in.alpha};
  begin_work();
  const std::vector<double> x = a.in.read();
  if (a.chunks.per > 0) return run_chunked(a, x, opt);
  const auto r = stats::chi2_uniform(x, opt);
  if (a.in.json) {
    auto j = to_json(r);
    j["test"] = "chi2";
    std::cout << j.dump(2) << "\n";
  } else {
    print_single(r, opt.bins == 0);
  }
}

const bool registered = register_command(30, [](CLI::App& root) {
  auto args = std::make_shared<Chi2Args>();
  CLI::App* sub = root.add_subcommand("chi2", "chi-squared test of uniformity on [0,1) (Sturges or K bins)");
  sub->footer(
      "A = sum (n_i - N)^2 / N over equal-width bins against chi2(k-1); fails when p < alpha.\n"
      "Values outside [0,1) or NaN are input errors (exit 2). Fewer than 5 expected per bin: n/a.\n"
      "Example: dpdrng gen -g tea32 -r 1 --count 32640 --format raw | dpdrng chi2 -i - -f u64\n");
  args->in.add_to(*sub);
  sub->add_option("--bins", args->bins, "sturges (ceil(log2 n) + 1, as R's nclass.Sturges) or a bin count K from 2 to 2^31 - 1")
      ->capture_default_str();
  args->chunks.add_to(*sub);
  sub->callback([args] { run_chi2(*args); });
});

}  // namespace
}  // namespace cmd_chi2
}  // namespace dpdrng::cli
