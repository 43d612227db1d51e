#pragma once
// Column-wise CSV for the --series outputs of the simulate subcommands.
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "dpdrng/common/output.hpp"

namespace dpdrng::cli {

// Columns of equal length; 17 significant digits so that a double survives the round trip. OutputError if the
// file cannot be written whole.
inline void write_csv(const std::filesystem::path& path, const std::vector<std::string>& head,
                      const std::vector<const std::vector<double>*>& cols) {
  std::ostringstream out;
  for (std::size_t c = 0; c < head.size(); ++c) out << (c ? "," : "") << head[c];
  out << "\n" << std::setprecision(17);
  const std::size_t rows = cols.empty() ? 0 : cols[0]->size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols.size(); ++c) out << (c ? "," : "") << (*cols[c])[r];
    out << "\n";
  }
  write_text_file(path, out.str());
}

}  // namespace dpdrng::cli
