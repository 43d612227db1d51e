#include "dpdrng/stats/input.hpp"

#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"

namespace dpdrng::stats {

InputFormat parse_input_format(std::string_view name) {
  if (name == "u64") return InputFormat::u64;
  if (name == "f64") return InputFormat::f64;
  if (name == "text") return InputFormat::text;
  throw InputError("unknown input format '" + std::string(name) + "' (u64, f64 or text)");
}

std::string_view to_string(InputFormat f) {
  switch (f) {
    case InputFormat::u64: return "u64";
    case InputFormat::f64: return "f64";
    case InputFormat::text: return "text";
  }
  return "?";
}

namespace {

// Raw words are little-endian on disk, as `dpdrng gen --format raw` writes them; on a big-endian host a byte
// swap would be needed, so refuse to build there rather than read garbage.
static_assert(std::endian::native == std::endian::little);

// Text where raw words belong (dpdrng gen's default hex lines, a column of numbers): 64 bytes or more, each
// printable ASCII or white space, one of them a line break. Random 64-bit words look so with a probability
// below 10^-26 (a random byte is text with probability 98/256); doubles even less often, their sign-and-exponent
// bytes being mostly outside ASCII.
bool looks_like_text(std::span<const char> bytes) {
  if (bytes.size() < 64) return false;
  bool line = false;
  for (const char c : bytes) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') line = true;
    if (!((u >= 0x20 && u < 0x7f) || c == '\n' || c == '\r' || c == '\t')) return false;
  }
  return line;
}

template <class Word>
std::vector<Word> words_of(std::span<const char> bytes, std::string_view source) {
  if (looks_like_text(bytes))
    throw InputError(std::string(source) +
                     ": the input is text (hex lines of gen without --format raw?), not raw 8-byte values; write "
                     "binary words with gen --format raw, or read one number a line with --format text");
  if (bytes.size() % sizeof(Word) != 0)
    throw InputError(std::string(source) + ": " + std::to_string(bytes.size()) +
                     " bytes is not a whole number of 8-byte words (truncated input?)");
  std::vector<Word> w(bytes.size() / sizeof(Word));
  if (!w.empty()) std::memcpy(w.data(), bytes.data(), bytes.size());
  return w;
}

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<double> parse_text(std::span<const char> bytes, std::string_view source) {
  std::vector<double> out;
  std::string_view rest(bytes.data(), bytes.size());
  for (std::size_t line_no = 1; !rest.empty(); ++line_no) {
    const std::size_t eol = rest.find('\n');
    std::string_view line = trim(rest.substr(0, eol));
    rest = eol == std::string_view::npos ? std::string_view{} : rest.substr(eol + 1);
    if (line.empty() || line.front() == '#') continue;
    // from_chars takes no leading '+', which is harmless to accept.
    std::string_view num = line.front() == '+' ? line.substr(1) : line;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(num.data(), num.data() + num.size(), v);
    if (ec != std::errc{} || end != num.data() + num.size() || !std::isfinite(v))
      throw InputError(std::string(source) + ": line " + std::to_string(line_no) + " is not a finite number: '" +
                       std::string(line.substr(0, 40)) + "'");
    out.push_back(v);
  }
  return out;
}

void check_finite(const std::vector<double>& v, std::string_view source) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw InputError(std::string(source) + ": value " + std::to_string(i) + " is not a finite number");
}

}  // namespace

std::vector<double> decode_values(std::span<const char> bytes, InputFormat format, std::string_view source) {
  std::vector<double> out;
  switch (format) {
    case InputFormat::u64: {
      const auto words = words_of<std::uint64_t>(bytes, source);
      out.reserve(words.size());
      for (const std::uint64_t w : words) out.push_back(rng::to_unit(w));
      break;
    }
    case InputFormat::f64:
      out = words_of<double>(bytes, source);
      check_finite(out, source);
      break;
    case InputFormat::text:
      out = parse_text(bytes, source);
      break;
  }
  if (out.empty()) throw InputError(std::string(source) + ": no values");
  return out;
}

void check_input_path(const std::string& path) {
  if (path == "-") return;
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(st))
    throw InputError("cannot open '" + path + "': " + (ec ? ec.message() : std::string("no such file")));
  if (std::filesystem::is_directory(st)) throw InputError("'" + path + "' is a directory, not an input file");
}

namespace {
struct Bytes {
  std::vector<char> data;
  std::string source;
};

Bytes read_all(const std::string& path) {
  check_input_path(path);
  const bool from_stdin = path == "-";
  const std::string source = from_stdin ? "standard input" : path;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> owned(from_stdin ? nullptr : std::fopen(path.c_str(), "rb"),
                                                       [](std::FILE* f) { return f ? std::fclose(f) : 0; });
  std::FILE* in = from_stdin ? stdin : owned.get();
  if (!in) throw InputError("cannot open '" + path + "': " + std::strerror(errno));
  std::vector<char> bytes;
  std::vector<char> chunk(std::size_t{1} << 20);
  for (;;) {
    const std::size_t got = std::fread(chunk.data(), 1, chunk.size(), in);
    bytes.insert(bytes.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(got));
    if (got < chunk.size()) break;
  }
  if (std::ferror(in)) throw InputError("cannot read " + source);
  return {std::move(bytes), source};
}
}  // namespace

std::vector<double> read_values(const std::string& path, InputFormat format) {
  const Bytes b = read_all(path);
  return decode_values(b.data, format, b.source);
}

std::vector<std::uint64_t> read_words(const std::string& path) {
  const Bytes b = read_all(path);
  auto words = words_of<std::uint64_t>(b.data, b.source);
  if (words.empty()) throw InputError(b.source + ": no values");
  return words;
}

}  // namespace dpdrng::stats
