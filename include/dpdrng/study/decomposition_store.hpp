#pragma once
// The results directory of a decomposition sweep, laid out as the study's (store.hpp):
//   DIR/decomposition.toml  the sweep as given (its canonical hash in DIR/config.hash)
//   DIR/cells/<id>.json     one file per finished cell, written to a temporary name and renamed, so a killed run
//                           leaves either a whole cell or none
// A cell is one (generator, seeding, distribution): its undecomposed reference run and every domain grid's
// decomposed run, one DecompResult per grid. The file holds every field of those rows, numbers to the bit, under
// a checksum of the rows and the config hash; outputs made from stored cells equal those of an unbroken run.
#include <filesystem>
#include <string>
#include <vector>

#include "dpdrng/study/decomposition_run.hpp"

namespace dpdrng::study {

struct DecompSweep;

struct DecompCell {
  rng::GeneratorSpec generator;
  dpd::DecompSeeding seeding;
  rng::Distribution distribution = rng::Distribution::gauss;
  std::string id() const;  // e.g. "tea32-r01-grid16-gauss", a valid file name
};

// Generators, then seedings, then distributions: the order of the sweep's rows, and what shards select from.
std::vector<DecompCell> decomp_cells(const DecompSweep& sweep);

class DecompStore {
 public:
  explicit DecompStore(std::filesystem::path dir) : dir_(std::move(dir)) {}

  // Creates the directory for `sweep`, or checks that an existing one was made with the same sweep.
  void open_for(const DecompSweep& sweep);

  enum class State { missing, stored, unreadable };
  // Whether the cell's file is missing, whole (with this store's config hash), or unreadable (`reason` says why).
  State state(const DecompCell& cell, std::string* reason = nullptr) const;
  void save(const DecompCell& cell, const std::vector<DecompResult>& rows);  // OutputError if it cannot be written
  std::vector<DecompResult> load(const DecompCell& cell) const;  // std::runtime_error with the reason

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path cell_path(const DecompCell& cell) const;

 private:
  std::filesystem::path dir_;
};

// Every field of a row, doubles to the bit (non-finite ones as their bit pattern), and its inverse (throws
// std::runtime_error or nlohmann::json::exception on a malformed record).
nlohmann::json decomp_record(const DecompResult& r);
DecompResult decomp_from_record(const nlohmann::json& j);

}  // namespace dpdrng::study
