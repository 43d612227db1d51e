#pragma once
// Shared glue of the chi2, ttest and corr subcommands: input options, number formatting, JSON of results.
// Private to src/cli (not installed); the library in dpdrng/stats knows nothing of it.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "dpdrng/cli/options.hpp"
#include "dpdrng/stats/correlation.hpp"
#include "dpdrng/stats/input.hpp"
#include "dpdrng/stats/pass_fraction.hpp"

namespace dpdrng::cli {

struct StatsInput {
  std::string input;
  std::string format;
  double alpha = 0.01;
  bool json = false;

  void add_to(CLI::App& app) {
    app.add_option("--input,-i", input, "file to read, or - for standard input")->required();
    app.add_option("--format,-f", format,
                   "u64 = raw little-endian 64-bit words mapped to [0,1) by their top 53 bits (dpdrng gen "
                   "--format raw); f64 = raw little-endian doubles; text = one number a line")
        ->required()
        ->check(CLI::IsMember({"u64", "f64", "text"}));
    add_real(app, "--alpha", alpha, "significance level of each test", {0, 1, true, true});
    app.add_flag("--json", json, "machine-readable output");
  }
  std::vector<double> read() const { return stats::read_values(input, stats::parse_input_format(format)); }
};

// Chunked runs (--per N): the pass fraction over chunks of N values.
struct ChunkOptions {
  std::size_t per = 0;
  double confidence = 0.99;

  void add_to(CLI::App& app) {
    add_integer(app, "--per", per, "split the input into chunks of N values, test each, report the pass fraction",
                {1, std::numeric_limits<std::size_t>::max()});
    add_real(app, "--confidence", confidence,
             "level of the pass fraction's central Clopper-Pearson interval; 1 - level is the level of the central "
             "binomial test, p = 2 min(P[X <= k], P[X >= k]), which agrees with that interval",
             {0, 1, true, true});
  }
};

// NaN and infinities have no JSON spelling: they become null, which is what "undefined" means here.
inline nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

inline std::string fmt(double v, const char* spec = "%.6g") {
  char buf[48];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

inline nlohmann::json pass_fraction_json(const stats::PassFraction& pf) {
  nlohmann::json j{{"applicable", pf.trials},
                   {"passed", pf.passed},
                   {"not_applicable", pf.not_applicable},
                   {"expected", pf.expected},
                   {"confidence", pf.confidence},
                   {"verdict", stats::to_string(pf.verdict)}};
  if (pf.verdict == stats::Verdict::not_applicable) {
    j["reason"] = pf.reason;
  } else {
    j["fraction"] = pf.fraction;
    j["ci"] = {pf.ci_low, pf.ci_high};
    j["binomial_p"] = pf.binomial_p;
  }
  return j;
}

inline void print_pass_fraction(const stats::PassFraction& pf, std::size_t chunks, std::size_t per,
                                std::size_t unused) {
  std::cout << "  chunks          " << chunks << " of " << per << " values";
  if (unused) std::cout << " (" << unused << " trailing values not tested)";
  std::cout << "\n  applicable      " << pf.trials << " (" << pf.not_applicable << " not applicable)\n";
  if (pf.verdict == stats::Verdict::not_applicable) {
    std::cout << "  pass fraction   n/a: " << pf.reason << "\n";
    return;
  }
  std::cout << "  passed          " << pf.passed << "\n"
            << "  pass fraction   " << fmt(pf.fraction, "%.4f") << "  " << fmt(100 * pf.confidence, "%g")
            << "% CI [" << fmt(pf.ci_low, "%.4f") << ", " << fmt(pf.ci_high, "%.4f") << "]  expected "
            << fmt(pf.expected, "%.4f") << "\n"
            << "  binomial test   p = " << fmt(pf.binomial_p, "%.4g") << "\n"
            << "  verdict         "
            << (pf.verdict == stats::Verdict::pass ? "consistent with alpha" : "NOT consistent with alpha") << "\n";
}

inline nlohmann::json correlation_json(const stats::CorrelationResult& c) {
  nlohmann::json j{{"check", c.what}, {"n", c.n}, {"alpha", c.alpha}, {"verdict", stats::to_string(c.verdict)}};
  if (c.verdict == stats::Verdict::not_applicable) {
    j["reason"] = c.reason;
  } else {
    j["r"] = c.r;
    j["t"] = number(c.statistic);
    j["dof"] = c.dof;
    j["p"] = c.p_value;
  }
  return j;
}

}  // namespace dpdrng::cli
