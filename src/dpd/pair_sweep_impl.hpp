#pragma once
// PairSweep's member templates (pair_sweep.hpp), for the integrators that instantiate them.
#include <algorithm>
#include <utility>

#include <omp.h>

#include "dpdrng/dpd/pair_sweep.hpp"

namespace dpdrng::dpd {

namespace pair_sweep_detail {

// Colour of a slab along z: its first layer's parity, and 2 for the last layer of an odd count (its slab wraps
// onto layer 0, as the slab at layer 0 does).
inline int colour_of(int layer, int n) { return n % 2 == 1 && layer == n - 1 ? 2 : layer % 2; }

inline constexpr int kColours = 3;

// Half of a cell's 8 neighbours in its layer: with the other half seen from the neighbours, each pair once.
inline constexpr int kInLayer[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};

}  // namespace pair_sweep_detail

template <class Acc, class Visit>
Acc PairSweep::sweep_all_pairs(System& s, Visit& visit) const {
  Acc acc{};
  const std::size_t n = s.size();
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = 0.5 * Lx, hy = 0.5 * Ly, hz = 0.5 * Lz, rc2 = rc_ * rc_;
  double* const v[3] = {s.vx.data(), s.vy.data(), s.vz.data()};
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const double dx = min_image(s.x[j] - s.x[i], Lx, hx), dy = min_image(s.y[j] - s.y[i], Ly, hy),
                   dz = min_image(s.z[j] - s.z[i], Lz, hz);
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < rc2 && r2 > 0) visit(v, i, j, i, j, dx, dy, dz, r2, acc);
    }
  return acc;
}

template <class Acc, class Visit>
void PairSweep::sweep_slab(const Box& box, int layer, Visit& visit, Acc& acc) {
  const double Lx = box.L[0], Ly = box.L[1], Lz = box.L[2];
  const double hx = 0.5 * Lx, hy = 0.5 * Ly, hz = 0.5 * Lz, rc2 = rc_ * rc_;
  double* const v[3] = {vx_.data(), vy_.data(), vz_.data()};
  // Sorted slots a, b of two beads; the pair is (i < j) by bead number, d = r_j − r_i.
  auto pair = [&](std::uint32_t a, std::uint32_t b) {
    if (cell_beads_[a] > cell_beads_[b]) std::swap(a, b);
    const double dx = min_image(px_[b] - px_[a], Lx, hx), dy = min_image(py_[b] - py_[a], Ly, hy),
                 dz = min_image(pz_[b] - pz_[a], Lz, hz);
    const double r2 = dx * dx + dy * dy + dz * dz;
    if (r2 < rc2 && r2 > 0) visit(v, a, b, cell_beads_[a], cell_beads_[b], dx, dy, dz, r2, acc);
  };
  auto cells = [&](std::size_t A, std::size_t B) {
    for (std::uint32_t a = cell_start_[A]; a < cell_start_[A + 1]; ++a)
      for (std::uint32_t b = cell_start_[B]; b < cell_start_[B + 1]; ++b) pair(a, b);
  };
  const int nx = nc_[0], ny = nc_[1], up = (layer + 1) % nc_[2];
  auto cell = [&](int cx, int cy, int cz) {
    return (std::size_t(cz) * ny + (cy + ny) % ny) * nx + (cx + nx) % nx;
  };
  for (int cy = 0; cy < ny; ++cy)
    for (int cx = 0; cx < nx; ++cx) {
      const std::size_t c = cell(cx, cy, layer);
      for (std::uint32_t a = cell_start_[c]; a < cell_start_[c + 1]; ++a)
        for (std::uint32_t b = a + 1; b < cell_start_[c + 1]; ++b) pair(a, b);
      for (const auto& o : pair_sweep_detail::kInLayer) cells(c, cell(cx + o[0], cy + o[1], layer));
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) cells(c, cell(cx + ox, cy + oy, up));
    }
}

template <class Acc, class Visit>
Acc PairSweep::sweep(System& s, bool one_thread, Visit&& visit) {
  if (!build_cells(s)) return sweep_all_pairs<Acc>(s, visit);
  sort_by_cell(s);
  std::vector<std::size_t> colour_start;
  const std::vector<int> order = slab_order(colour_start);
  std::vector<Acc> slab_acc(order.size());
  const int threads = one_thread ? 1 : team_size(threads_);
  const Box box = s.box;
#pragma omp parallel num_threads(threads)
  for (int k = 0; k < pair_sweep_detail::kColours; ++k) {
    if (colour_start[k] == colour_start[k + 1]) continue;  // the same for every thread
    // The implicit barrier at the loop's end keeps colours apart.
#pragma omp for schedule(static)
    for (std::size_t b = colour_start[k]; b < colour_start[k + 1]; ++b) sweep_slab(box, order[b], visit, slab_acc[b]);
  }
  Acc total{};
  for (const Acc& a : slab_acc) total.merge(a);
  const std::size_t n = s.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = cell_beads_[k];
    s.vx[i] = vx_[k], s.vy[i] = vy_[k], s.vz[i] = vz_[k];
  }
  return total;
}

template <class Acc, class Visit>
Acc PairSweep::replay(Visit&& visit) {
  std::vector<Acc> slab_acc(slab_pairs_.size());
  double* const v[3] = {vx_.data(), vy_.data(), vz_.data()};
  const int threads = team_size(threads_);
#pragma omp parallel num_threads(threads)
  for (int k = 0; k < pair_sweep_detail::kColours; ++k) {
    if (colour_start_[k] == colour_start_[k + 1]) continue;  // the same for every thread
#pragma omp for schedule(static)
    for (std::size_t b = colour_start_[k]; b < colour_start_[k + 1]; ++b)
      for (const Pair& p : slab_pairs_[b]) visit(v, p, slab_acc[b]);
  }
  Acc total{};
  for (const Acc& a : slab_acc) total.merge(a);
  return total;
}

}  // namespace dpdrng::dpd
