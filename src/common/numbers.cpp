#include "dpdrng/common/numbers.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#include "dpdrng/common/error.hpp"

namespace dpdrng {
namespace {

using i128 = __int128;

// Bounds that are a type's limit read better as powers of two than as 19- or 20-digit numbers.
std::string words(i128 v) {
  if (v == static_cast<i128>(std::numeric_limits<std::uint64_t>::max())) return "2^64 - 1";
  if (v == static_cast<i128>(std::numeric_limits<std::int64_t>::max())) return "2^63 - 1";
  if (v == static_cast<i128>(std::numeric_limits<std::uint32_t>::max())) return "2^32 - 1";
  if (v == static_cast<i128>(std::numeric_limits<std::int32_t>::max())) return "2^31 - 1";
  if (v == static_cast<i128>(std::numeric_limits<std::int64_t>::min())) return "-2^63";
  if (v == static_cast<i128>(std::numeric_limits<std::int32_t>::min())) return "-2^31";
  const bool neg = v < 0;
  auto mag = static_cast<unsigned __int128>(neg ? -v : v);
  std::string s;
  do {
    s.insert(s.begin(), static_cast<char>('0' + static_cast<int>(mag % 10)));
    mag /= 10;
  } while (mag != 0);
  return neg ? "-" + s : s;
}

std::string real_words(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Decimal digits with an optional sign. False when the text is not that; too_big when its magnitude exceeds
// 2^64 - 1 (the digits are still all read, so that "12x" with many digits is "not a decimal integer").
bool decimal(std::string_view text, i128& value, bool& too_big) {
  too_big = false;
  bool neg = false;
  if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
    neg = text.front() == '-';
    text.remove_prefix(1);
  }
  if (text.empty()) return false;
  i128 v = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
    if (!too_big) {
      v = v * 10 + (c - '0');
      too_big = v > static_cast<i128>(std::numeric_limits<std::uint64_t>::max());
    }
  }
  value = neg ? -v : v;
  return true;
}

std::string check_in(std::string_view text, const IntRange& range, i128& out) {
  i128 v = 0;
  bool too_big = false;
  const std::string expected = "expected " + describe(range);
  if (!decimal(text, v, too_big)) return quote_input(text) + " is not a decimal integer: " + expected;
  if (too_big) return quote_input(text) + " is out of range: " + expected;
  if (v < static_cast<i128>(range.lo) || v > static_cast<i128>(range.hi))
    return quote_input(text) + " is out of range: " + expected;
  out = v;
  return "";
}

}  // namespace

std::string describe(const IntRange& r) {
  return "an integer from " + words(r.lo) + " to " + words(static_cast<i128>(r.hi));
}

std::string describe(const RealRange& r) {
  const bool has_lo = std::isfinite(r.lo), has_hi = std::isfinite(r.hi);
  if (has_lo && has_hi)
    return "a number within " + std::string(r.lo_open ? "(" : "[") + real_words(r.lo) + ", " + real_words(r.hi) +
           (r.hi_open ? ")" : "]");
  if (has_lo) return std::string("a number ") + (r.lo_open ? "> " : ">= ") + real_words(r.lo);
  if (has_hi) return std::string("a number ") + (r.hi_open ? "< " : "<= ") + real_words(r.hi);
  return "a finite number";
}

namespace {

// The length of the well-formed UTF-8 sequence of a non-ASCII character at s[i], 0 if there is none.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = static_cast<unsigned char>(s[i]);
  const std::size_t len = b >= 0xc2 && b <= 0xdf ? 2 : b >= 0xe0 && b <= 0xef ? 3 : b >= 0xf0 && b <= 0xf4 ? 4 : 0;
  if (len == 0 || i + len > s.size()) return 0;
  for (std::size_t k = 1; k < len; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return 0;
  return len;
}

// Control characters, NUL and bytes that are not UTF-8 (and, with `quotes`, quotes and backslashes) as \xNN.
std::string escaped(std::string_view text, bool quotes) {
  std::string s;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b >= 0x20 && b < 0x7f && !(quotes && (b == '\'' || b == '\\'))) {
      s += text[i++];
      continue;
    }
    if (const std::size_t len = b >= 0x80 ? utf8_length(text, i) : 0) {
      s.append(text.substr(i, len));
      i += len;
      continue;
    }
    char esc[8];
    std::snprintf(esc, sizeof esc, "\\x%02x", b);
    s += esc;
    ++i;
  }
  return s;
}

}  // namespace

