// dpdrng moments: mean, variance, skewness, kurtosis and ⟨x²⟩ of a stream, with distribution-free intervals.
#include <cmath>
#include <memory>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/stats/moments.hpp"
#include "stats_cli.hpp"

namespace dpdrng::cli {
namespace cmd_moments {
namespace {

struct MomentsArgs {
  StatsInput in;
  double confidence = 0.95;
  double target = 1.0;
};

nlohmann::json interval(const stats::Interval& i) { return {number(i.low), number(i.high)}; }

void run_moments(const MomentsArgs& a) {
  begin_work();
  const auto x = a.in.read();
  const auto r = stats::moments(x, a.confidence, a.target);
  const bool ok = r.second_moment_p >= a.in.alpha;
  if (a.in.json) {
    nlohmann::json j{{"test", "moments"},
                     {"n", r.n},
                     {"confidence", r.confidence},
                     {"mean", r.mean},
                     {"mean_ci", interval(r.mean_ci)},
                     {"variance", number(r.variance)},
                     {"variance_ci", interval(r.variance_ci)},
                     {"skewness", number(r.skewness)},
                     {"kurtosis", number(r.kurtosis)},
                     {"second_moment", r.second_moment},
                     {"second_moment_ci", interval(r.second_moment_ci)},
                     {"second_moment_target", r.second_moment_target},
                     {"second_moment_p", number(r.second_moment_p)},
                     {"alpha", a.in.alpha}};
    if (!r.out_of_range.empty()) j["out_of_range"] = r.out_of_range;
    if (!r.reason.empty()) {
      j["reason"] = r.reason;
      j["verdict"] = "n/a";
    } else {
      j["verdict"] = ok ? "pass" : "fail";
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  const std::string level = fmt(100 * r.confidence, "%g") + "% CI";
  auto ci = [](const stats::Interval& i) { return "[" + fmt(i.low, "%.6g") + ", " + fmt(i.high, "%.6g") + "]"; };
  // A figure beyond the double range has no value to print: the line says so, once.
  auto with_ci = [&](double v, const stats::Interval& i) {
    return std::isfinite(v) ? fmt(v) + "  " + level + " " + ci(i) : std::string("not applicable (see below)");
  };
  std::cout << "moments\n"
            << "  n               " << r.n << "\n"
            << "  mean            " << fmt(r.mean) << "  " << level << " " << ci(r.mean_ci) << "\n"
            << "  variance        " << with_ci(r.variance, r.variance_ci) << "\n"
            << "  skewness        " << fmt(r.skewness) << "\n"
            << "  excess kurtosis " << fmt(r.kurtosis) << "\n"
            << "  <x^2>           " << with_ci(r.second_moment, r.second_moment_ci) << "\n";
  if (!r.out_of_range.empty()) std::cout << "  not applicable: " << r.out_of_range << "\n";
  if (!r.reason.empty()) {
    std::cout << "  <x^2> test      n/a: " << r.reason << "\n";
    return;
  }
  std::cout << "  <x^2> = " << fmt(r.second_moment_target, "%g") << "?     p = " << fmt(r.second_moment_p, "%.4g")
            << "  " << (ok ? "pass" : "fail") << " at alpha " << a.in.alpha << "\n";
}

const bool registered = register_command(33, [](CLI::App& root) {
  auto args = std::make_shared<MomentsArgs>();
  CLI::App* sub = root.add_subcommand("moments", "mean, variance, skewness, kurtosis and a test of <x^2> = 1");
  sub->footer(
      "Intervals are distribution-free (central limit theorem with the sample's own moments): the variance's from\n"
      "the fourth central moment, <x^2>'s from the spread of x^2. The test of <x^2> is a two-sided z-test; in DPD\n"
      "the kinetic temperature scales with <zeta^2>. Skewness g1 = m3/m2^1.5, excess kurtosis g2 = m4/m2^2 - 3\n"
      "(central moments over n). u64 words are mapped to [0,1) first, as everywhere.\n"
      "Example: dpdrng moments -i zeta.f64 -f f64 --json\n");
  args->in.add_to(*sub);
  add_real(*sub, "--confidence", args->confidence, "level of the intervals", {0, 1, true, true});
  add_real(*sub, "--second-moment", args->target, "the value <x^2> is tested against");
  sub->callback([args] { run_moments(*args); });
});

}  // namespace
}  // namespace cmd_moments
}  // namespace dpdrng::cli
