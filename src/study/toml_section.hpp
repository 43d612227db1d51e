#pragma once
// The TOML reader of every config the study layer parses (study configs, decomposition sweeps): one table at a
// time, each key checked off as it is read, so that a misspelt key is an error naming the keys allowed there,
// and every value checked for type, finiteness and range with a message that names the key.
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "dpdrng/common/error.hpp"

namespace dpdrng::study {

// Reads one TOML table, remembering which keys were used, so that a misspelt key is an error rather than
// a silently ignored setting.
class Section {
 public:
  Section(const toml::table* t, std::string path, std::string origin)
      : t_(t), path_(std::move(path)), origin_(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(origin_ + ": " + full(key) + ": " + problem);
  }
  std::string full(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const toml::node* get(const std::string& key) {
    used_.insert(key);
    return t_ ? t_->get(key) : nullptr;
  }

  std::string str(const std::string& key, std::string def) {
    const toml::node* n = get(key);
    if (!n) return def;
    if (!n->is_string()) fail(key, "must be a string");
    return std::string(*n->value<std::string>());
  }
  double num(const std::string& key, double def, double lo, double hi, bool lo_open = false) {
    const toml::node* n = get(key);
    if (!n) return def;
    return check_num(key, *n, lo, hi, lo_open);
  }
  long integer(const std::string& key, long def, long lo, long hi) {
    const toml::node* n = get(key);
    if (!n) return def;
    return check_int(key, *n, lo, hi);
  }
  std::vector<std::string> strings(const std::string& key, std::vector<std::string> def) {
    const toml::node* n = get(key);
    if (!n) return def;
    const toml::array* a = n->as_array();
    if (!a) fail(key, "must be an array of strings");
    std::vector<std::string> out;
    for (const auto& e : *a) {
      if (!e.is_string()) fail(key, "must be an array of strings");
      out.emplace_back(*e.value<std::string>());
    }
    if (out.empty()) fail(key, "must not be empty");
    return out;
  }
  std::vector<long> integers(const std::string& key, long lo, long hi) {
    const toml::node* n = get(key);
    if (!n) return {};
    std::vector<long> out;
    if (const toml::array* a = n->as_array()) {
      for (const auto& e : *a) out.push_back(check_int(key, e, lo, hi));
      if (out.empty()) fail(key, "must not be empty");
    } else {
      out.push_back(check_int(key, *n, lo, hi));
    }
    return out;
  }
  std::vector<double> numbers(const std::string& key, std::vector<double> def, double lo, double hi, bool lo_open) {
    const toml::node* n = get(key);
    if (!n) return def;
    std::vector<double> out;
    if (const toml::array* a = n->as_array()) {
      for (const auto& e : *a) out.push_back(check_num(key, e, lo, hi, lo_open));
      if (out.empty()) fail(key, "must not be empty");
    } else {
      out.push_back(check_num(key, *n, lo, hi, lo_open));
    }
    return out;
  }
  Section sub(const std::string& key) {
    const toml::node* n = get(key);
    if (n && !n->is_table()) fail(key, "must be a table");
    return Section(n ? n->as_table() : nullptr, full(key), origin_);
  }
  const toml::array* array_of_tables(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    if (!n->is_array_of_tables()) fail(key, "must be an array of tables ([[" + full(key) + "]])");
    return n->as_array();
  }
  // Every key not read is unknown: name it, and the keys that are allowed.
  void finish() const {
    if (!t_) return;
    for (const auto& [k, v] : *t_) {
      const std::string key(k.str());
      if (!used_.count(key)) {
        std::string allowed;
        for (const auto& u : used_) allowed += (allowed.empty() ? "" : ", ") + u;
        fail(key, "unknown key (allowed here: " + allowed + ")");
      }
    }
  }

 private:
  double check_num(const std::string& key, const toml::node& n, double lo, double hi, bool lo_open) const {
    double v;
    if (auto d = n.value_exact<double>())
      v = *d;
    else if (auto i = n.value_exact<std::int64_t>())
      v = static_cast<double>(*i);
    else
      fail(key, "must be a number");
    if (!std::isfinite(v)) fail(key, "must be finite (got " + std::to_string(v) + ")");
    if (v < lo || v > hi || (lo_open && v == lo)) {
      std::ostringstream msg;
      msg << "out of range: " << v << " not in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
      fail(key, msg.str());
    }
    return v;
  }
  long check_int(const std::string& key, const toml::node& n, long lo, long hi) const {
    auto i = n.value_exact<std::int64_t>();
    if (!i) fail(key, "must be an integer");
    if (*i < lo || *i > hi)
      fail(key, "out of range: " + std::to_string(*i) + " not in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "]");
    return static_cast<long>(*i);
  }

  const toml::table* t_;
  std::string path_, origin_;
  std::set<std::string> used_;
};

// Runs f(); an InputError it throws is re-thrown naming `key` of section s.
template <class F>
auto named(const Section& s, const std::string& key, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    s.fail(key, e.what());
  }
}

// Parses TOML text; a syntax error is an InputError "<origin>: <description> (line N)".
toml::table parse_toml(const std::string& text, const std::string& origin);

}  // namespace dpdrng::study
