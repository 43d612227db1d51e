#include "dpdrng/dpd/neighbours.hpp"

#include <algorithm>
#include <cmath>

namespace dpdrng::dpd {

void CellGrid::build(const System& s, double rmin) {
  usable_ = true;
  for (int d = 0; d < 3; ++d) {
    n_[d] = std::max(1, static_cast<int>(std::floor(s.box.L[d] / rmin)));
    inv_w_[d] = n_[d] / s.box.L[d];
    if (n_[d] < 3) usable_ = false;
  }
  if (!usable_) return;
  const std::size_t ncell = std::size_t(n_[0]) * n_[1] * n_[2];
  start_.assign(ncell + 1, 0);
  beads_.resize(s.size());
  std::vector<std::uint32_t> cell(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    cell[i] = static_cast<std::uint32_t>(cell_of(s.x[i], s.y[i], s.z[i]));
    ++start_[cell[i] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < s.size(); ++i) beads_[fill[cell[i]]++] = static_cast<std::uint32_t>(i);
}

int CellGrid::cell_of(double x, double y, double z) const {
  // Positions are wrapped into [0, L); the clamp only guards x·n/L rounding up to n.
  const int cx = std::min(n_[0] - 1, static_cast<int>(x * inv_w_[0]));
  const int cy = std::min(n_[1] - 1, static_cast<int>(y * inv_w_[1]));
  const int cz = std::min(n_[2] - 1, static_cast<int>(z * inv_w_[2]));
  return (cz * n_[1] + cy) * n_[0] + cx;
}

void CellGrid::stencil(int c, int out[27]) const {
  const int cx = c % n_[0], cy = (c / n_[0]) % n_[1], cz = c / (n_[0] * n_[1]);
  int k = 0;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = (cx + dx + n_[0]) % n_[0], y = (cy + dy + n_[1]) % n_[1], z = (cz + dz + n_[2]) % n_[2];
        out[k++] = (z * n_[1] + y) * n_[0] + x;
      }
}

template <bool Fill>
std::uint32_t VerletList::scan_row(const System& s, std::uint32_t i, double rl2, std::uint32_t* out) const {
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = Lx / 2, hy = Ly / 2, hz = Lz / 2;
  const double xi = s.x[i], yi = s.y[i], zi = s.z[i];
  std::uint32_t n = 0;
  auto consider = [&](std::uint32_t j) {
    const double dx = min_image(s.x[j] - xi, Lx, hx), dy = min_image(s.y[j] - yi, Ly, hy),
                 dz = min_image(s.z[j] - zi, Lz, hz);
    if (dx * dx + dy * dy + dz * dz < rl2) {
      if constexpr (Fill) out[n] = j;
      ++n;
    }
  };
  if (!grid_.usable()) {
    for (std::uint32_t j = i + 1; j < s.size(); ++j) consider(j);
    return n;
  }
  int cells[27];
  grid_.stencil(grid_.cell_of(xi, yi, zi), cells);
  const auto& start = grid_.start();
  const auto& beads = grid_.beads();
  for (int c : cells)
    for (std::uint32_t k = start[c]; k < start[c + 1]; ++k)
      if (beads[k] > i) consider(beads[k]);
  return n;
}

void VerletList::build(const System& s, double rc, int threads) {
  const double rl = rc + skin;
  grid_.build(s, rl);
  const std::size_t n = s.size();
  offset_.assign(n + 1, 0);
  const double rl2 = rl * rl;
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] = scan_row<false>(s, std::uint32_t(i), rl2, nullptr);
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] += offset_[i];
  j_.resize(offset_[n]);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) scan_row<true>(s, std::uint32_t(i), rl2, j_.data() + offset_[i]);
  x0_ = s.x;
  y0_ = s.y;
  z0_ = s.z;
  ++builds_;
}

bool VerletList::stale(const System& s) const {
  if (x0_.size() != s.size()) return true;
  const double lim2 = 0.25 * skin * skin;
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double dx = min_image(s.x[i] - x0_[i], Lx, Lx / 2), dy = min_image(s.y[i] - y0_[i], Ly, Ly / 2),
                 dz = min_image(s.z[i] - z0_[i], Lz, Lz / 2);
    if (dx * dx + dy * dy + dz * dz > lim2) return true;
  }
  return false;
}

}  // namespace dpdrng::dpd
