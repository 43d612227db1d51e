#pragma once
// Reading bit streams the way the reference suite does: ASCII '0'/'1' (other text skipped) or raw bytes, most
// significant bit of each byte first; from a file or standard input ("-"). ASCII input holding a byte that is not
// text (a control character other than white space, or >= 0x80) is refused as binary data: the reference would
// test the few stray '0'/'1' bytes of a binary file.
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
