// dpdrng nist: the whole SP800-22 battery (sts-2.1.2's defaults) on one or many streams of a bit file.
#include <algorithm>
#include <iostream>
#include <limits>
#include <memory>

#include "cmd_nist_common.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/stats/nist/report.hpp"

namespace dpdrng::cli {

namespace nist = stats::nist;

void NistInput::add_to(CLI::App& app) {
  app.add_option("--input,-i", input, "bit file, or - for standard input");
  app.add_option("--format", format,
                 "ascii ('0'/'1' and white space; any other byte refused) or raw (bytes, MSB first)")
      ->check(CLI::IsMember({"ascii", "raw"}))
      ->capture_default_str();
  const IntRange positive{1, std::numeric_limits<std::size_t>::max()};
  add_integer(app, "--streams", streams, "number of streams K (default: one stream of all the input)", positive);
  add_integer(app, "--stream-bits", stream_bits, "bits per stream N (needed with --streams)", positive);
  add_real(app, "--alpha", alpha, "significance level", {0, 1, true, true});
  app.add_flag("--tsv", tsv, "one line per P-value: stream, test, variant, p");
  app.add_flag("--json", json, "machine-readable output");
}

void NistInput::inherit(const CLI::App& parent, const CLI::App& sub) {
  static const std::vector<std::string> shared = {"--input", "--format", "--streams", "--stream-bits",
                                                  "--alpha", "--tsv",    "--json"};
  for (const CLI::Option* o : parent.get_options())
    if (o->count() > 0 && std::find(shared.begin(), shared.end(), o->get_name()) == shared.end())
      throw InputError(o->get_name() + " is an option of the whole battery, not of 'nist " + sub.get_name() +
                       "' (see dpdrng nist " + sub.get_name() + " --help)");
  for (const std::string& name : shared) {
    const CLI::Option* given = parent.get_option(name);
    if (given->count() == 0) continue;
    if (sub.get_option(name)->count() > 0)
      throw InputError(name + " is given both before and after '" + sub.get_name() + "': give it once");
    if (name == "--input") input = given->as<std::string>();
    if (name == "--format") format = given->as<std::string>();
    if (name == "--streams") streams = given->as<std::size_t>();
    if (name == "--stream-bits") stream_bits = given->as<std::size_t>();
    if (name == "--alpha") alpha = given->as<double>();
    if (name == "--tsv") tsv = true;
    if (name == "--json") json = true;
  }
}

void NistInput::check() const {
  if (input.empty()) throw InputError("--input is required (a file, or - for standard input)");
  if (tsv && json) throw InputError("choose one of --tsv and --json");
  if ((streams == 0) != (stream_bits == 0))
    throw InputError(streams == 0 ? "--stream-bits needs --streams (how many streams of that many bits)"
                                  : "--streams needs --stream-bits (how many bits a stream holds)");
  if (streams != 0 && stream_bits > std::numeric_limits<std::size_t>::max() / streams)
    throw InputError("--streams x --stream-bits is more bits than this machine can address");
}

std::vector<nist::BitSequence> NistInput::load() const {
  check();
  const nist::BitFormat f = nist::parse_bit_format(format);
  if (streams == 0) {
    nist::BitSequence all = nist::read_bits(input, f);
    if (all.empty())
      throw InputError(source() + ": no bits in the input" +
                       (f == nist::BitFormat::ascii ? " (no '0' or '1' characters)" : " (empty)"));
    return {std::move(all)};
  }
  return nist::split_streams(nist::read_bits(input, f, streams * stream_bits), streams, stream_bits);
}

void check_nist_parameters(const std::vector<nist::Test>& tests, const nist::Parameters& p,
                           const std::function<std::string(const std::string& field)>& flag) {
  for (const nist::Test t : tests)
    if (const auto problem = nist::check_parameters(t, p)) {
      // A template as typed: its bits, not their value.
      std::string value = std::to_string(problem->value);
      if (problem->field == "non_overlapping_templates" && p.non_overlapping_m >= 1 && p.non_overlapping_m <= 32) {
        value.clear();
        for (int k = p.non_overlapping_m - 1; k >= 0; --k) value += (problem->value >> k) & 1 ? '1' : '0';
      }
      throw InputError(flag(problem->field) + " " + value + ": " + problem->reason);
    }
}

void print_nist(const NistInput& in, const std::vector<std::vector<nist::TestResult>>& results,
                const nlohmann::json& parameters) {
  const auto rows = nist::assess(results, in.alpha);
  if (in.tsv) {
    std::cout << nist::tsv_lines(results);
    return;
  }
  if (in.json) {
    nlohmann::json j;
    j["source"] = in.source();
    j["format"] = in.format;
    j["streams"] = results.size();
    j["stream_bits"] = results.empty() || results[0].empty() ? 0 : results[0][0].n;
    j["alpha"] = in.alpha;
    j["parameters"] = parameters;
    nlohmann::json seqs = nlohmann::json::array();
    for (const auto& r : results) {
      nlohmann::json one = nlohmann::json::array();
      for (const auto& t : r) one.push_back(nist::to_json(t));
      seqs.push_back(one);
    }
    j["results"] = seqs;
    nlohmann::json a = nlohmann::json::array();
    for (const auto& row : rows) a.push_back(nist::to_json(row));
    j["assessment"] = a;
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << nist::final_analysis_report(rows, in.source(), in.alpha);
  // Say why a test has fewer (or no) P-values rather than leaving the sample size unexplained.
  for (std::size_t ti = 0; ti < results.front().size(); ++ti) {
    std::size_t na = 0, first = 0;
    for (std::size_t i = results.size(); i-- > 0;)
      if (!results[i][ti].applicable) ++na, first = i;
    if (na == 0) continue;
    std::cout << "n/a " << nist::test_name(results.front()[ti].test) << " on " << na << " of " << results.size()
              << " streams (stream " << first + 1 << ": " << results[first][ti].reason << ")\n";
  }
}

namespace cmd_nist {
namespace {

struct NistArgs {
  NistInput in;
  std::string tests;
  nist::Parameters p;
};

std::vector<nist::Test> parse_tests(const std::string& list) {
  std::vector<nist::Test> out;
  if (list.empty()) return out;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    const auto t = nist::parse_test(name);
    if (!t) throw InputError("--tests: unknown test " + quote_input(name) + " (e.g. Frequency,Runs or frequency,runs)");
    if (std::find(out.begin(), out.end(), *t) != out.end())
      throw InputError("--tests: " + quote_input(name) + " lists " + std::string(nist::test_name(*t)) + " twice");
    out.push_back(*t);
    start = end + 1;
  }
  return out;
}

nlohmann::json parameters_json(const nist::Parameters& p) {
  return {{"block_frequency_M", p.block_frequency_M}, {"non_overlapping_m", p.non_overlapping_m},
          {"overlapping_m", p.overlapping_m},         {"universal_L", p.universal_L},
          {"universal_Q", p.universal_Q},             {"approximate_entropy_m", p.approximate_entropy_m},
          {"serial_m", p.serial_m},                   {"linear_complexity_M", p.linear_complexity_M}};
}

void run_nist(const NistArgs& a) {
  const auto tests = parse_tests(a.tests);
  a.in.check();
  // The battery's flags are the Parameters fields spelt with dashes (--universal-L for universal_L).
  check_nist_parameters(tests.empty() ? nist::all_tests() : tests, a.p, [](std::string field) {
    std::replace(field.begin(), field.end(), '_', '-');
    return "--" + field;
  });
  begin_work();
  const auto seqs = a.in.load();
  const auto results = nist::run_battery(seqs, a.p, tests);
  print_nist(a.in, results, parameters_json(a.p));
}

const bool registered = register_command(35, [](CLI::App& root) {
  auto args = std::make_shared<NistArgs>();
  CLI::App* sub = root.add_subcommand("nist", "NIST SP800-22 rev1a battery (sts-2.1.2 defaults), or one test of it");
  sub->footer(
      "Without a test subcommand, runs the whole battery (188 P-values a stream with the defaults) and prints\n"
      "the reference's finalAnalysisReport. Streams: stream i = input bits [iN, (i+1)N).");
  args->in.add_to(*sub);
  sub->add_option("--tests", args->tests, "comma-separated subset, reference or subcommand names (default: all)");
  auto& p = args->p;
  add_integer(*sub, "--block-frequency-M", p.block_frequency_M, "BlockFrequency block length");
  add_integer(*sub, "--non-overlapping-m", p.non_overlapping_m, "NonOverlappingTemplate template length");
  add_integer(*sub, "--overlapping-m", p.overlapping_m, "OverlappingTemplate template length");
  add_integer(*sub, "--universal-L", p.universal_L, "Universal block length (0: from n, as the reference)");
  add_integer(*sub, "--universal-Q", p.universal_Q, "Universal initialisation blocks (0: 10*2^L)");
  add_integer(*sub, "--approximate-entropy-m", p.approximate_entropy_m, "ApproximateEntropy block length");
  add_integer(*sub, "--serial-m", p.serial_m, "Serial block length");
  add_integer(*sub, "--linear-complexity-M", p.linear_complexity_M, "LinearComplexity block length");
  sub->callback([args, sub] {
    if (!sub->get_subcommands().empty()) return;  // a per-test subcommand ran instead
    run_nist(*args);
  });
});

}  // namespace
}  // namespace cmd_nist
}  // namespace dpdrng::cli
