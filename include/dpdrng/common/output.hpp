#pragma once
// Checked output: every file and standard-output writer ends here, so that a full disk or a closed device is an
// OutputError naming what could not be written, never a silently truncated result.
#include <filesystem>
#include <cstddef>
#include <initializer_list>
#include <string>

namespace dpdrng {

// Writes `text` to `path` (created or truncated) and closes it; OutputError "<path>: <reason>" on any failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

// Writes `bytes` to a hidden temporary beside `path` (".<name>.tmp<pid>"), syncs it and renames it over `path`:
// after a crash the name points at a complete file or at nothing, and on any failure (a full disk, an I/O
// error) the temporary is removed and OutputError "<path>: <reason>" is thrown. Every file the study layer
// writes, HDF5 files included (built in memory, then handed here), goes through this one path.
void write_file_atomically(const std::filesystem::path& path, const std::string& bytes);
// The hidden temporary name write_file_atomically() uses for `path`.
std::filesystem::path temporary_name(const std::filesystem::path& path);

// A file written piece by piece, for outputs too large to hold in memory, with write_file_atomically()'s promise:
// the pieces go to the hidden temporary, and only commit() (synced, then renamed) puts the file under its name;
// on any failure, and when destroyed uncommitted, the temporary is removed. OutputError "<path>: <reason>".
// Several files that belong together: finish() each (where a full disk shows), then commit() each (renames).
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(const void* data, std::size_t bytes);
  void finish();  // syncs and closes the temporary
  void commit();  // finish() if not done, then the rename
  const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] void fail(int err);
  std::filesystem::path path_, tmp_;
  int fd_ = -1;
  bool settled_ = false;  // renamed, or removed after a failure: nothing left to clean up
};

// Flushes std::cout and stdout; OutputError "standard output: <reason>" if anything written to them was lost
// (a closed pipe is not a loss: its reader has stopped reading).
void flush_standard_output();

// Creates `dir` (and its parents) if needed and checks that files can be created in it, before any work whose
// results would go there; InputError "<what> <dir>: <reason>" (a file in the way, no permission, an empty name).
void prepare_output_directory(const std::filesystem::path& dir, const std::string& what);
// prepare_output_directory(), then checks that each of `files` can be written there: InputError
// "<what> <dir>: <file> exists and is not a regular file" (a directory in the way) or "<file>: cannot write it".
void prepare_output_files(const std::filesystem::path& dir, std::initializer_list<const char*> files,
                          const std::string& what);

}  // namespace dpdrng
