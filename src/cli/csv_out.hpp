#pragma once
// Column-wise CSV for the --series outputs of the simulate subcommands.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <vector>

#include "dpdrng/common/error.hpp"

namespace dpdrng::cli {

// Columns of equal length; 17 significant digits so that a double survives the round trip.
inline void write_csv(const std::filesystem::path& path, const std::vector<std::string>& head,
                      const std::vector<const std::vector<double>*>& cols) {
  std::ofstream out(path);
  if (!out) throw InputError("cannot write " + path.string());
  for (std::size_t c = 0; c < head.size(); ++c) out << (c ? "," : "") << head[c];
  out << "\n" << std::setprecision(17);
  const std::size_t rows = cols.empty() ? 0 : cols[0]->size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols.size(); ++c) out << (c ? "," : "") << (*cols[c])[r];
    out << "\n";
  }
  if (!out) throw std::runtime_error("write failed: " + path.string());
}

}  // namespace dpdrng::cli
