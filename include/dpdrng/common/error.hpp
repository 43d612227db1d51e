#pragma once
// Exit-code contract: 0 = ran (pass or fail is data), 2 = bad input, 1 = internal error.
#include <stdexcept>
#include <string>

namespace dpdrng {

// Thrown for anything the user can fix: bad arguments, malformed or short input, invalid configs.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown when output cannot be written (a full disk, /dev/full, a vanished directory): results would be lost, so
// the command fails with "write error: <what>" and exit code 1.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;

}  // namespace dpdrng
