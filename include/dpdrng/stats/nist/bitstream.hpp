#pragma once
// Reading bit streams: ASCII '0'/'1' with white space between them, or raw bytes, most significant bit of each
// byte first; from a file or standard input ("-"). ASCII input holding any other byte (a hex digit, a comment,
// binary data) is refused with its offset: the reference would skip it and test the stray '0'/'1' characters of
// hex text or of a binary file, a mismatch no P-value reveals.
#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "dpdrng/stats/nist/bitseq.hpp"

namespace dpdrng::stats::nist {

enum class BitFormat { ascii, raw };

BitFormat parse_bit_format(std::string_view name);  // throws InputError

// Reads up to max_bits bits (all of the input by default).
BitSequence read_bits(std::istream& in, BitFormat format,
                      std::size_t max_bits = std::numeric_limits<std::size_t>::max());
// path "-" is standard input; throws InputError when the file cannot be opened.
BitSequence read_bits(const std::string& path, BitFormat format,
                      std::size_t max_bits = std::numeric_limits<std::size_t>::max());

// K consecutive streams of N bits (stream i = bits [iN, (i+1)N)), as the reference's --streams/-length split.
// Throws InputError when the input holds fewer than K*N bits.
std::vector<BitSequence> split_streams(const BitSequence& all, std::size_t K, std::size_t N);

}  // namespace dpdrng::stats::nist
