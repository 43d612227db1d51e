#pragma once
// The golden test's vocabulary: a run's results flattened into named quantities, each written as the exact bits
// it holds (a scalar as a hex float, an array as its shape and an FNV-1a hash of its bytes, with its first and
// last values), and the digest files these are compared with (tests/golden/README.md).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace dpdrng::golden {

using Quantities = std::map<std::string, std::string>;  // quantity → digest
using Runs = std::map<std::string, Quantities>;         // run → its quantities

inline std::uint64_t fnv1a64(const void* data, std::size_t bytes, std::uint64_t h = 0xcbf29ce484222325ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < bytes; ++k) h = (h ^ p[k]) * 0x100000001b3ull;
  return h;
}

inline std::string hex64(std::uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
  return buf;
}

// A double exactly: its hex-float spelling (a NaN also by its bits, which %a does not show).
inline std::string exact(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%a", v);
  std::string s = buf;
  if (std::isnan(v)) s += "(" + hex64(std::bit_cast<std::uint64_t>(v)) + ")";
  return s;
}

inline std::string f64(double v) { return "f64 " + exact(v); }
inline std::string i64(std::int64_t v) { return "i64 " + std::to_string(v); }

// Short printable strings verbatim (escaped), others by length and hash.
inline std::string str(const std::string& s) {
  if (s.size() <= 100) {
    std::string out = "str \"";
    bool printable = true;
    for (char c : s) {
      if (c == '"' || c == '\\') out += '\\';
      if (static_cast<unsigned char>(c) < 0x20) printable = false;
      out += c;
    }
    if (printable) return out + "\"";
  }
  return "str[" + std::to_string(s.size()) + "] fnv1a64=" + hex64(fnv1a64(s.data(), s.size()));
}

inline std::string shape_of(const std::vector<std::size_t>& shape) {
  std::string s;
  for (std::size_t k = 0; k < shape.size(); ++k) s += (k ? "x" : "") + std::to_string(shape[k]);
  return s;
}

inline std::string f64s(const std::vector<double>& v, const std::vector<std::size_t>& shape = {}) {
  std::string s = "f64[" + shape_of(shape.empty() ? std::vector<std::size_t>{v.size()} : shape) + "] fnv1a64=" +
                  hex64(fnv1a64(v.data(), v.size() * sizeof(double)));
  if (!v.empty()) s += " first=" + exact(v.front()) + " last=" + exact(v.back());
  return s;
}

template <class Int>
std::string ints(const std::vector<Int>& v) {
  static_assert(sizeof(Int) == 8);
  std::string s = std::string(std::is_signed_v<Int> ? "i64[" : "u64[") + std::to_string(v.size()) +
                  "] fnv1a64=" + hex64(fnv1a64(v.data(), v.size() * 8));
  if (!v.empty()) s += " first=" + std::to_string(v.front()) + " last=" + std::to_string(v.back());
  return s;
}

inline std::string strs(const std::vector<std::string>& v) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const auto& s : v) {
    const std::uint64_t len = s.size();
    h = fnv1a64(&len, sizeof len, h);
    h = fnv1a64(s.data(), s.size(), h);
  }
  return "str[" + std::to_string(v.size()) + "] fnv1a64=" + hex64(h);
}

// Every leaf of a JSON document, its path joined by '/'; arrays of numbers are one quantity, other arrays are
// indexed. `keep(path)` drops what it rejects (timings).
inline void flatten(const nlohmann::json& j, const std::string& path, Quantities& q,
                    const std::function<bool(const std::string&)>& keep) {
  if (!keep(path)) return;
  const auto child = [&](const std::string& key) { return path.empty() ? key : path + "/" + key; };
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) flatten(it.value(), child(it.key()), q, keep);
  } else if (j.is_array()) {
    bool numbers = true, integers = true;
    for (const auto& e : j) numbers = numbers && e.is_number(), integers = integers && e.is_number_integer();
    if (!numbers) {
      for (std::size_t k = 0; k < j.size(); ++k) flatten(j[k], child(std::to_string(k)), q, keep);
    } else if (integers && !j.empty()) {
      std::vector<std::int64_t> v;
      for (const auto& e : j) v.push_back(e.get<std::int64_t>());
      q[path] = ints(v);
    } else {
      std::vector<double> v;
      for (const auto& e : j) v.push_back(e.get<double>());
      q[path] = f64s(v);
    }
  } else if (j.is_number_float()) {
    q[path] = f64(j.get<double>());
  } else if (j.is_number_unsigned()) {
    q[path] = "u64 " + std::to_string(j.get<std::uint64_t>());
  } else if (j.is_number_integer()) {
    q[path] = i64(j.get<std::int64_t>());
  } else if (j.is_string()) {
    q[path] = str(j.get<std::string>());
  } else if (j.is_boolean()) {
    q[path] = j.get<bool>() ? "bool true" : "bool false";
  } else {
    q[path] = "null";
  }
}

