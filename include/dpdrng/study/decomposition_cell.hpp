#pragma once
// The decomposition sweep's cells in the one cell store (store.hpp), with the sweep's config as
// DIR/decomposition.toml. A cell is one (generator, seeding, distribution): its undecomposed reference run and
// every domain grid's decomposed run, one DecompResult per grid, as the groups /cell/row<k> in the sweep's order.
// Each row's fields are attributes (structures as subgroups: snapshot, decomposed, reference, randomness), numbers
// to the bit (counts as integers); outputs made from stored cells equal those of an unbroken run.
#include <string>
#include <vector>

#include "dpdrng/study/decomposition_run.hpp"
#include "dpdrng/study/store.hpp"

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

// Creates the store's directory for `sweep`, or checks that an existing one was made with the same sweep.
void open_decomp_store(const CellStore& store, const DecompSweep& sweep);
// Whether the cell is missing, stored whole or unreadable (then `reason` says why).
CellStore::State decomp_cell_state(const CellStore& store, const DecompCell& cell, std::string* reason = nullptr);
void save_decomp_cell(const CellStore& store, const DecompCell& cell, const std::vector<DecompResult>& rows);
std::vector<DecompResult> load_decomp_cell(const CellStore& store, const DecompCell& cell);  // runtime_error: why
// Writes DIR/study.h5 from the stored cells (the sweep's name, description, config and hash on its root); returns
// the number of cells in it.
std::size_t assemble_decomp_store(const CellStore& store, const DecompSweep& sweep);

// A cell's record in an HDF5 group, and back (std::runtime_error naming what is missing or of the wrong type);
// read_decomp_rows returns the id of the cell the group holds.
void write_decomp_rows(hid_t group, const std::string& id, const std::vector<DecompResult>& rows);
std::string read_decomp_rows(hid_t group, std::vector<DecompResult>* rows);

}  // namespace dpdrng::study
