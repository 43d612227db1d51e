#include "dpdrng/dpd/pair_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace dpdrng::dpd {

namespace {

// Cell index along one axis; positions are wrapped into [0, L), the clamps only guard rounding.
int cell_along(double x, double inv_w, int n) {
  const double t = x * inv_w;
  if (!(t >= 0)) return 0;
  return std::min(n - 1, static_cast<int>(t));
}

}  // namespace

bool PairSweep::build_cells(const System& s) {
  const std::size_t n = s.size();
  std::size_t ncell = 1;
  double inv_w[3];
  for (int d = 0; d < 3; ++d) {
    nc_[d] = static_cast<int>(std::floor(s.box.L[d] / rc_));
    inv_w[d] = nc_[d] / s.box.L[d];
    ncell *= static_cast<std::size_t>(std::max(nc_[d], 1));
  }
  if (std::min({nc_[0], nc_[1], nc_[2]}) < 3) return false;  // fewer than 3 cells: the 27-cell stencil repeats cells
  cell_start_.assign(ncell + 1, 0);
  bead_cell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int cx = cell_along(s.x[i], inv_w[0], nc_[0]), cy = cell_along(s.y[i], inv_w[1], nc_[1]),
              cz = cell_along(s.z[i], inv_w[2], nc_[2]);
    bead_cell_[i] = static_cast<std::uint32_t>((cz * nc_[1] + cy) * nc_[0] + cx);
    ++cell_start_[bead_cell_[i] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_beads_.resize(n);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) cell_beads_[fill[bead_cell_[i]]++] = static_cast<std::uint32_t>(i);
  return true;
}

void PairSweep::sort_by_cell(const System& s) {
  const std::size_t n = s.size();
  for (auto* a : {&px_, &py_, &pz_, &vx_, &vy_, &vz_}) a->resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = cell_beads_[k];
    px_[k] = s.x[i], py_[k] = s.y[i], pz_[k] = s.z[i];
    vx_[k] = s.vx[i], vy_[k] = s.vy[i], vz_[k] = s.vz[i];
  }
}

}  // namespace dpdrng::dpd
