// The NIST bit readers (ASCII '0'/'1' text, raw bytes MSB first; the first byte picks the format and a bit
// limit), and the stream split: the bits read are exactly the input's, and in ASCII mode any byte but '0', '1'
// and white space is refused.
#include <cstdint>
#include <sstream>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/stats/nist/bitstream.hpp"
#include "fuzz_check.hpp"

using namespace dpdrng;
using namespace dpdrng::stats::nist;
using fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const BitFormat format = data[0] & 1 ? BitFormat::raw : BitFormat::ascii;
  // Bit limits from none at all to "unlimited", as --streams x --stream-bits sets them.
  const std::size_t limit = data[1] == 255 ? static_cast<std::size_t>(-1) : std::size_t{data[1]} * 7;
  const std::string body(reinterpret_cast<const char*>(data + 2), size - 2);
  std::istringstream in(body);
  BitSequence s;
  try {
    s = read_bits(in, format, limit);
  } catch (const InputError&) {
    require(format == BitFormat::ascii, "raw bytes refused");
    return 0;
  }
  std::string bits;
  if (format == BitFormat::raw) {
    for (const unsigned char c : body)
      for (int b = 7; b >= 0; --b) bits += (c >> b) & 1 ? '1' : '0';
  } else {
    for (const char c : body)
      if (c == '0' || c == '1') bits += c;
    // Read to its end (below the limit), the input held bits and white space alone.
    if (bits.size() < limit)
      for (const char c : body)
        require(c == '0' || c == '1' || c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f',
                "ASCII input with a byte that is neither a bit nor white space accepted");
  }
  if (bits.size() > limit) bits.resize(limit);
  require(s.size() == bits.size(), "bit count differs from the input's");
  for (std::size_t i = 0; i < s.size(); ++i) require(s[i] == (bits[i] == '1'), "a bit differs from the input's");
  const std::size_t K = data[0] / 2 % 7 + 1;
  if (s.size() >= K) {
    const std::size_t N = s.size() / K;
    const auto streams = split_streams(s, K, N);
    require(streams.size() == K, "split_streams gave the wrong number of streams");
    for (std::size_t k = 0; k < K; ++k)
      for (std::size_t i = 0; i < N; ++i) require(streams[k][i] == s[k * N + i], "a stream is not its slice");
  } else {
    try {
      split_streams(s, K, 1);
      fuzz::fail("split_streams accepted too few bits");
    } catch (const InputError&) {
    }
  }
  return 0;
}
