// dpdrng gof: Anderson–Darling goodness of fit of a stream against N(0,1) or U(−√3, √3).
#include <memory>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/stats/anderson_darling.hpp"
#include "stats_cli.hpp"

namespace dpdrng::cli {
namespace cmd_gof {
namespace {

struct GofArgs {
  StatsInput in;
  std::string target = "gauss";
};

void run_gof(const GofArgs& a) {
  const auto target = stats::parse_fit_target(a.target);
  begin_work();
  const auto x = a.in.read();
  const auto r = stats::anderson_darling(x, target, a.in.alpha);
  if (a.in.json) {
    nlohmann::json j{{"test", "anderson-darling"}, {"target", stats::to_string(r.target)}, {"n", r.n},
                     {"alpha", r.alpha}, {"verdict", stats::to_string(r.verdict)}};
    if (r.verdict == stats::Verdict::not_applicable) {
      j["reason"] = r.reason;
    } else {
      j["statistic"] = number(r.statistic);
      j["p"] = r.p_value;
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << "Anderson-Darling goodness of fit against "
            << (target == stats::FitTarget::gauss ? "N(0,1)" : "U(-sqrt 3, sqrt 3)") << "\n"
            << "  n               " << r.n << "\n";
  if (r.verdict == stats::Verdict::not_applicable) {
    std::cout << "  verdict         n/a: " << r.reason << "\n";
    return;
  }
  std::cout << "  statistic A^2   " << fmt(r.statistic) << "\n"
            << "  p-value         " << fmt(r.p_value, "%.6g") << "\n"
            << "  alpha           " << r.alpha << "\n"
            << "  verdict         " << stats::to_string(r.verdict) << "\n";
}

const bool registered = register_command(34, [](CLI::App& root) {
  auto args = std::make_shared<GofArgs>();
  CLI::App* sub = root.add_subcommand("gof", "Anderson-Darling test of a stream against N(0,1) or U(-sqrt 3, sqrt 3)");
  sub->footer(
      "A^2 = -n - (1/n) sum (2i-1) [ln F(x_(i)) + ln(1 - F(x_(n+1-i)))] against the fully specified target;\n"
      "p-value from Marsaglia & Marsaglia (2004), J. Stat. Software 9(2): the limiting distribution with their\n"
      "finite-n correction. A value outside a uniform target's support gives A^2 = inf, p = 0. Fewer than 5\n"
      "values: n/a. u64 words are mapped to [0,1) first, as everywhere (which fits neither target).\n"
      "Example: dpdrng gof -i zeta.f64 -f f64 --target gauss\n");
  args->in.add_to(*sub);
  sub->add_option("--target", args->target, "gauss = N(0,1), uniform = U(-sqrt 3, sqrt 3) (unit variance)")
      ->check(CLI::IsMember({"gauss", "uniform"}))
      ->capture_default_str();
  sub->callback([args] { run_gof(*args); });
});

}  // namespace
}  // namespace cmd_gof
}  // namespace dpdrng::cli
