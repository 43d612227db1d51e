// Writes the seed corpus of fuzz_cell_h5: real cell files as Store::save writes them (config hash "fuzz"),
// one with every kind of record (scalars, notes, series in subgroups, a matrix, strings) and one unstable cell.
// Usage: make_cell_seeds DIR  (writes DIR/full.h5 and DIR/unstable.h5, both of cell kCellId of fuzz_cell_h5.cpp)
#include <filesystem>
#include <fstream>
#include <iostream>

#include "dpdrng/study/library_init.hpp"
#include "dpdrng/study/store.hpp"

using namespace dpdrng::study;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_cell_seeds DIR\n";
    return 2;
  }
  init_libraries();
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir / "cells");
  std::ofstream(dir / "config.hash") << "fuzz\n";
  Store store(dir);
  CellResult r;
  r.cell.generator = "tea32";
  r.cell.rounds = 1;
  r.cell.distribution = dpdrng::rng::Distribution::gauss;
  r.cell.seeding = dpdrng::rng::Seeding::distance;
  r.cell.seed = 12345;
  r.seconds = 1.5;
  r.scalars = {{"temperature_mean", 1.02}, {"chi2.x.fraction", 0.99}, {"steps_done", 100}};
  r.notes = {{"nist", "not run"}};
  r.series = {{"msd/tau", {0.0, 0.5, 1.0}}, {"msd/msd", {0.0, 0.1, 0.2}}, {"chi2/x/p", {0.5, 0.25}}};
  r.matrices = {{"corr", dpdrng::study::h5::Matrix{2, 2, {1.0, 0.1, 0.1, 1.0}}}};
  r.strings = {{"names", {"a", "bc"}}};
  store.save(r);
  std::filesystem::rename(store.cell_path(r.cell), dir / "full.h5");
  r.status = CellStatus::unstable;
  r.unstable_step = 3;
  r.reason = "unstable at step 3: temperature runaway";
  r.scalars = {{"steps_done", 3}};
  r.series.clear();
  r.matrices.clear();
  r.strings.clear();
  store.save(r);
  std::filesystem::rename(store.cell_path(r.cell), dir / "unstable.h5");
  return 0;
}
