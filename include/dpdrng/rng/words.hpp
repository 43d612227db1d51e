#pragma once
#include <cstdint>

namespace dpdrng::rng {

constexpr std::uint32_t lo32(std::uint64_t w) { return static_cast<std::uint32_t>(w); }
constexpr std::uint32_t hi32(std::uint64_t w) { return static_cast<std::uint32_t>(w >> 32); }
constexpr std::uint64_t join32(std::uint32_t hi, std::uint32_t lo) {
  return (static_cast<std::uint64_t>(hi) << 32) | lo;
}

}  // namespace dpdrng::rng
