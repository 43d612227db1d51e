#pragma once
// Linked cells and half Verlet lists. Everything here is built in a fixed order (cells filled by a serial
// counting sort, rows listing neighbour cells in a fixed stencil order and beads in index order), so the pair
// order, and with it the mt19937 reference's slot of every pair, never depends on the thread count.
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

class CellGrid {
 public:
  // Cells at least `rmin` wide. usable() is false when a dimension has fewer than 3 cells (the 27-cell
  // stencil would visit a cell twice); callers then fall back to all pairs.
  void build(const System& s, double rmin);
  bool usable() const { return usable_; }
  int cell_of(double x, double y, double z) const;
  // The 27 cells around (and including) cell c, in a fixed order.
  void stencil(int c, int out[27]) const;
  const std::vector<std::uint32_t>& start() const { return start_; }  // beads of cell c: [start[c], start[c+1])
  const std::vector<std::uint32_t>& beads() const { return beads_; }

 private:
  int n_[3] = {0, 0, 0};
  double inv_w_[3] = {0, 0, 0};
  bool usable_ = false;
  std::vector<std::uint32_t> start_, beads_;
};

// Half list: row i holds the j > i within r_c + skin. Rebuilt when any bead has moved more than skin/2.
class VerletList {
 public:
  double skin = 0.3;
  void build(const System& s, double rc, int threads);
  bool stale(const System& s) const;
  std::size_t rows() const { return offset_.empty() ? 0 : offset_.size() - 1; }
  std::size_t entries() const { return j_.size(); }
  std::uint32_t begin(std::size_t i) const { return offset_[i]; }
  std::uint32_t end(std::size_t i) const { return offset_[i + 1]; }
  const std::uint32_t* j() const { return j_.data(); }
  std::uint64_t builds() const { return builds_; }

 private:
  template <bool Fill>
  std::uint32_t scan_row(const System& s, std::uint32_t i, double rl2, std::uint32_t* out) const;
  CellGrid grid_;
  std::vector<std::uint32_t> offset_, j_;
  std::vector<double> x0_, y0_, z0_;
  std::uint64_t builds_ = 0;
};

}  // namespace dpdrng::dpd
