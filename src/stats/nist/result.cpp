#include "dpdrng/stats/nist/result.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace dpdrng::stats::nist {

namespace {

struct Names {
  std::string_view reference, cli;
};
constexpr std::array<Names, kTestCount> kNames = {{
    {"Frequency", "frequency"},
    {"BlockFrequency", "block-frequency"},
    {"CumulativeSums", "cumulative-sums"},
    {"Runs", "runs"},
    {"LongestRun", "longest-run"},
    {"Rank", "rank"},
    {"FFT", "fft"},
    {"NonOverlappingTemplate", "non-overlapping-template"},
    {"OverlappingTemplate", "overlapping-template"},
    {"Universal", "universal"},
    {"ApproximateEntropy", "approximate-entropy"},
    {"RandomExcursions", "random-excursions"},
    {"RandomExcursionsVariant", "random-excursions-variant"},
    {"Serial", "serial"},
    {"LinearComplexity", "linear-complexity"},
}};

bool iequal(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

std::string_view test_name(Test t) { return kNames[static_cast<int>(t)].reference; }
std::string_view test_cli_name(Test t) { return kNames[static_cast<int>(t)].cli; }

std::optional<Test> parse_test(std::string_view name) {
  for (int i = 0; i < kTestCount; ++i)
    if (iequal(name, kNames[i].reference) || iequal(name, kNames[i].cli)) return static_cast<Test>(i);
  return std::nullopt;
}

double TestResult::min_p() const {
  double m = NAN;
  for (const auto& v : values)
    if (!std::isnan(v.p) && (std::isnan(m) || v.p < m)) m = v.p;
  return m;
}

}  // namespace dpdrng::stats::nist
