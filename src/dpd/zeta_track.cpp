#include "dpdrng/dpd/zeta_track.hpp"

#include <algorithm>
#include <cmath>

#include "dpdrng/dpd/neighbours.hpp"

namespace dpdrng::dpd {

ZetaTracker::ZetaTracker(int lags, std::size_t beads, double rc, int stars)
    : lags_(lags), window_(std::max(4 * lags, 20)), rc2_(rc * rc), sum_(std::size_t(lags), 0.0),
      sum2_(std::size_t(lags), 0.0), count_(std::size_t(lags), 0) {
  const std::size_t m = std::min<std::size_t>(std::size_t(std::max(stars, 1)), beads);
  for (std::size_t q = 0; q < m; ++q) stars_.push_back(std::uint32_t(q * beads / m));
  tracks_.resize(2 * m);
}

namespace {

double separation2(const System& s, std::uint32_t i, std::uint32_t j) {
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double dx = min_image(s.x[j] - s.x[i], Lx, Lx / 2), dy = min_image(s.y[j] - s.y[i], Ly, Ly / 2),
               dz = min_image(s.z[j] - s.z[i], Lz, Lz / 2);
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace

// Each star's first two partners inside r_c, in bead order (in the 27 cells around it when the box has a grid).
void ZetaTracker::start_window(const System& s) {
  CellGrid grid;
  if (s.size() > 2000) grid.build(s, std::sqrt(rc2_));
  std::vector<std::uint32_t> found;
  for (std::size_t q = 0; q < stars_.size(); ++q) {
    const std::uint32_t i = stars_[q];
    found.clear();
    auto consider = [&](std::uint32_t j) {
      if (j != i && separation2(s, i, j) < rc2_) found.push_back(j);
    };
    if (grid.usable()) {
      int cells[27];
      grid.stencil(grid.cell_of(s.x[i], s.y[i], s.z[i]), cells);
      for (const int c : cells)
        for (std::uint32_t k = grid.start()[c]; k < grid.start()[c + 1]; ++k) consider(grid.beads()[k]);
      std::sort(found.begin(), found.end());
    } else {
      for (std::uint32_t j = 0; j < s.size() && found.size() < 2; ++j) consider(j);
    }
    for (std::size_t slot = 0; slot < 2; ++slot) {
      Track& t = tracks_[2 * q + slot];
      t.zeta.clear();
      t.alive = slot < found.size();
      if (t.alive) t.i = std::min(i, found[slot]), t.j = std::max(i, found[slot]);
    }
  }
}

void ZetaTracker::add_segment(const std::vector<double>& z) {
  if (z.empty()) return;
  ++segments_;
  for (const double v : z) s0_ += v * v;
  n0_ += z.size();
  for (std::size_t l = 1; l <= std::size_t(lags_) && l < z.size(); ++l)
    for (std::size_t t = 0; t + l < z.size(); ++t) {
      const double p = z[t] * z[t + l];
      sum_[l - 1] += p, sum2_[l - 1] += p * p, ++count_[l - 1];
    }
}

void ZetaTracker::close_window() {
  for (const Track& t : tracks_) add_segment(t.zeta);
}

void ZetaTracker::record(const System& s, const PairForces& pair, std::uint64_t step) {
  if (in_window_ == 0) start_window(s);
  // The tracks still inside r_c, their ζ in one call; a track that left r_c ends its segment here.
  live_.clear(), live_i_.clear(), live_j_.clear();
  for (std::size_t k = 0; k < tracks_.size(); ++k) {
    Track& t = tracks_[k];
    if (!t.alive) continue;
    if (!(separation2(s, t.i, t.j) < rc2_)) {
      t.alive = false;
      continue;
    }
    live_.push_back(k), live_i_.push_back(t.i), live_j_.push_back(t.j);
  }
  live_zeta_.resize(live_.size());
  pair.zetas_of(s, live_i_.data(), live_j_.data(), live_.size(), step, live_zeta_.data());
  double z[2] = {NAN, NAN};
  std::size_t next = 0;
  for (std::size_t k = 0; k < tracks_.size(); ++k) {
    const bool live = next < live_.size() && live_[next] == k;
    z[k % 2] = live ? live_zeta_[next++] : NAN;
    if (live) {
      if (std::isnan(z[k % 2])) {
        unknown_ = true;
        return;
      }
      tracks_[k].zeta.push_back(z[k % 2]);
    }
    if (k % 2 == 1 && tracks_[k - 1].alive && tracks_[k].alive) {
      const double p = z[0] * z[1];
      shared_ += p, shared2_ += p * p, ++shared_n_;
    }
  }
  if (++in_window_ == window_) close_window(), in_window_ = 0;
}

namespace {

// mean(products)/⟨ζ²⟩ with the products' standard error over the same scale (independent products, as they are
// under independent ζ; ⟨ζ²⟩'s own error is second order).
Estimate normalised(double sum, double sum2, std::uint64_t n, double c0) {
  Estimate e;
  e.n = n;
  if (n < 2) {
    e.not_applicable = "fewer than 2 products";
    return e;
  }
  const double m = sum / double(n), var = std::max(0.0, sum2 / double(n) - m * m);
  e.mean = m / c0;
  e.se = std::sqrt(var / double(n - 1)) / c0;
  return e;
}

}  // namespace

ZetaCorrelation ZetaTracker::finish() const {
  ZetaCorrelation out;
  if (unknown_) {
    out.not_applicable = "the pair forces cannot recompute a pair's ζ (the mt19937 stream outside pairs = all)";
    return out;
  }
  // The open window's segments count too.
  ZetaTracker rest = *this;
  rest.close_window();
  out.segments = rest.segments_;
  if (rest.n0_ == 0 || !(rest.s0_ > 0)) {
    out.not_applicable = "no tracked pair stayed inside r_c";
    return out;
  }
  const double c0 = rest.s0_ / double(rest.n0_);
  for (std::size_t l = 0; l < std::size_t(lags_); ++l)
    out.autocorrelation.push_back(normalised(rest.sum_[l], rest.sum2_[l], rest.count_[l], c0));
  out.shared_bead = normalised(rest.shared_, rest.shared2_, rest.shared_n_, c0);
  return out;
}

}  // namespace dpdrng::dpd
