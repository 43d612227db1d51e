#pragma once
// A packed bit sequence, the input of every SP800-22 test.
//
// Bit i of the sequence is bit (63 - i % 64) of word i / 64: the first bit is the most significant one, so a
// window of m bits starting anywhere reads as an m-bit number with the earliest bit on top, the way the
// reference (sts-2.1.2) forms template and block values. One zero guard word past the end lets the tests read
// 64 bits from any position without bounds checks.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace dpdrng::stats::nist {

class BitSequence {
 public:
  BitSequence() : words_(1, 0) {}
  explicit BitSequence(std::size_t n) : words_(n / 64 + 2, 0), size_(n) {}

  // One element per bit, each 0 or 1 (anything non-zero counts as 1).
  static BitSequence from_bits(std::span<const std::uint8_t> bits);
  // '0' and '1' characters; everything else is skipped, as in the reference's ASCII data files.
  static BitSequence from_ascii(std::string_view text);
  // Bytes in order, most significant bit of each byte first (the reference's binary mode).
  static BitSequence from_bytes(std::span<const std::uint8_t> bytes);
  // The bits of the words written little-endian to a file and read back with from_bytes: what a generator's
  // raw output (`dpdrng gen --format raw`, dieharder -g 200) looks like to the reference suite.
  static BitSequence from_words_le(std::span<const std::uint64_t> words);

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool operator[](std::size_t i) const { return (words_[i >> 6] >> (63 - (i & 63))) & 1u; }
  void set(std::size_t i, bool bit) {
    const std::uint64_t mask = std::uint64_t{1} << (63 - (i & 63));
    words_[i >> 6] = bit ? (words_[i >> 6] | mask) : (words_[i >> 6] & ~mask);
  }
  void push_back(bool bit);

  // 64 bits starting at bit `pos` (first bit on top); bits past the end read as 0. Needs pos <= size().
  std::uint64_t word_at(std::size_t pos) const {
    const std::size_t k = pos >> 6;
    const unsigned s = pos & 63;
    return s == 0 ? words_[k] : (words_[k] << s) | (words_[k + 1] >> (64 - s));
  }
  // The m <= 32 bits starting at `pos` as a number, first bit most significant.
  std::uint32_t bits_at(std::size_t pos, unsigned m) const {
    return static_cast<std::uint32_t>(word_at(pos) >> (64 - m));
  }
  // Packed words (ceil(size/64) of them, unused low bits zero) followed by the guard words.
  std::span<const std::uint64_t> words() const { return words_; }

  // Bits [start, start+len) as a new sequence.
  BitSequence slice(std::size_t start, std::size_t len) const;
  // The sequence followed by its own first `extra` bits: the circular reading used by Serial and ApEn.
  BitSequence wrapped(std::size_t extra) const;

  std::size_t count_ones() const;
  // Ones among bits [start, start+len).
  std::size_t count_ones(std::size_t start, std::size_t len) const;

 private:
  std::vector<std::uint64_t> words_;
  std::size_t size_ = 0;
};

}  // namespace dpdrng::stats::nist
