#include "dpdrng/stats/nist/report.hpp"

#include <cmath>
#include <cstdio>

namespace dpdrng::stats::nist {

namespace {

std::string fmt(const char* f, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, args...);
  return buf;
}

const char* kRule = "------------------------------------------------------------------------------\n";

std::string column_name(const Assessment& a) {
  std::string name(test_name(a.test));
  return a.variant == "-" ? name : name + " " + a.variant;
}

}  // namespace

std::string final_analysis_report(std::span<const Assessment> rows, const std::string& source, double alpha) {
  std::string out;
  out += kRule;
  out += "RESULTS FOR THE UNIFORMITY OF P-VALUES AND THE PROPORTION OF PASSING SEQUENCES\n";
  out += kRule;
  out += "   generator is <" + source + ">\n";
  out += kRule;
  out += " C1  C2  C3  C4  C5  C6  C7  C8  C9 C10  P-VALUE  PROPORTION  STATISTICAL TEST\n";
  out += kRule;
  int general = 0, excursion = 0;
  for (const Assessment& a : rows) {
    for (int b : a.bins) out += fmt("%3d ", b);
    if (a.sample_size / 10 == 0)
      out += "    ----    ";
    else
      out += fmt(" %8.6f %c ", a.reference_uniformity_p, a.reference_uniformity_ok ? ' ' : '*');
    if (a.sample_size == 0)
      out += " ------     " + column_name(a);
    else
      out += fmt("%4d/%-4d %c  ", a.reference_passed, a.sample_size, a.reference_proportion_ok ? ' ' : '*') + column_name(a);
    if (a.sample_size > 0 && a.ok() != a.reference_ok())
      out += a.ok() ? "   [exact bounds: pass]" : "   [exact bounds: FAIL]";
    out += "\n";
    const bool exc = a.test == Test::RandomExcursions || a.test == Test::RandomExcursionsVariant;
    (exc ? excursion : general) = a.sample_size;
  }
  out += "\n\n- - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - -\n";
  auto min_pass = [&](int m) { return static_cast<int>(proportion_range(alpha, m).low * m); };
  if (general > 0)
    out += fmt("The minimum pass rate for each statistical test with the exception of the\n"
               "random excursion (variant) test is approximately = %d for a\nsample size = %d binary sequences.\n\n",
               min_pass(general), general);
  if (excursion > 0)
    out += fmt("The minimum pass rate for the random excursion (variant) test\n"
               "is approximately = %d for a sample size = %d binary sequences.\n\n",
               min_pass(excursion), excursion);
  out += fmt("Proportion bounds: (1-alpha) -+ 3 sqrt(alpha(1-alpha)/m), alpha = %g; uniformity P-value_T >= 0.0001.\n",
             alpha);
  out += "'*' marks the reference's verdict (integer-truncated bounds, 6-digit P-values);\n"
         "[exact bounds: ...] appears where the untruncated bounds disagree with it.\n";
  out += "- - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - -\n";
  return out;
}

std::string tsv_lines(std::span<const std::vector<TestResult>> per_sequence) {
  std::string out;
  for (std::size_t i = 0; i < per_sequence.size(); ++i)
    for (const TestResult& r : per_sequence[i])
      for (const PValue& v : r.values) {
        out += std::to_string(i + 1) + '\t' + std::string(test_name(r.test)) + '\t' + v.variant + '\t';
        out += (!r.applicable || std::isnan(v.p)) ? std::string("n/a") : fmt("%f", v.p);
        out += '\n';
      }
  return out;
}

nlohmann::json to_json(const TestResult& r) {
  nlohmann::json j;
  j["test"] = test_name(r.test);
  j["n"] = r.n;
  j["applicable"] = r.applicable;
  if (!r.applicable) {
    j["reason"] = r.reason;
    j["min_bits"] = r.min_bits;
  }
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [k, v] : r.parameters) params[k] = v;
  j["parameters"] = params;
  nlohmann::json values = nlohmann::json::array();
  for (const PValue& v : r.values) {
    nlohmann::json e;
    e["variant"] = v.variant;
    e["statistic"] = std::isnan(v.statistic) ? nlohmann::json() : nlohmann::json(v.statistic);
    e["p"] = std::isnan(v.p) ? nlohmann::json() : nlohmann::json(v.p);
    values.push_back(e);
  }
  j["values"] = values;
  return j;
}

nlohmann::json to_json(const Assessment& a) {
  auto num = [](double x) { return std::isnan(x) ? nlohmann::json() : nlohmann::json(x); };
  return {{"test", test_name(a.test)},
          {"variant", a.variant},
          {"sample_size", a.sample_size},
          {"passed", a.passed},
          {"reference_passed", a.reference_passed},
          {"bins", a.bins},
          {"uniformity_p", num(a.uniformity_p)},
          {"reference_uniformity_p", num(a.reference_uniformity_p)},
          {"proportion_low", num(a.proportion_low)},
          {"proportion_high", num(a.proportion_high)},
          {"reference_min_pass", a.reference_min_pass},
          {"reference_max_pass", a.reference_max_pass},
          {"ok", a.ok()},
          {"reference_ok", a.reference_ok()}};
}

}  // namespace dpdrng::stats::nist