// Digest files: one line per quantity, "run<TAB>quantity<TAB>digest", sorted; '#' starts a comment line.
inline Runs read_digests(const std::string& path) {
  Runs runs;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto a = line.find('\t'), b = line.find('\t', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    runs[line.substr(0, a)][line.substr(a + 1, b - a - 1)] = line.substr(b + 1);
  }
  return runs;
}

inline void write_digests(const std::string& path, const Runs& runs, const std::string& what) {
  std::ofstream out(path);
  out << "# Golden digests of " << what << ": run, quantity, exact bits. Regenerate only as README.md says.\n";
  for (const auto& [run, q] : runs)
    for (const auto& [name, digest] : q) out << run << '\t' << name << '\t' << digest << '\n';
}

// Every difference between the committed digests and the runs produced: changed, missing or new quantities,
// and (when `complete`, i.e. every run of the file was produced) runs that were not produced.
inline std::vector<std::string> differences(const Runs& golden, const Runs& produced, bool complete) {
  std::vector<std::string> out;
  for (const auto& [run, q] : produced) {
    const auto g = golden.find(run);
    if (g == golden.end()) {
      out.push_back("new run " + run);
      continue;
    }
    for (const auto& [name, digest] : q) {
      const auto e = g->second.find(name);
      if (e == g->second.end())
        out.push_back("new quantity " + run + " : " + name + " = " + digest);
      else if (e->second != digest)
        out.push_back("changed " + run + " : " + name + "\n    golden   " + e->second + "\n    produced " + digest);
    }
    for (const auto& [name, digest] : g->second)
      if (!q.count(name)) out.push_back("missing quantity " + run + " : " + name + " (golden " + digest + ")");
  }
  if (complete)
    for (const auto& [run, q] : golden)
      if (!produced.count(run)) out.push_back("run not produced: " + run);
  return out;
}

inline bool updating() {
  const char* e = std::getenv("DPDRNG_UPDATE_GOLDEN");
  return e != nullptr && std::string(e) == "1";
}

// Compares `produced` with tests/golden/<file>, or rewrites the file under DPDRNG_UPDATE_GOLDEN=1.
inline void check(const std::string& file, const Runs& produced, bool complete, const std::string& what) {
  const std::string path = std::string(DPDRNG_SOURCE_DIR) + "/tests/golden/" + file;
  ASSERT_FALSE(produced.empty());
  if (updating()) {
    ASSERT_TRUE(complete) << "DPDRNG_UPDATE_GOLDEN=1 needs the full-scale runs (unset DPDRNG_TEST_SCALE)";
    write_digests(path, produced, what);
    std::printf("rewrote %s\n", path.c_str());
    return;
  }
  const Runs golden = read_digests(path);
  ASSERT_FALSE(golden.empty()) << path << " holds no digests (DPDRNG_UPDATE_GOLDEN=1 writes them)";
  const auto diffs = differences(golden, produced, complete);
  std::ostringstream msg;
  const std::size_t shown = std::min<std::size_t>(diffs.size(), 60);
  for (std::size_t k = 0; k < shown; ++k) msg << diffs[k] << "\n";
  if (shown < diffs.size()) msg << "… and " << diffs.size() - shown << " more\n";
  EXPECT_TRUE(diffs.empty()) << diffs.size() << " difference(s) from " << path << ":\n" << msg.str();
}

}  // namespace dpdrng::golden
