#include "dpdrng/common/output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <utility>

#include "dpdrng/common/error.hpp"

namespace dpdrng {
namespace fs = std::filesystem;

namespace {

// Every byte through write(2), each call checked; an interrupted or short write goes on from where it stopped.
// Returns 0 or the errno of the first failure.
int write_bytes(int fd, const char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t w = ::write(fd, data + done, size - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return w < 0 ? errno : EIO;
    done += static_cast<std::size_t>(w);
  }
  return 0;
}

// write_bytes(), then the sync if asked; the descriptor is closed either way.
int write_all(int fd, const std::string& bytes, bool sync) {
  int err = write_bytes(fd, bytes.data(), bytes.size());
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
  AtomicFile file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)), tmp_(temporary_name(path_)) {
  fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) throw OutputError(path_.string() + ": cannot create " + tmp_.filename().string() + ": " +
                                 std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (settled_) return;
  if (fd_ >= 0) ::close(fd_);
  ::unlink(tmp_.c_str());  // a half-written temporary is no use to anyone
}

void AtomicFile::fail(int err) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(tmp_.c_str());
  settled_ = true;  // nothing left to remove
  throw OutputError(path_.string() + ": " + std::strerror(err));
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  if (settled_ || fd_ < 0) throw std::logic_error("AtomicFile::write after finish() or commit()");
  if (const int err = write_bytes(fd_, static_cast<const char*>(data), bytes)) fail(err);
}

void AtomicFile::finish() {
  if (fd_ < 0) return;
  int err = ::fsync(fd_) != 0 ? errno : 0;
  if (::close(fd_) != 0 && err == 0) err = errno;
  fd_ = -1;
  if (err != 0) fail(err);
}

void AtomicFile::commit() {
  if (settled_) throw std::logic_error("AtomicFile::commit twice or after a failure");
  finish();
  if (::rename(tmp_.c_str(), path_.c_str()) != 0) fail(errno);
  settled_ = true;
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
