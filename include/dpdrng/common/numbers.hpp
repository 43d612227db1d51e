#pragma once
// The one parser for numbers typed by a user (flags, "k/N" shards, comma lists): decimal only ("010" is ten, not
// eight; "0x10" is refused), no silent wrap-around or clamping (2^64 and "-1" for an unsigned are refused), and
// ranges stated in words ("an integer from 1 to 2^64 - 1", "a number within (0, 1)") so that no message echoes a
// 300-digit bound. check_* return the problem in words ("" when the text is fine); parse_* throw InputError
// "<what>: <problem>".
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace dpdrng {

// An integer range [lo, hi]; hi written in words when it is a type's maximum ("2^64 - 1").
struct IntRange {
  std::int64_t lo = std::numeric_limits<std::int64_t>::min();
  std::uint64_t hi = std::numeric_limits<std::uint64_t>::max();
};

// A real range; an infinite bound means "unbounded on that side". NaN and ±inf are always refused.
struct RealRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
};

std::string describe(const IntRange& r);   // "an integer from 1 to 2^64 - 1"
std::string describe(const RealRange& r);  // "a number within (0, 1)", "a number > 0", "a finite number"

// A real as the names of files and ids carry it: printf's %g where that reads back as the same double (0.04,
// 1e-05), otherwise the shortest decimal that does (0.0400000001), so two different values never share a name.
std::string exact_decimal(double x);
// A computed number in a message: printf's %g (6 significant digits; never %f's "-0.000000" or 310 digits).
std::string format_g(double x);

// The text, shortened for a message (a pasted megabyte stays a line).
std::string quote_input(std::string_view text);  // control bytes, quotes and non-UTF-8 as \xNN
// A whole message as it is printed: control bytes (newlines too) and non-UTF-8 as \xNN, so that whatever a
// message echoes from the command line or a file, it stays one line of text.
std::string printable(std::string_view message);

// On success writes the value and returns ""; otherwise returns the problem and leaves the output alone.
std::string check_integer(std::string_view text, const IntRange& range, std::int64_t& out);
std::string check_unsigned(std::string_view text, const IntRange& range, std::uint64_t& out);
std::string check_real(std::string_view text, const RealRange& range, double& out);

// The range of an integer type, optionally narrowed.
template <class T>
IntRange range_of(std::int64_t lo = static_cast<std::int64_t>(std::numeric_limits<T>::min()),
                  std::uint64_t hi = static_cast<std::uint64_t>(std::numeric_limits<T>::max())) {
  return {lo, hi};
}

// Parses into any integer type within `range` ∩ the type's range; throws InputError "<what>: <problem>".
template <class T>
T parse_number(std::string_view text, std::string_view what, IntRange range = range_of<T>());
double parse_real(std::string_view text, std::string_view what, const RealRange& range = {});

// "a,b,c": each entry through parse_number; an empty list or entry is an InputError.
template <class T>
std::vector<T> parse_list(std::string_view text, std::string_view what, IntRange range = range_of<T>()) {
  std::vector<T> out;
  for (;;) {
    const std::size_t comma = text.find(',');
    out.push_back(parse_number<T>(text.substr(0, comma), what, range));
    if (comma == std::string_view::npos) return out;
    text.remove_prefix(comma + 1);
  }
}

}  // namespace dpdrng
