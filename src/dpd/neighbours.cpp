#include "dpdrng/dpd/neighbours.hpp"

#include <omp.h>

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

void SortedCells::build(const System& s, double rc) {
#pragma omp single
  prepare(s, rc, omp_get_num_threads());
  sort(s);
#pragma omp barrier
}

void SortedCells::sort(const System& s) {
  const std::size_t t = omp_get_thread_num(), nt = omp_get_num_threads();
  const auto [lo, hi] = team_share(s.size(), t, nt);
  count(s, lo, hi, counts_.data() + t * ncell_);
#pragma omp barrier
  places(t, nt);
  std::uint32_t* next = places_.data() + t * ncell_;
  for (std::size_t i = lo; i < hi; ++i) order_[next[cell_[i]]++] = static_cast<std::uint32_t>(i);
}

// The grid for this box, and room for a team of `team` threads.
void SortedCells::prepare(const System& s, double rc, int team) {
  // The smallest counts for which the 13 forward neighbours are distinct cells; z needs an even count so
  // that layers of one colour never write to the same layer.
  constexpr int kMin[3] = {3, 3, 4};
  int n[3];
  bool grid = true;
  for (int d = 0; d < 3; ++d) {
    n[d] = static_cast<int>(std::floor(s.box.L[d] / rc));
    if (d == 2) n[d] -= n[d] % 2;
    grid = grid && n[d] >= kMin[d];
  }
  if (!grid) n[0] = n[1] = n[2] = 1;
  const bool reshaped = n[0] != n_[0] || n[1] != n_[1] || n[2] != n_[2] || builds_ == 0;
  for (int d = 0; d < 3; ++d) n_[d] = n[d], inv_w_[d] = n[d] / s.box.L[d];
  ncell_ = n[0] * n[1] * n[2];
  cell_.resize(s.size());
  order_.resize(s.size());
  start_.resize(std::size_t(ncell_) + 1);
  counts_.resize(std::size_t(team) * ncell_);
  places_.resize(std::size_t(team) * ncell_);
  if (reshaped) fill_forward();
  ++builds_;
}

std::uint32_t SortedCells::cell_index(double x, double y, double z) const {
  // Positions are wrapped into [0, L); the clamps only guard x·n/L rounding to n (or a stray −0).
  int c[3];
  const double r[3] = {x, y, z};
  for (int d = 0; d < 3; ++d) c[d] = std::clamp(static_cast<int>(r[d] * inv_w_[d]), 0, n_[d] - 1);
  return static_cast<std::uint32_t>((c[2] * n_[1] + c[1]) * n_[0] + c[0]);
}

// Cells of beads [lo, hi), and how many of them each cell gets.
void SortedCells::count(const System& s, std::size_t lo, std::size_t hi, std::uint32_t* counts) {
  std::fill(counts, counts + ncell_, 0u);
  for (std::size_t i = lo; i < hi; ++i) {
    cell_[i] = cell_index(s.x[i], s.y[i], s.z[i]);
    ++counts[cell_[i]];
  }
}

// Thread t's first place in each cell: cell by cell, the threads' ranges in order. Every thread sums all the
// counts itself (16 000 additions at 24 000 beads), which spares the team a barrier; thread 0 writes the cell starts.
void SortedCells::places(std::size_t t, std::size_t team) {
  std::uint32_t* mine = places_.data() + t * ncell_;
  std::uint32_t place = 0;
  for (int c = 0; c < ncell_; ++c) {
    if (t == 0) start_[c] = place;
    for (std::size_t u = 0; u < team; ++u) {
      if (u == t) mine[c] = place;
      place += counts_[u * ncell_ + c];
    }
  }
  if (t == 0) start_[ncell_] = place;
}

void SortedCells::fill_forward() {
  forward_.assign(gridded() ? std::size_t(ncell_) * kForward : 0, 0);
  wraps_.assign(std::size_t(ncell_), 1);
  if (!gridded()) return fill_runs();
  // Beads of neighbouring cells lie less than two widths apart (a rounding aside), which with 5 or more cells
  // along an axis is less than the half edge of 2.5 widths or more.
  const bool wide = n_[0] >= 5 && n_[1] >= 5 && n_[2] >= 5;
  for (int c = 0; c < ncell_; ++c) {
    const int cx = c % n_[0], cy = (c / n_[0]) % n_[1], cz = c / (n_[0] * n_[1]);
    const bool inside = cx >= 1 && cx + 1 < n_[0] && cy >= 1 && cy + 1 < n_[1] && cz + 1 < n_[2];
    wraps_[std::size_t(c)] = !(wide && inside);
    std::int32_t* out = forward_.data() + std::size_t(c) * kForward;
    int k = 0;
    for (int dz = 0; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (dz == 0 && (dy < 0 || (dy == 0 && dx <= 0))) continue;
          const int x = (cx + dx + n_[0]) % n_[0], y = (cy + dy + n_[1]) % n_[1], z = (cz + dz) % n_[2];
          out[k++] = (z * n_[1] + y) * n_[0] + x;
        }
  }
  fill_runs();
}

void SortedCells::fill_runs() {
  runs_.assign(std::size_t(ncell_) * (kForward + 1), Run{0, 0});
  run_count_.assign(std::size_t(ncell_), 0);
  const int nf = forward_count();
  for (int c = 0; c < ncell_; ++c) {
    Run* out = runs_.data() + std::size_t(c) * (kForward + 1);
    int k = 0;
    out[k++] = {c, c};
    for (int f = 0; f < nf; ++f) {
      const std::int32_t next = forward(c)[f];
      if (next == out[k - 1].last + 1)
        out[k - 1].last = next;
      else
        out[k++] = {next, next};
    }
    run_count_[std::size_t(c)] = k;
  }
}

}  // namespace dpdrng::dpd
