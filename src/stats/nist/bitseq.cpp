#include "dpdrng/stats/nist/bitseq.hpp"

#include <bit>

namespace dpdrng::stats::nist {

BitSequence BitSequence::from_bits(std::span<const std::uint8_t> bits) {
  BitSequence s(bits.size());
  for (std::size_t i = 0; i < bits.size(); ++i)
    if (bits[i]) s.words_[i >> 6] |= std::uint64_t{1} << (63 - (i & 63));
  return s;
}

BitSequence BitSequence::from_ascii(std::string_view text) {
  BitSequence s;
  s.words_.reserve(text.size() / 64 + 2);
  for (char c : text)
    if (c == '0' || c == '1') s.push_back(c == '1');
  return s;
}

BitSequence BitSequence::from_bytes(std::span<const std::uint8_t> bytes) {
  BitSequence s(bytes.size() * 8);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    s.words_[i >> 3] |= std::uint64_t{bytes[i]} << (56 - 8 * (i & 7));
  return s;
}

BitSequence BitSequence::from_words_le(std::span<const std::uint64_t> words) {
  // Little-endian bytes in file order, each read MSB first, is exactly the byte-swapped word.
  BitSequence s(words.size() * 64);
  for (std::size_t i = 0; i < words.size(); ++i) s.words_[i] = __builtin_bswap64(words[i]);
  return s;
}

void BitSequence::push_back(bool bit) {
  if ((size_ >> 6) + 2 > words_.size()) words_.push_back(0);
  set(size_, bit);
  ++size_;
}

BitSequence BitSequence::slice(std::size_t start, std::size_t len) const {
  BitSequence s(len);
  for (std::size_t k = 0; k * 64 < len; ++k) s.words_[k] = word_at(start + 64 * k);
  if (len & 63) s.words_[len >> 6] &= ~std::uint64_t{0} << (64 - (len & 63));
  return s;
}

BitSequence BitSequence::wrapped(std::size_t extra) const {
  BitSequence s(size_ + extra);
  for (std::size_t k = 0; k < words_.size() && k < s.words_.size(); ++k) s.words_[k] = words_[k];
  for (std::size_t i = 0; i < extra; ++i) s.set(size_ + i, (*this)[i % size_]);
  return s;
}

std::size_t BitSequence::count_ones() const {
  std::size_t c = 0;
  for (std::uint64_t w : words_) c += static_cast<std::size_t>(std::popcount(w));
  return c;
}

std::size_t BitSequence::count_ones(std::size_t start, std::size_t len) const {
  std::size_t c = 0;
  std::size_t pos = start;
  for (; len >= 64; len -= 64, pos += 64) c += static_cast<std::size_t>(std::popcount(word_at(pos)));
  if (len) c += static_cast<std::size_t>(std::popcount(word_at(pos) >> (64 - len)));
  return c;
}

}  // namespace dpdrng::stats::nist
