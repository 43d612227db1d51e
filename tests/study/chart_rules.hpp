#pragma once
// The rules every chart follows (docs/charts.md), checked on a chart's three files: the gnuplot script (axis
// labels with units, data read only from the chart's own CSV, at most six titled series per panel), the CSV (one header,
// every row as wide as it) and the rendered SVG (tick labels with no more digits than the data need, no two
// text boxes overlapping). Text extents are estimated from the font size and the number of characters, as a
// reader's eye would judge them: 0.55 em per character, 1 em tall.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace chart_rules {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Characters of a UTF-8 string (continuation bytes not counted).
inline std::size_t glyphs(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

inline std::vector<std::string> gp_violations(const std::string& gp, const std::string& name) {
  std::vector<std::string> v;
  for (const char* axis : {"x", "y"}) {
    const std::regex label(std::string("set ") + axis + R"re(label "((?:[^"\\]|\\.)*)")re");
    std::smatch m;
    const bool categories = gp.find(std::string("# ") + axis + " axis: categories") != std::string::npos;
    if (!std::regex_search(gp, m, label)) {
      v.push_back(std::string("no ") + axis + " label");
      continue;
    }
    if (!categories && !std::regex_search(m[1].str(), std::regex(R"(\[[^\]]+\]$)")))
      v.push_back(std::string(axis) + " label without a unit in brackets: \"" + m[1].str() + "\"");
  }
  // Every file the script reads is the chart's own CSV.
  const std::regex file("\"([^\"]+\\.(csv|dat|txt))\"");
  for (auto it = std::sregex_iterator(gp.begin(), gp.end(), file); it != std::sregex_iterator(); ++it)
    if ((*it)[1].str() != name + ".csv") v.push_back("reads " + (*it)[1].str() + ", not " + name + ".csv");
  // Series per panel: the distinct blocks each plot command draws.
  std::istringstream lines(gp);
  std::string line, command;
  std::vector<std::string> commands;
  while (std::getline(lines, line)) {
    if (line.rfind("plot ", 0) == 0) command = line;
    else if (!command.empty()) command += line;
    if (!command.empty() && (line.empty() || line.back() != '\\')) commands.push_back(command), command.clear();
  }
  if (commands.empty()) v.push_back("no plot command");
  // A series is a block drawn with a title (in the key); untitled elements over it (point labels, the triangles
  // of shifts beyond the axis, a Pareto front) annotate, and keyentry lines draw no data.
  const std::regex element(R"re(index (\d+)[^\n]*? (title "([^"]*)"|notitle))re");
  for (const auto& c : commands) {
    std::set<std::string> blocks;
    for (auto it = std::sregex_iterator(c.begin(), c.end(), element); it != std::sregex_iterator(); ++it)
      if ((*it)[3].matched && !(*it)[3].str().empty()) blocks.insert((*it)[1].str());
    if (blocks.size() > 6) v.push_back("a panel draws " + std::to_string(blocks.size()) + " series (at most 6)");
  }
  return v;
}

inline std::vector<std::string> csv_violations(const std::string& csv) {
  std::vector<std::string> v;
  std::istringstream lines(csv);
  std::string line;
  if (!std::getline(lines, line) || line.rfind("series,", 0) != 0) return {"the CSV's header does not start with series,"};
  const auto fields = [](const std::string& s) {
    std::size_t n = 1;
    bool quoted = false;
    for (char c : s) quoted = c == '"' ? !quoted : quoted, n += !quoted && c == ',';
    return n;
  };
  const std::size_t width = fields(line);
  std::size_t row = 1;
  while (std::getline(lines, line)) {
    ++row;
    if (!line.empty() && fields(line) != width)
      v.push_back("CSV row " + std::to_string(row) + " has " + std::to_string(fields(line)) + " fields, the header " +
                  std::to_string(width));
  }
  return v;
}

struct Text {
  std::string s;
  double x0, x1, y0, y1;
};

// The value of attribute `name` inside the tag text `tag` ("" when absent).
inline std::string attribute(const std::string& tag, const std::string& name) {
  const std::size_t at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const std::size_t from = at + name.size() + 3;
  return tag.substr(from, tag.find('"', from) - from);
}

// The characters of an element's body without its tags and entities decoded, trimmed.
inline std::string plain(const std::string& body) {
  std::string s;
  bool tag = false;
  for (char c : body) {
    if (c == '<') tag = true;
    if (!tag) s += c;
    if (c == '>') tag = false;
  }
  for (const auto& [entity, c] : {std::pair{"&lt;", "<"}, std::pair{"&gt;", ">"}, std::pair{"&amp;", "&"}})
    for (std::size_t at = s.find(entity); at != std::string::npos; at = s.find(entity, at + 1))
      s.replace(at, std::string(entity).size(), c);
  const std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// Every text element of a gnuplot SVG (a <g transform="translate(x,y) [rotate(a)]" … font-size text-anchor>
// around a <text>) with its estimated box.
inline std::vector<Text> svg_texts(const std::string& svg) {
  std::vector<Text> out;
  for (std::size_t at = svg.find("<g transform=\"translate("); at != std::string::npos;
       at = svg.find("<g transform=\"translate(", at + 1)) {
    const std::size_t close = svg.find('>', at);
    const std::string tag = svg.substr(at, close - at);
    const std::size_t text = svg.find_first_not_of(" \t\r\n", close + 1);
    if (text == std::string::npos || svg.compare(text, 6, "<text>") != 0) continue;
    const std::string s = plain(svg.substr(text + 6, svg.find("</text>", text) - text - 6));
    const std::string size = attribute(tag, "font-size"), anchor = attribute(tag, "text-anchor");
    if (s.empty() || size.empty()) continue;
    const std::string transform = attribute(tag, "transform");
    double x = 0, y = 0, a = 0;
    std::sscanf(transform.c_str(), "translate(%lf,%lf) rotate(%lf)", &x, &y, &a);
    const double f = std::stod(size), w = 0.55 * f * double(glyphs(s));
    const double lo = anchor == "middle" ? -w / 2 : anchor == "end" ? -w : 0;
    Text t{s, x + lo, x + lo + w, y - 0.8 * f, y + 0.2 * f};
    if (std::abs(std::abs(a) - 90) < 1 || std::abs(a - 270) < 1) t = Text{s, x - 0.8 * f, x + 0.2 * f, y - lo - w, y - lo};
    out.push_back(t);
  }
  return out;
}

// A tick label with more digits than the data need: a trailing zero after the decimal point ("1000.000000"),
// four or more zeros after it before the first digit ("0.00000001"), or more than six significant digits.
inline bool too_precise(const std::string& s) {
  static const std::regex number(R"(^[-−+]?(\d+)(\.(\d+))?$)");
  std::smatch m;
  if (!std::regex_match(s, m, number)) return false;
  const std::string decimals = m[3].str();
  if (!decimals.empty() && decimals.back() == '0') return true;
  if (decimals.rfind("0000", 0) == 0) return true;
  std::string digits = m[1].str() + decimals;
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
  while (!digits.empty() && digits.back() == '0' && decimals.empty()) digits.pop_back();
  return digits.size() > 6;
}

inline std::vector<std::string> svg_violations(const std::string& svg) {
  std::vector<std::string> v;
  const auto texts = svg_texts(svg);
  if (texts.empty()) v.push_back("no text in the SVG");
  for (const auto& t : texts)
    if (too_precise(t.s)) v.push_back("tick label with more digits than the data need: " + t.s);
  constexpr double kSlack = 1.0;  // px: boxes that merely touch do not overlap
  for (std::size_t i = 0; i < texts.size(); ++i)
    for (std::size_t j = i + 1; j < texts.size(); ++j) {
      const Text &a = texts[i], &b = texts[j];
      const double dx = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), dy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
      if (dx > kSlack && dy > kSlack) v.push_back("texts overlap: \"" + a.s + "\" and \"" + b.s + "\"");
    }
  return v;
}

}  // namespace chart_rules
