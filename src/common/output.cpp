#include "dpdrng/common/output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>

#include "dpdrng/common/error.hpp"

namespace dpdrng {
namespace fs = std::filesystem;

namespace {

// Every byte through write(2), each call checked; an interrupted or short write goes on from where it stopped.
// Returns 0 or the errno of the first failure (the descriptor is closed either way).
int write_all(int fd, const std::string& bytes, bool sync) {
  std::size_t done = 0;
  int err = 0;
  while (done < bytes.size()) {
    const ssize_t w = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      err = w < 0 ? errno : EIO;
      break;
    }
    done += static_cast<std::size_t>(w);
  }
  if (err == 0 && sync && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  return err;
}

}  // namespace

void write_text_file(const fs::path& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw OutputError(path.string() + ": " + std::strerror(errno));
  if (const int err = write_all(fd, text, false)) throw OutputError(path.string() + ": " + std::strerror(err));
}

fs::path temporary_name(const fs::path& path) {
  // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on the chained operator+ form.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp";
  name += std::to_string(::getpid());
  return path.parent_path() / name;
}

void write_file_atomically(const fs::path& path, const std::string& bytes) {
  const fs::path tmp = temporary_name(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw OutputError(path.string() + ": cannot create " + tmp.filename().string() + ": " +
                                std::strerror(errno));
  int err = write_all(fd, bytes, true);
  if (err == 0 && ::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(tmp.c_str());  // a half-written temporary is no use to anyone
    throw OutputError(path.string() + ": " + std::strerror(err));
  }
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

namespace dpdrng {

void prepare_output_files(const fs::path& dir, std::initializer_list<const char*> files, const std::string& what) {
  prepare_output_directory(dir, what);
  for (const char* name : files) {
    const fs::path p = dir / name;
    std::error_code ec;
    if (!fs::exists(p, ec)) continue;
    if (!fs::is_regular_file(p, ec))
      throw InputError(what + " " + dir.string() + ": " + name + " exists and is not a regular file");
    if (::access(p.c_str(), W_OK) != 0)
      throw InputError(what + " " + dir.string() + ": " + name + ": cannot write it: " + std::strerror(errno));
  }
}

}  // namespace dpdrng
