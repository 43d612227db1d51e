#include "dpdrng/stats/nist/bitstream.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/input.hpp"

namespace dpdrng::stats::nist {

namespace {

// White space: all an ASCII bit string may hold besides its bits. The reference skips every other byte too, so
// that hex digits (dpdrng gen's default output) or binary words would be tested as their stray '0' and '1'
// characters: a format mismatch that no P-value would reveal.
bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; }

// A byte as a message shows it: 'a' when printable, 0x1d otherwise.
std::string shown(char c) {
  constexpr char kDigits[] = "0123456789abcdef";
  const auto u = static_cast<unsigned char>(c);
  if (u > 0x20 && u < 0x7f) return std::string("'") + c + "'";
  return std::string("0x") + kDigits[u >> 4] + kDigits[u & 15];
}

}  // namespace

BitFormat parse_bit_format(std::string_view name) {
  if (name == "ascii") return BitFormat::ascii;
  if (name == "raw") return BitFormat::raw;
  throw InputError("unknown bit format '" + std::string(name) + "' (ascii or raw)");
}

BitSequence read_bits(std::istream& in, BitFormat format, std::size_t max_bits) {
  std::vector<char> buf(std::size_t{1} << 20);
  if (format == BitFormat::raw) {
    std::vector<std::uint8_t> bytes;
    const std::size_t max_bytes = max_bits / 8 + (max_bits % 8 != 0);
    while (bytes.size() < max_bytes && in) {
      in.read(buf.data(), static_cast<std::streamsize>(std::min(buf.size(), max_bytes - bytes.size())));
      bytes.insert(bytes.end(), buf.data(), buf.data() + in.gcount());
    }
    BitSequence all = BitSequence::from_bytes(bytes);
    return all.size() > max_bits ? all.slice(0, max_bits) : all;
  }
  BitSequence s;
  std::size_t offset = 0;
  while (s.size() < max_bits && in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    for (std::streamsize i = 0; i < in.gcount() && s.size() < max_bits; ++i, ++offset) {
      const char c = buf[i];
      if (c == '0' || c == '1')
        s.push_back(c == '1');
      else if (!is_space(c))
        throw InputError("input is not an ASCII bit string: byte " + shown(c) + " at offset " +
                         std::to_string(offset) + "; for binary words (gen --format raw) use --format raw");
    }
  }
  return s;
}

BitSequence read_bits(const std::string& path, BitFormat format, std::size_t max_bits) {
  check_input_path(path);
  if (path == "-") {
    std::ios::sync_with_stdio(false);
    return read_bits(std::cin, format, max_bits);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open '" + path + "'");
  return read_bits(in, format, max_bits);
}

std::vector<BitSequence> split_streams(const BitSequence& all, std::size_t K, std::size_t N) {
  if (K == 0 || N == 0) throw InputError("--streams and --stream-bits must be positive");
  if (all.size() / K < N)
    throw InputError("input has " + std::to_string(all.size()) + " bits, fewer than " + std::to_string(K) + " x " +
                     std::to_string(N) + " = " + std::to_string(K * N));
  std::vector<BitSequence> out;
  out.reserve(K);
  for (std::size_t i = 0; i < K; ++i) out.push_back(all.slice(i * N, N));
  return out;
}

}  // namespace dpdrng::stats::nist
