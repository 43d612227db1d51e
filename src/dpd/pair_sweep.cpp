#include "dpdrng/dpd/pair_sweep.hpp"

#include <numeric>

#include "pair_sweep_impl.hpp"

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

// Slabs in sweep order: colour by colour, each colour's first layers ascending.
std::vector<int> PairSweep::slab_order(std::vector<std::size_t>& colour_start) const {
  const int nz = nc_[2];
  std::vector<int> order;
  colour_start.assign(1, 0);
  for (int k = 0; k < pair_sweep_detail::kColours; ++k) {
    for (int layer = 0; layer < nz; ++layer)
      if (pair_sweep_detail::colour_of(layer, nz) == k) order.push_back(layer);
    colour_start.push_back(order.size());
  }
  return order;
}

namespace {

PairSweep::Pair make_pair(std::uint32_t a, std::uint32_t b, double dx, double dy, double dz, double r2, double rc) {
  const double r = std::sqrt(r2);
  return {a, b, dx / r, dy / r, dz / r, 1.0 - r / rc};
}

}  // namespace

// Fewer than 3 cells a side: one slab of every pair i < j, the identity as cell order, one thread.
void PairSweep::record_all_pairs(const System& s) {
  const std::size_t n = s.size();
  cell_beads_.resize(n);
  std::iota(cell_beads_.begin(), cell_beads_.end(), 0u);
  vx_ = s.vx, vy_ = s.vy, vz_ = s.vz;
  slab_pairs_.assign(1, {});
  colour_start_ = {0, 1, 1, 1};
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = 0.5 * Lx, hy = 0.5 * Ly, hz = 0.5 * Lz, rc2 = rc_ * rc_;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const double dx = min_image(s.x[j] - s.x[i], Lx, hx), dy = min_image(s.y[j] - s.y[i], Ly, hy),
                   dz = min_image(s.z[j] - s.z[i], Lz, hz);
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < rc2 && r2 > 0) slab_pairs_[0].push_back(make_pair(i, j, dx, dy, dz, r2, rc_));
    }
}

void PairSweep::record(const System& s) {
  if (!build_cells(s)) return record_all_pairs(s);
  sort_by_cell(s);
  const std::vector<int> order = slab_order(colour_start_);
  slab_pairs_.resize(order.size());
  const double rc = rc_;
  const auto keep = [rc](double* const(&)[3], std::uint32_t a, std::uint32_t b, std::uint32_t, std::uint32_t,
                         double dx, double dy, double dz, double r2, std::vector<Pair>& out) {
    out.push_back(make_pair(a, b, dx, dy, dz, r2, rc));
  };
  const int threads = team_size(threads_);
  const Box box = s.box;
  // Each slab fills its own list: any team gives the same lists.
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t k = 0; k < order.size(); ++k) {
    slab_pairs_[k].clear();
    sweep_slab(box, order[k], keep, slab_pairs_[k]);
  }
}

void PairSweep::release(System& s) const {
  const std::size_t n = s.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = cell_beads_[k];
    s.vx[i] = vx_[k], s.vy[i] = vy_[k], s.vz[i] = vz_[k];
  }
}

}  // namespace dpdrng::dpd
