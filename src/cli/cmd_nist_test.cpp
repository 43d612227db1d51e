// dpdrng nist <test>: one SP800-22 test with its own parameters, e.g. `dpdrng nist runs -i data.e`.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cmd_nist_common.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/nist/report.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::cli {
namespace cmd_nist_test {
namespace {

namespace nist = stats::nist;

struct TestArgs {
  NistInput in;
  nist::Test test{};
  nist::Parameters p;
  std::vector<std::string> templates;
};

std::uint32_t parse_template(const std::string& bits, int m) {
  if (static_cast<int>(bits.size()) != m || bits.find_first_not_of("01") != std::string::npos)
    throw InputError("--template '" + bits + "' must be " + std::to_string(m) + " characters of 0/1");
  std::uint32_t v = 0;
  for (char c : bits) v = (v << 1) | static_cast<std::uint32_t>(c == '1');
  return v;
}

// The per-test flag that sets each Parameters field.
std::string flag_of(const std::string& field) {
  if (field == "non_overlapping_blocks") return "--blocks";
  if (field == "non_overlapping_templates") return "--template";
  if (field == "overlapping_K") return "--K";
  if (field == "universal_Q") return "--init-blocks";
  if (field == "block_frequency_M" || field == "overlapping_M" || field == "universal_L" ||
      field == "linear_complexity_M")
    return "--block-length";
  return "--template-length";
}

void print_human(const std::vector<std::vector<nist::TestResult>>& results) {
  for (std::size_t i = 0; i < results.size(); ++i) {
    const nist::TestResult& r = results[i].front();
    std::printf("%s, stream %zu, n = %zu\n", std::string(nist::test_name(r.test)).c_str(), i + 1, r.n);
    for (const auto& [k, v] : r.parameters) std::printf("  %-10s = %.10g\n", k.c_str(), v);
    if (!r.applicable) {
      std::printf("  not applicable: %s\n", r.reason.c_str());
      continue;
    }
    for (const auto& v : r.values)
      std::printf("  %-12s statistic = %-14.8g p = %f\n", v.variant.c_str(), v.statistic, v.p);
  }
}

void run(TestArgs& a) {
  a.in.check();
  if (a.p.non_overlapping_m >= 2 && a.p.non_overlapping_m <= 21) {
    a.p.non_overlapping_templates.clear();
    for (const auto& b : a.templates) a.p.non_overlapping_templates.push_back(parse_template(b, a.p.non_overlapping_m));
  }
  check_nist_parameters({a.test}, a.p, flag_of);
  begin_work();
  const auto seqs = a.in.load();
  std::vector<std::vector<nist::TestResult>> results(seqs.size());
  const long count = static_cast<long>(seqs.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long i = 0; i < count; ++i) results[i] = {nist::run_test(a.test, seqs[i], a.p)};
  if (a.in.tsv || a.in.json || seqs.size() > 1) {
    if (!a.in.tsv && !a.in.json) print_human(results);
    const auto& p = a.p;
    print_nist(a.in, results,
               {{"block_frequency_M", p.block_frequency_M}, {"non_overlapping_m", p.non_overlapping_m},
                {"non_overlapping_blocks", p.non_overlapping_blocks}, {"templates", a.templates},
                {"overlapping_m", p.overlapping_m}, {"overlapping_M", p.overlapping_M},
                {"overlapping_K", p.overlapping_K}, {"universal_L", p.universal_L}, {"universal_Q", p.universal_Q},
                {"approximate_entropy_m", p.approximate_entropy_m}, {"serial_m", p.serial_m},
                {"linear_complexity_M", p.linear_complexity_M}});
    return;
  }
  print_human(results);
}

void add_test(CLI::App& nist_app, nist::Test t) {
  auto a = std::make_shared<TestArgs>();
  a->test = t;
  CLI::App* sub = nist_app.add_subcommand(std::string(nist::test_cli_name(t)),
                                          "SP800-22 " + std::string(nist::test_name(t)) + " test");
  sub->footer("One test with its own parameters; several streams also get the second-level assessment.");
  a->in.add_to(*sub);
  using T = nist::Test;
  auto& p = a->p;
  switch (t) {
    case T::BlockFrequency:
      add_integer(*sub, "--block-length", p.block_frequency_M, "M, bits per block");
      break;
    case T::NonOverlappingTemplate:
      add_integer(*sub, "--template-length", p.non_overlapping_m, "m");
      sub->add_option("--template", a->templates, "template bits, e.g. 000000001 (default: all aperiodic ones)");
      add_integer(*sub, "--blocks", p.non_overlapping_blocks, "N, number of blocks");
      break;
    case T::OverlappingTemplate:
      add_integer(*sub, "--template-length", p.overlapping_m, "m, length of the all-ones template");
      add_integer(*sub, "--block-length", p.overlapping_M, "M");
      add_integer(*sub, "--K", p.overlapping_K, "degrees of freedom (classes 0..K)");
      break;
    case T::Universal:
      add_integer(*sub, "--block-length", p.universal_L, "L (0: from n, as the reference)");
      add_integer(*sub, "--init-blocks", p.universal_Q, "Q (0: 10*2^L)");
      break;
    case T::ApproximateEntropy:
      add_integer(*sub, "--template-length", p.approximate_entropy_m, "m, block length");
      break;
    case T::Serial:
      add_integer(*sub, "--template-length", p.serial_m, "m, block length");
      break;
    case T::LinearComplexity:
      add_integer(*sub, "--block-length", p.linear_complexity_M, "M");
      break;
    default:
      break;
  }
  sub->callback([a, sub] {
    a->in.inherit(*sub->get_parent(), *sub);
    run(*a);
  });
}

const bool registered = register_command(36, [](CLI::App& root) {
  CLI::App& nist_app = group(root, "nist", "NIST SP800-22 battery");
  for (nist::Test t : nist::all_tests()) add_test(nist_app, t);
});

}  // namespace
}  // namespace cmd_nist_test
}  // namespace dpdrng::cli
