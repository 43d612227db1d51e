#pragma once
// What one cell leaves behind: its status, named scalars (HDF5 attributes), series and matrices (datasets)
// and string lists. Names with '/' become subgroups ("chi2/p" → group chi2, dataset p), so h5py users see a tree.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "dpdrng/study/h5.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng::study {

// How a cell ended. unstable: the run blew up (its observables are null, never 0); disrupted: a lipid left the
// membrane, the run went to the end and its observables are data; failed: a measurement threw (the reason says
// which).
enum class CellStatus { ok, unstable, disrupted, failed };
std::string_view to_string(CellStatus s);
CellStatus parse_cell_status(std::string_view text);  // std::runtime_error for a word not listed above

struct CellResult {
  Cell cell;
  CellStatus status = CellStatus::ok;
  long unstable_step = -1;
  std::string reason;
  double seconds = 0;  // wall time of the whole cell

  std::map<std::string, double> scalars;
  std::map<std::string, std::string> notes;  // e.g. why a measurement is missing or not applicable
  std::map<std::string, std::vector<double>> series;
  std::map<std::string, h5::Matrix> matrices;
  std::map<std::string, std::vector<std::string>> strings;

  double scalar(const std::string& name, double fallback) const {
    auto it = scalars.find(name);
    return it == scalars.end() ? fallback : it->second;
  }
  bool has(const std::string& name) const { return scalars.count(name) > 0; }
  const std::vector<double>* find_series(const std::string& name) const {
    auto it = series.find(name);
    return it == series.end() ? nullptr : &it->second;
  }
};

// The group layout (also what h5py users read): attributes cell.* describe the cell, status/reason/seconds,
// every scalar as an attribute; notes as attributes "note.<name>"; datasets as named.
void write_cell(hid_t group, const CellResult& r);
CellResult read_cell(hid_t group);

}  // namespace dpdrng::study
