#pragma once
// Checked output: every file and standard-output writer ends here, so that a full disk or a closed device is an
// OutputError naming what could not be written, never a silently truncated result.
#include <filesystem>
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
