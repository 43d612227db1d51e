// One look per generator across every chart: colour by family (the Okabe–Ito palette, readable with the common
// colour-vision deficiencies), point type by round count, the reference in black; and the bands and lines that
// every shift chart draws the same way.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study::detail {

std::string family_colour(const std::string& generator) {
  static const std::pair<const char*, const char*> colours[] = {
      {"mt19937", "#000000"},   {"tea32", "#0072B2"},    {"tea64", "#E69F00"},  {"philox4x32", "#009E73"},
      {"threefry2x64", "#CC79A7"}, {"saru", "#D55E00"}, {"splitmix64", "#56B4E9"}, {"squares64", "#999933"}, {"defect", "#7F7F7F"}};
  for (const auto& [family, colour] : colours)
    if (generator.rfind(family, 0) == 0) return colour;
  return "#332288";  // any other generator (a plug-in)
}

// gnuplot's point types, one per round count a study sweeps: filled circle, square, triangle, diamond, inverted
// triangle, pentagon for 1–6 rounds; open inverted triangle, circle, pentagon, asterisk, square, plus, triangle,
// diamond for 7, 8, 10, 13, 16, 20, 32, 64 (the safe counts of TEA, Philox and Threefry among them); a cross for
// any other count and for a generator without rounds.
int rounds_point(int rounds) {
  static const std::pair<int, int> points[] = {{1, 7},  {2, 5},  {3, 9}, {4, 13}, {5, 11}, {6, 15}, {7, 10},
                                               {8, 6},  {10, 14}, {13, 3}, {16, 4}, {20, 1}, {32, 8}, {64, 12}};
  for (const auto& [r, pt] : points)
    if (r == rounds) return pt;
  return 2;
}

std::string colour_style(const std::string& generator) { return "lc rgb '" + family_colour(generator) + "'"; }

std::string generator_style(const std::string& generator, int rounds) {
  std::ostringstream s;
  s << "lc rgb '" << family_colour(generator) << "' pt " << rounds_point(rounds);
  return s.str();
}

std::vector<std::vector<std::string>> generator_groups(const std::vector<std::string>& generators) {
  const std::size_t n = generators.size();
  const std::size_t k = std::max<std::size_t>(1, (n + kMaxSeriesPerPanel - 1) / kMaxSeriesPerPanel);
  std::vector<std::vector<std::string>> groups(k);
  for (std::size_t g = 0, at = 0; g < k; ++g)  // the first n mod k groups one larger
    for (std::size_t i = 0; i < n / k + (g < n % k ? 1 : 0); ++i) groups[g].push_back(generators[at++]);
  return groups;
}

std::size_t group_of(const std::vector<std::vector<std::string>>& groups, const std::string& generator) {
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (std::find(groups[g].begin(), groups[g].end(), generator) != groups[g].end()) return g;
  return 0;
}

std::string panel_title(const std::string& prefix, std::size_t group, std::size_t groups) {
  if (groups < 2) return prefix;
  return prefix + (prefix.empty() ? "" : ", ") + "generators " + std::to_string(group + 1) + " of " +
         std::to_string(groups);
}

std::string margin_band(double margin, const std::string& what) {
  if (!std::isfinite(margin) || margin <= 0) return "";
  std::ostringstream s;
  s << "set object 1 rectangle from graph 0, first " << -margin << " to graph 1, first " << margin
    << " behind fillcolor rgb '#DDEEDD' fillstyle solid 1.0 noborder\n"
    << "set label 1 " << q(what + " ±" + num(margin)) << " at graph 0.01, first " << margin
    << " offset 0,-0.8 font ',10' tc rgb '#336633' front\n"
    << "set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb 'black'\n";
  return s.str();
}

std::string hline(double y, const std::string& title, const char* colour) {
  if (!std::isfinite(y)) return "";
  std::ostringstream s;
  s << "set arrow from graph 0, first " << y << " to graph 1, first " << y << " nohead dt 2 lw 2 lc rgb '" << colour
    << "'\n";
  if (!title.empty())
    s << "set label " << q(title) << " at graph 0.01, first " << y << " offset 0,0.6 font ',10' tc rgb '" << colour
      << "'\n";
  return s.str();
}

}  // namespace dpdrng::study::detail
