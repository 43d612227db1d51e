// dpdrng nist <test>: one SP800-22 test with its own parameters, e.g. `dpdrng nist runs -i data.e`.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cmd_nist_common.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/nist/report.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::cli {
namespace {

namespace nist = stats::nist;

struct TestArgs {
  NistInput in;
  nist::Test test{};
  int block_length = 0;     // M (0: the test's default)
  int template_length = 0;  // m
  int K = 5;
  int blocks = 8;
  int universal_Q = 0;
  std::vector<std::string> templates;
  std::vector<std::uint32_t> parsed_templates;  // filled before the parallel loop: no throwing inside it
};

std::uint32_t parse_template(const std::string& bits, int m) {
  if (static_cast<int>(bits.size()) != m || bits.find_first_not_of("01") != std::string::npos)
    throw InputError("--template '" + bits + "' must be " + std::to_string(m) + " characters of 0/1");
  std::uint32_t v = 0;
  for (char c : bits) v = (v << 1) | static_cast<std::uint32_t>(c == '1');
  return v;
}

nist::TestResult run_one(const TestArgs& a, const nist::BitSequence& s) {
  auto or_default = [](int v, int d) { return v == 0 ? d : v; };
  switch (a.test) {
    case nist::Test::BlockFrequency: return nist::block_frequency(s, or_default(a.block_length, 128));
    case nist::Test::NonOverlappingTemplate: {
      return nist::non_overlapping_template(s, or_default(a.template_length, 9), a.parsed_templates, a.blocks);
    }
    case nist::Test::OverlappingTemplate:
      return nist::overlapping_template(s, or_default(a.template_length, 9), or_default(a.block_length, 1032), a.K);
    case nist::Test::Universal: return nist::universal(s, a.block_length, a.universal_Q);
    case nist::Test::ApproximateEntropy: return nist::approximate_entropy(s, or_default(a.template_length, 10));
    case nist::Test::Serial: return nist::serial(s, or_default(a.template_length, 16));
    case nist::Test::LinearComplexity: return nist::linear_complexity(s, or_default(a.block_length, 500));
    default: return nist::run_test(a.test, s);
  }
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
  const int m = a.template_length == 0 ? 9 : a.template_length;
  a.parsed_templates.clear();
  for (const auto& b : a.templates) a.parsed_templates.push_back(parse_template(b, m));
  const auto seqs = a.in.load();
  std::vector<std::vector<nist::TestResult>> results(seqs.size());
  const long count = static_cast<long>(seqs.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long i = 0; i < count; ++i) results[i] = {run_one(a, seqs[i])};
  if (a.in.tsv || a.in.json || seqs.size() > 1) {
    if (!a.in.tsv && !a.in.json) print_human(results);
    print_nist(a.in, results,
               {{"block_length", a.block_length}, {"template_length", a.template_length}, {"K", a.K},
                {"blocks", a.blocks}, {"universal_Q", a.universal_Q}, {"templates", a.templates}});
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
  switch (t) {
    case T::BlockFrequency:
      sub->add_option("--block-length", a->block_length, "M, bits per block (default 128)");
      break;
    case T::NonOverlappingTemplate:
      sub->add_option("--template-length", a->template_length, "m (default 9)");
      sub->add_option("--template", a->templates, "template bits, e.g. 000000001 (default: all aperiodic ones)");
      sub->add_option("--blocks", a->blocks, "N, number of blocks")->capture_default_str();
      break;
    case T::OverlappingTemplate:
      sub->add_option("--template-length", a->template_length, "m, length of the all-ones template (default 9)");
      sub->add_option("--block-length", a->block_length, "M (default 1032)");
      sub->add_option("--K", a->K, "degrees of freedom (classes 0..K)")->capture_default_str();
      break;
    case T::Universal:
      sub->add_option("--block-length", a->block_length, "L (default: from n, as the reference)");
      sub->add_option("--init-blocks", a->universal_Q, "Q (default 10*2^L)");
      break;
    case T::ApproximateEntropy:
      sub->add_option("--template-length", a->template_length, "m, block length (default 10)");
      break;
    case T::Serial:
      sub->add_option("--template-length", a->template_length, "m, block length (default 16)");
      break;
    case T::LinearComplexity:
      sub->add_option("--block-length", a->block_length, "M (default 500)");
      break;
    default:
      break;
  }
  sub->callback([a] { run(*a); });
}

const bool registered = register_command(36, [](CLI::App& root) {
  CLI::App& nist_app = group(root, "nist", "NIST SP800-22 battery");
  for (nist::Test t : nist::all_tests()) add_test(nist_app, t);
});

}  // namespace
}  // namespace dpdrng::cli
