#pragma once
// SHA-256 (FIPS 180-4): the identity of a plug-in library, pinned by study configs and stored in each cell.
#include <cstdint>
#include <span>
#include <string>

namespace dpdrng {

// Lower-case hex digest of the bytes.
std::string sha256_hex(std::span<const std::uint8_t> bytes);
// The digest of a file's contents; InputError naming the file when it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace dpdrng
