#include "dpdrng/common/output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>

#include "dpdrng/common/error.hpp"

namespace dpdrng {
namespace fs = std::filesystem;

void write_text_file(const fs::path& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw OutputError(path.string() + ": " + std::strerror(errno));
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  int err = written ? 0 : errno;
  if (std::fflush(f) != 0 && err == 0) err = errno;
  if (std::fclose(f) != 0 && err == 0) err = errno;
  if (!written || err != 0) throw OutputError(path.string() + ": " + std::strerror(err ? err : EIO));
}

void flush_standard_output() {
  std::cout.flush();
  const bool stream_ok = static_cast<bool>(std::cout);
  errno = 0;
  const bool stdio_ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
  const int err = errno;
  // A reader that closed the pipe (`| head`) has all it wanted: not a lost result.
  if (stream_ok && (stdio_ok || err == EPIPE)) return;
  // errno belongs to the failed write when this flush made it; an earlier buffered write left only the flag.
  throw OutputError(std::string("standard output: ") + (err ? std::strerror(err) : "part of the output was lost"));
}

void prepare_output_directory(const fs::path& dir, const std::string& what) {
  if (dir.empty()) throw InputError(what + ": an empty path names no directory");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(what + " " + dir.string() + ": exists and is not a directory");
  fs::create_directories(dir, ec);
  if (ec) throw InputError(what + " " + dir.string() + ": cannot create it: " + ec.message());
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(what + " " + dir.string() + ": cannot write in it: " + std::strerror(errno));
}

}  // namespace dpdrng
