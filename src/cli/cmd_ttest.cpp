// dpdrng ttest: the paper's lag-1 serial-correlation t-test, once on the whole input or as a pass fraction.
#include <memory>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/stats/ttest.hpp"
#include "stats_cli.hpp"

namespace dpdrng::cli {
namespace cmd_ttest {
namespace {

struct TtestArgs {
  StatsInput in;
  ChunkOptions chunks;
};

nlohmann::json to_json(const stats::Lag1Result& r) {
  nlohmann::json j{{"n", r.n}, {"alpha", r.alpha}, {"verdict", stats::to_string(r.verdict)}};
  if (r.verdict == stats::Verdict::not_applicable) {
    j["reason"] = r.reason;
    return j;
  }
  j["r"] = r.r;
  j["statistic"] = number(r.statistic);
  j["dof"] = r.dof;
  j["p"] = r.p_value;
  return j;
}

void print_single(const stats::Lag1Result& r) {
  std::cout << "lag-1 correlation t-test\n"
            << "  n               " << r.n << "\n";
  if (r.verdict == stats::Verdict::not_applicable) {
    std::cout << "  verdict         n/a: " << r.reason << "\n";
    return;
  }
  std::cout << "  r (lag 1)       " << fmt(r.r) << "\n"
            << "  statistic B     " << fmt(r.statistic) << "\n"
            << "  dof             " << r.dof << "\n"
            << "  p-value         " << fmt(r.p_value) << " (two-sided)\n"
            << "  alpha           " << r.alpha << "\n"
            << "  verdict         " << stats::to_string(r.verdict) << "\n";
}

void run_chunked(const TtestArgs& a, const std::vector<double>& x) {
  const auto results = stats::per_chunk(x, a.chunks.per, [&](std::span<const double> c) {
    return stats::lag1_ttest(c, a.in.alpha);
  });
  const auto pf = stats::pass_fraction(stats::verdicts_of(results), {a.in.alpha, a.chunks.confidence});
  const std::size_t unused = x.size() % a.chunks.per;
  if (a.in.json) {
    nlohmann::json p = nlohmann::json::array();
    for (const auto& r : results)
      p.push_back(r.verdict == stats::Verdict::not_applicable ? nlohmann::json(nullptr) : nlohmann::json(r.p_value));
    nlohmann::json j{{"test", "ttest"}, {"n", x.size()}, {"per", a.chunks.per}, {"chunks", results.size()},
                     {"unused", unused}, {"alpha", a.in.alpha}, {"pass_fraction", pass_fraction_json(pf)}, {"p_values", p}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << "lag-1 correlation t-test, pass fraction over chunks\n"
            << "  n               " << x.size() << "\n"
            << "  alpha           " << a.in.alpha << "\n";
  print_pass_fraction(pf, results.size(), a.chunks.per, unused);
}

void run_ttest(const TtestArgs& a) {
  begin_work();
  const std::vector<double> x = a.in.read();
  if (a.chunks.per > 0) return run_chunked(a, x);
  const auto r = stats::lag1_ttest(x, a.in.alpha);
  if (a.in.json) {
    auto j = to_json(r);
    j["test"] = "ttest";
    std::cout << j.dump(2) << "\n";
  } else {
    print_single(r);
  }
}

const bool registered = register_command(31, [](CLI::App& root) {
  auto args = std::make_shared<TtestArgs>();
  CLI::App* sub = root.add_subcommand("ttest", "lag-1 serial-correlation t-test");
  sub->footer(
      "r = sum (x_t - m)(x_t+1 - m) / sum (x_t - m)^2 (the standard sample autocorrelation, as R's acf);\n"
      "B = r sqrt(n-2) / sqrt(1-r^2) against Student's t(n-2), two-sided; fails when p < alpha.\n"
      "A constant series has no r: n/a. Values need not lie in [0,1).\n");
  args->in.add_to(*sub);
  args->chunks.add_to(*sub);
  sub->callback([args] { run_ttest(*args); });
});

}  // namespace
}  // namespace cmd_ttest
}  // namespace dpdrng::cli
