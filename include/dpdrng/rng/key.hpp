#pragma once
// The 128-bit key every keyed hash takes (TEA's four words; the other families read their key from it), apart
// from the generators so that naming a key does not compile one.
#include <array>
#include <cstdint>

namespace dpdrng::rng {

using TeaKey = std::array<std::uint32_t, 4>;
inline constexpr TeaKey kPaperTeaKey{3, 4, 5, 6};

}  // namespace dpdrng::rng
