#pragma once
// Checked output: every file and standard-output writer ends here, so that a full disk or a closed device is an
// OutputError naming what could not be written, never a silently truncated result.
#include <filesystem>
#include <string>

namespace dpdrng {

// Writes `text` to `path` (created or truncated) and closes it; OutputError "<path>: <reason>" on any failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

// Flushes std::cout and stdout; OutputError "standard output: <reason>" if anything written to them was lost
// (a closed pipe is not a loss: its reader has stopped reading).
void flush_standard_output();

// Creates `dir` (and its parents) if needed and checks that files can be created in it, before any work whose
// results would go there; InputError "<what> <dir>: <reason>" (a file in the way, no permission, an empty name).
void prepare_output_directory(const std::filesystem::path& dir, const std::string& what);

}  // namespace dpdrng
