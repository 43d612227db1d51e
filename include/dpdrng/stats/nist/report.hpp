#pragma once
// Output of the battery: the reference's finalAnalysisReport table, one-line-per-P-value TSV, and JSON.
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "dpdrng/stats/nist/battery.hpp"

namespace dpdrng::stats::nist {

// The reference's layout (C1..C10, P-VALUE, PROPORTION, STATISTICAL TEST, '*' marks), with the exact-bound
// verdict added at the end of a line where it differs from the reference's.
std::string final_analysis_report(std::span<const Assessment> rows, const std::string& source, double alpha);

// "stream<TAB>test<TAB>variant<TAB>p" lines, streams numbered from 1, P to 6 places as the reference writes
// them, "n/a" where not applicable.
std::string tsv_lines(std::span<const std::vector<TestResult>> per_sequence);

nlohmann::json to_json(const TestResult& r);
nlohmann::json to_json(const Assessment& a);

}  // namespace dpdrng::stats::nist