std::string quote_input(std::string_view text) {
  constexpr std::size_t kMax = 24;
  // A message stays one line of text, whatever was typed or read.
  std::string s = "'";
  s += escaped(text.substr(0, kMax), true);
  s += text.size() > kMax ? "...'" : "'";
  return s;
}

std::string printable(std::string_view message) { return escaped(message, false); }

std::string check_integer(std::string_view text, const IntRange& range, std::int64_t& out) {
  IntRange r = range;
  if (r.hi > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    r.hi = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  i128 v = 0;
  std::string problem = check_in(text, r, v);
  if (problem.empty()) out = static_cast<std::int64_t>(v);
  return problem;
}

std::string check_unsigned(std::string_view text, const IntRange& range, std::uint64_t& out) {
  IntRange r = range;
  if (r.lo < 0) r.lo = 0;
  i128 v = 0;
  std::string problem = check_in(text, r, v);
  if (problem.empty()) out = static_cast<std::uint64_t>(v);
  return problem;
}

std::string check_real(std::string_view text, const RealRange& range, double& out) {
  const std::string expected = "expected " + describe(range);
  std::string_view t = text;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || end != t.data() + t.size() || (ec != std::errc{} && ec != std::errc::result_out_of_range))
    return quote_input(text) + " is not a number: " + expected;
  if (ec == std::errc::result_out_of_range) return quote_input(text) + " is beyond the range of a double: " + expected;
  if (!std::isfinite(v)) return quote_input(text) + " is not a finite number: " + expected;
  if (v < range.lo || (range.lo_open && v == range.lo) || v > range.hi || (range.hi_open && v == range.hi))
    return quote_input(text) + " is out of range: " + expected;
  out = v;
  return "";
}

template <class T>
T parse_number(std::string_view text, std::string_view what, IntRange range) {
  const IntRange type = range_of<T>();
  if (range.lo < type.lo) range.lo = type.lo;
  if (range.hi > type.hi) range.hi = type.hi;
  std::string problem;
  T value{};
  if constexpr (std::is_signed_v<T>) {
    std::int64_t v = 0;
    problem = check_integer(text, range, v);
    value = static_cast<T>(v);
  } else {
    std::uint64_t v = 0;
    problem = check_unsigned(text, range, v);
    value = static_cast<T>(v);
  }
  if (!problem.empty()) throw InputError(std::string(what) + ": " + problem);
  return value;
}

template int parse_number<int>(std::string_view, std::string_view, IntRange);
template long parse_number<long>(std::string_view, std::string_view, IntRange);
template long long parse_number<long long>(std::string_view, std::string_view, IntRange);
template unsigned parse_number<unsigned>(std::string_view, std::string_view, IntRange);
template unsigned long parse_number<unsigned long>(std::string_view, std::string_view, IntRange);
template unsigned long long parse_number<unsigned long long>(std::string_view, std::string_view, IntRange);

double parse_real(std::string_view text, std::string_view what, const RealRange& range) {
  double v = 0;
  const std::string problem = check_real(text, range, v);
  if (!problem.empty()) throw InputError(std::string(what) + ": " + problem);
  return v;
}

}  // namespace dpdrng

namespace dpdrng {

std::string format_g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string exact_decimal(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", x);
  if (std::strtod(buf, nullptr) == x) return buf;
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace dpdrng
