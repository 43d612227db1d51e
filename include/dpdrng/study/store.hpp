#pragma once
// The one store of every sweep kind (the study's cells and the decomposition sweep's): a results directory
//   DIR/<config file>     the config as given (study.toml, decomposition.toml; its canonical hash in
//                         DIR/config.hash)
//   DIR/cells/<id>.h5     one small HDF5 file per finished cell, its record in the group /cell, written to a
//                         temporary name and renamed, so a killed run leaves either a whole cell or none, and
//                         sealed by a checksum of its bytes
//   DIR/study.h5          all cells in one file (/cells/<id>), assembled from cells/
// A store made with one config refuses cells of another: resuming with an edited config would mix results.
// CellStore knows files, checksums and hashes; each sweep kind brings the reader and writer of its record.
#include <filesystem>
#include <functional>
#include <map>
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

// What an assembled store says about itself on its root: the study, the config that made it (as written, in
// canonical form and its hash) and the dpdrng version.
struct StoreIdentity {
  std::string study;
  std::string description;
  std::string config_toml;
  std::string config_canonical_json;
  std::string config_hash;
};

class CellStore {
 public:
  explicit CellStore(std::filesystem::path dir) : dir_(std::move(dir)) {}

  // Reads a record whole from its /cell group and returns the id of the cell it holds; throws
  // std::runtime_error with the reason when the record is not whole.
  using Reader = std::function<std::string(hid_t group)>;
  using Writer = std::function<void(hid_t group)>;

  // Creates the directory, or checks that an existing one was made with the same hash (InputError if not).
  void open(const std::string& config_file, const std::string& source_text, const std::string& hash) const;

  // Whether the cell's file is missing, whole and readable (with this store's config hash), or unreadable (then
  // `reason` says why, in words).
  enum class State { missing, stored, unreadable };
  State state(const std::string& id, const Reader& read, std::string* reason = nullptr) const;
  void save(const std::string& id, const Writer& write) const;  // OutputError when the file cannot be written
  // Checks a cell file (checksum, config hash, the id of its name) and hands its record to `read`; throws
  // std::runtime_error with the reason.
  void read(const std::filesystem::path& file, const Reader& read) const;
  // The cell files present (hidden temporaries left by a killed run excluded), in name order.
  std::vector<std::filesystem::path> files() const;

  // Writes study.h5 atomically: the identity on its root, and a copy of every whole cell of this config under
  // /cells/<id>, with the units of the cells' scalars under /units; returns the number of cells in it.
  std::size_t assemble(const StoreIdentity& identity, const Reader& read) const;
  // Copies the cells of `other` that this store lacks; both must hold the same config. A cell file that is
  // unreadable or filed under another cell's name is not copied (listed in *refused when given).
  std::size_t merge_from(const CellStore& other, const Reader& read, std::vector<UnreadableCell>* refused) const;

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path cell_path(const std::string& id) const { return dir_ / "cells" / (id + ".h5"); }
  std::filesystem::path study_file() const { return dir_ / "study.h5"; }
  std::string hash() const;  // "" when the directory has none

 private:
  std::filesystem::path dir_;
};

// The study's cells (CellResult records) in a CellStore.
class Store {
 public:
  explicit Store(std::filesystem::path dir) : cells_(std::move(dir)) {}

  // Creates the directory for `config`, or checks that an existing one was made with the same config.
  void open_for(const StudyConfig& config);
  // Reads the config stored in the directory (for merge and report).
  StudyConfig stored_config() const;

  using State = CellStore::State;
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

  const std::filesystem::path& dir() const { return cells_.dir(); }
  std::filesystem::path cell_path(const Cell& cell) const { return cells_.cell_path(cell.id()); }
  std::filesystem::path study_file() const { return cells_.study_file(); }

 private:
  CellStore cells_;
};

// A cell file's bytes; std::runtime_error("cannot open it") when it cannot be read (the reason an unreadable cell
// is listed with).
std::string read_whole_file(const std::filesystem::path& p);

}  // namespace dpdrng::study
