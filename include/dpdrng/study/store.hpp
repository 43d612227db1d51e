#pragma once
// The results directory of one study:
//   DIR/study.toml        the config as given (its canonical hash in DIR/config.hash)
//   DIR/cells/<id>.h5     one small file per finished cell, written to a temporary name and renamed, so a
//                         killed run leaves either a whole cell or none
//   DIR/study.h5          all cells in one file (/cells/<id>), assembled from cells/ by run, merge and report
// A store made with one config refuses cells of another: resuming with an edited config would mix results.
#include <filesystem>
#include <string>
#include <vector>

#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study {

// A cell file that exists but cannot be used: truncated, garbage, written by another config, or missing a field.
struct UnreadableCell {
  std::filesystem::path file;
  std::string reason;
};

class Store {
 public:
  explicit Store(std::filesystem::path dir) : dir_(std::move(dir)) {}

  // Creates the directory for `config`, or checks that an existing one was made with the same config.
  void open_for(const StudyConfig& config);
  // Reads the config stored in the directory (for merge and report).
  StudyConfig stored_config() const;

  // Whether the cell's file is missing, whole and readable (with this store's config hash), or unreadable (then
  // `reason` says why, in words).
  enum class State { missing, stored, unreadable };
  State state(const Cell& cell, std::string* reason = nullptr) const;
  bool has(const Cell& cell) const { return state(cell) == State::stored; }
  void save(const CellResult& result);  // OutputError when the file cannot be written
  CellResult load(const Cell& cell) const;
  // Every readable cell file, in id order; the others are listed in *unreadable when given.
  std::vector<CellResult> load_all(std::vector<UnreadableCell>* unreadable = nullptr) const;

  // Writes study.h5 atomically from the cell files present; returns the number of cells in it.
  std::size_t assemble(const StudyConfig& config) const;

  // Copies the cells of `other` that this store lacks; both must hold the same config. A cell file that is
  // unreadable or filed under another cell's name is not copied (listed in *refused when given).
  std::size_t merge_from(const Store& other, std::vector<UnreadableCell>* refused = nullptr);

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path cell_path(const Cell& cell) const;
  std::filesystem::path study_file() const { return dir_ / "study.h5"; }

 private:
  std::string stored_hash() const;
  std::filesystem::path dir_;
};

// A cell file's bytes; std::runtime_error("cannot open it") when it cannot be read (the reason an unreadable cell
// is listed with).
std::string read_whole_file(const std::filesystem::path& p);

// The directory layout every store shares: dir/cells/, the config's text as dir/<config_file> and its hash in
// dir/config.hash. Creates it, or checks that an existing one was made with the same hash (InputError if not).
void open_store_directory(const std::filesystem::path& dir, const std::string& config_file,
                          const std::string& source_text, const std::string& hash);
std::string read_store_hash(const std::filesystem::path& dir);  // "" when the directory has none

}  // namespace dpdrng::study
