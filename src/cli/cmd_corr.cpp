// dpdrng corr: correlations a histogram cannot see. On a plain stream: lag-k autocorrelations. On pair noise
// (--pairs P, every step's P values in a row, as a per-step tap writes them): neighbouring pairs at the same step
// and the same pair across steps.
#include <memory>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "stats_cli.hpp"

namespace dpdrng::cli {
namespace cmd_corr {
namespace {

struct CorrArgs {
  StatsInput in;
  std::size_t pairs = 0;
  std::string layout = "step-major";
  std::string lags = "1";
  std::string offsets = "1";
  bool offsets_given = false;
};

std::vector<std::size_t> positive_list(const std::string& text, const std::string& what) {
  return parse_list<std::size_t>(text, what, {1, std::numeric_limits<std::size_t>::max()});
}

// The lags and offsets to test, checked before the input is read.
struct CorrPlan {
  std::vector<std::size_t> lags, offsets;
};

CorrPlan plan_of(const CorrArgs& a) {
  CorrPlan plan{positive_list(a.lags, "--lags"), {}};
  if (a.pairs == 0 && a.offsets_given) throw InputError("--offsets needs --pairs: a plain stream has no pairs");
  if (a.pairs != 0) plan.offsets = positive_list(a.offsets, "--offsets");
  return plan;
}

std::vector<stats::CorrelationResult> run_checks(const CorrArgs& a, const CorrPlan& plan, const std::vector<double>& x) {
  const auto& lags = plan.lags;
  std::vector<stats::CorrelationResult> out;
  if (a.pairs == 0) {
    // A stream is one "pair" followed over time.
    const auto m = stats::NoiseMatrix::pair_major(x, 1, x.size());
    for (const std::size_t lag : lags) {
      out.push_back(stats::across_time_correlation(m, lag, a.in.alpha));
      out.back().what = "x_t vs x_t+" + std::to_string(lag);
    }
    return out;
  }
  if (x.size() % a.pairs != 0)
    throw InputError(std::to_string(x.size()) + " values do not fill whole rows of --pairs " + std::to_string(a.pairs));
  const std::size_t steps = x.size() / a.pairs;
  const auto m = a.layout == "pair-major" ? stats::NoiseMatrix::pair_major(x, a.pairs, steps)
                                          : stats::NoiseMatrix::step_major(x, a.pairs, steps);
  for (const std::size_t off : plan.offsets)
    out.push_back(stats::cross_pair_correlation(m, off, a.in.alpha));
  for (const std::size_t lag : lags) out.push_back(stats::across_time_correlation(m, lag, a.in.alpha));
  return out;
}

void print_table(const std::vector<stats::CorrelationResult>& rs, std::size_t n, std::size_t pairs) {
  std::cout << "correlation checks (Pearson r, two-sided t-test)\n  n " << n;
  if (pairs) std::cout << " = " << pairs << " pairs x " << n / pairs << " steps";
  std::cout << "\n";
  std::printf("  %-34s %12s %10s %12s %12s  %s\n", "check", "couples", "r", "t", "p", "verdict");
  for (const auto& c : rs) {
    if (c.verdict == stats::Verdict::not_applicable) {
      std::printf("  %-34s %12zu  n/a: %s\n", c.what.c_str(), c.n, c.reason.c_str());
      continue;
    }
    std::printf("  %-34s %12zu %10.5f %12.4g %12.4g  %s\n", c.what.c_str(), c.n, c.r, c.statistic, c.p_value,
                std::string(stats::to_string(c.verdict)).c_str());
  }
  std::fflush(stdout);
}

void run_corr(const CorrArgs& a) {
  const CorrPlan plan = plan_of(a);
  begin_work();
  const std::vector<double> x = a.in.read();
  const auto results = run_checks(a, plan, x);
  if (a.in.json) {
    nlohmann::json checks = nlohmann::json::array();
    for (const auto& c : results) checks.push_back(correlation_json(c));
    nlohmann::json j{{"test", "corr"}, {"n", x.size()}, {"alpha", a.in.alpha}, {"checks", checks}};
    if (a.pairs) j["pairs"] = a.pairs, j["steps"] = x.size() / a.pairs, j["layout"] = a.layout;
    std::cout << j.dump(2) << "\n";
    return;
  }
  print_table(results, x.size(), a.pairs);
}

const bool registered = register_command(32, [](CLI::App& root) {
  auto args = std::make_shared<CorrArgs>();
  CLI::App* sub = root.add_subcommand("corr", "correlation checks: lag-k on a stream, cross-pair and across-time on pair noise");
  sub->footer(
      "Without --pairs: Pearson r of x_t against x_t+k for each k in --lags.\n"
      "With --pairs P: the input is a pairs x steps matrix of noise (step-major: each step's P values together);\n"
      "zeta(p,t) vs zeta(p+o,t) for each o in --offsets (the row order decides which pairs are neighbours) and\n"
      "zeta(p,t) vs zeta(p,t+k) for each k in --lags, each pooled over the whole matrix.\n"
      "A weak hash fed neighbouring inputs can pass chi2 with a perfect histogram and still fail here.\n");
  args->in.add_to(*sub);
  add_integer(*sub, "--pairs", args->pairs, "read the input as pair noise with this many pairs per step");
  sub->add_option("--layout", args->layout, "step-major (rows = steps) or pair-major (rows = pairs)")
      ->check(CLI::IsMember({"step-major", "pair-major"}))
      ->capture_default_str();
  sub->add_option("--lags", args->lags, "comma-separated lags (steps) to test")->capture_default_str();
  sub->add_option("--offsets", args->offsets, "comma-separated pair offsets to test (with --pairs)")
      ->capture_default_str();
  sub->callback([args, sub] {
    args->offsets_given = sub->count("--offsets") > 0;
    run_corr(*args);
  });
});

}  // namespace
}  // namespace cmd_corr
}  // namespace dpdrng::cli
