#pragma once
// Reading the numbers the χ², t and correlation tests consume: a file or standard input, in one of three formats.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace dpdrng::stats {

enum class InputFormat {
  u64,   // raw little-endian 64-bit words (dpdrng gen --format raw), mapped to [0,1) by rng::to_unit (53 bits)
  f64,   // raw little-endian IEEE-754 doubles, taken as they are
  text,  // one decimal number a line; blank lines and lines starting with '#' are skipped
};

InputFormat parse_input_format(std::string_view name);  // throws InputError naming the formats
std::string_view to_string(InputFormat f);

// Decodes a whole input. Throws InputError for: no values, text given as u64 or f64 (64 bytes or more, all
// printable ASCII or white space with a line break: hex lines of gen without --format raw), a byte count that is
// not a multiple of 8 (u64, f64), a text line that is not exactly one number, and any NaN or infinite value.
// `source` names the input in errors.
std::vector<double> decode_values(std::span<const char> bytes, InputFormat format, std::string_view source);

// Reads `path` ("-" = standard input) completely and decodes it. Throws InputError when it cannot be opened.
std::vector<double> read_values(const std::string& path, InputFormat format);

// Reads `path` ("-" = standard input) as raw little-endian 64-bit words, unmapped (the 2-D χ² takes their
// 32-bit halves). Throws InputError as read_values does.
std::vector<std::uint64_t> read_words(const std::string& path);

// Throws InputError when `path` (not "-") names nothing, a directory or something unreadable, so that every
// input reader says why in the same words.
void check_input_path(const std::string& path);

}  // namespace dpdrng::stats
