#include "dpdrng/dpd/observables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dpdrng/dpd/neighbours.hpp"

namespace dpdrng::dpd {

void VelocityHistogram::sample(const System& s) {
  const std::vector<double>* v[3] = {&s.vx, &s.vy, &s.vz};
  for (int c = 0; c < 3; ++c)
    for (double u : *v[c]) {
      const double b = std::floor((u - lo_) / w_);
      if (b >= 0 && b < bins_) ++counts_[c][static_cast<std::size_t>(b)];
    }
  samples_ += s.size();
}

VelocityPdf VelocityHistogram::finish(double kT, double measured_kT) const {
  VelocityPdf out;
  out.samples = samples_;
  if (samples_ == 0) return out;
  // Bin-averaged MB density: the exact probability of the bin over its width (no midpoint error).
  auto mb = [&](double a, double b, double t) {
    const double k = 1.0 / std::sqrt(2.0 * t);
    return 0.5 * (std::erfc(a * k) - std::erfc(b * k)) / w_;
  };
  for (int b = 0; b < bins_; ++b) {
    const double a = lo_ + b * w_, e = a + w_;
    out.v.push_back(a + 0.5 * w_);
    out.mb_kT.push_back(mb(a, e, kT));
    out.mb_measured.push_back(mb(a, e, measured_kT));
  }
  double pooled_kT = 0, pooled_meas = 0;
  for (int c = 0; c < 3; ++c) {
    double sum_kT = 0, sum_meas = 0;
    int used = 0;
    for (int b = 0; b < bins_; ++b) {
      const double p = counts_[c][b] / (double(samples_) * w_);
      out.pdf[c].push_back(p);
      if (out.mb_kT[b] * w_ < 1e-3) continue;
      sum_kT += std::abs(p - out.mb_kT[b]) / out.mb_kT[b];
      sum_meas += std::abs(p - out.mb_measured[b]) / out.mb_measured[b];
      ++used;
    }
    out.error_rate_kT[c] = used ? sum_kT / used : 0;
    out.error_rate_measured[c] = used ? sum_meas / used : 0;
    pooled_kT += out.error_rate_kT[c] / 3;
    pooled_meas += out.error_rate_measured[c] / 3;
  }
  out.error_rate_kT_mean = pooled_kT;
  out.error_rate_measured_mean = pooled_meas;
  return out;
}

void MsdRecorder::sample(const System& s) {
  if (frames_.size() >= max_samples_) return;
  std::vector<double> f(3 * n_);
  for (std::size_t i = 0; i < n_; ++i) {
    f[3 * i] = s.x[i] + s.ix[i] * s.box.L[0];
    f[3 * i + 1] = s.y[i] + s.iy[i] * s.box.L[1];
    f[3 * i + 2] = s.z[i] + s.iz[i] * s.box.L[2];
  }
  frames_.push_back(std::move(f));
}

namespace {
// Least-squares slope of y against x over [lo, hi).
double slope(const std::vector<double>& x, const std::vector<double>& y, std::size_t lo, std::size_t hi) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = double(hi - lo);
  for (std::size_t k = lo; k < hi; ++k) sx += x[k], sy += y[k], sxx += x[k] * x[k], sxy += x[k] * y[k];
  const double den = m * sxx - sx * sx;
  return den > 0 ? (m * sxy - sx * sy) / den : 0.0;
}
}  // namespace

Msd MsdRecorder::finish() const {
  Msd out;
  const std::size_t nf = frames_.size();
  if (nf < 8) return out;
  const std::size_t lmax = nf / 2;
  // Every frame up to 400 origins; origins fall into 4 quarters for an error estimate of D.
  const std::size_t stride = std::max<std::size_t>(1, (nf - 1) / 400);
  std::vector<double> sum(lmax + 1, 0), qsum[4];
  std::vector<std::size_t> cnt(lmax + 1, 0), qcnt[4];
  for (int q = 0; q < 4; ++q) qsum[q].assign(lmax + 1, 0), qcnt[q].assign(lmax + 1, 0);
  const std::size_t norigins = (nf - 1) / stride + 1;
  for (std::size_t o = 0; o < norigins; ++o) {
    const std::size_t t0 = o * stride;
    const int q = static_cast<int>(4 * o / norigins);
    const auto& a = frames_[t0];
    for (std::size_t l = 1; l <= lmax && t0 + l < nf; ++l) {
      const auto& b = frames_[t0 + l];
      double d2 = 0;
      for (std::size_t k = 0; k < 3 * n_; ++k) d2 += (b[k] - a[k]) * (b[k] - a[k]);
      d2 /= double(n_);
      sum[l] += d2, ++cnt[l];
      qsum[q][l] += d2, ++qcnt[q][l];
    }
  }
  out.tau.push_back(0), out.msd.push_back(0);
  for (std::size_t l = 1; l <= lmax; ++l) {
    out.tau.push_back(l * interval_);
    out.msd.push_back(cnt[l] ? sum[l] / cnt[l] : 0);
  }
  // The diffusive regime: past the ballistic start (first 10 % of the lags), up to half the trajectory.
  const std::size_t lo = std::max<std::size_t>(1, lmax / 10), hi = lmax + 1;
  out.fit_from = out.tau[lo], out.fit_to = out.tau[lmax];
  out.diffusion = slope(out.tau, out.msd, lo, hi) / 6.0;
  double m = 0, m2 = 0;
  int used = 0;
  for (int q = 0; q < 4; ++q) {
    std::vector<double> y(lmax + 1, 0);
    bool full = true;
    for (std::size_t l = lo; l <= lmax; ++l) {
      if (!qcnt[q][l]) full = false;
      y[l] = qcnt[q][l] ? qsum[q][l] / qcnt[q][l] : 0;
    }
    if (!full) continue;
    const double d = slope(out.tau, y, lo, hi) / 6.0;
    m += d, m2 += d * d, ++used;
  }
  if (used > 1) {
    m /= used;
    out.diffusion_sem = std::sqrt(std::max(0.0, (m2 / used - m * m) * used / (used - 1)) / used);
  }
  return out;
}

namespace {
// Partners j > i of bead i: those in the 27 cells around it, or every later bead when there is no grid.
template <class F>
void for_partners(const System& s, const CellGrid& grid, std::size_t i, F&& f) {
  if (!grid.usable()) {
    for (std::size_t j = i + 1; j < s.size(); ++j) f(j);
    return;
  }
  int cells[27];
  grid.stencil(grid.cell_of(s.x[i], s.y[i], s.z[i]), cells);
  for (int c : cells)
    for (std::uint32_t k = grid.start()[c]; k < grid.start()[c + 1]; ++k)
      if (grid.beads()[k] > i) f(grid.beads()[k]);
}
}  // namespace

void RdfHistogram::sample(const System& s) {
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double r2max = rmax_ * rmax_, inv_dr = bins_ / rmax_;
  CellGrid grid;
  if (s.size() > 2000) grid.build(s, rmax_);
  const std::int64_t n = static_cast<std::int64_t>(s.size());
#pragma omp parallel num_threads(threads_) if (grid.usable())
  {
    std::vector<std::uint64_t> mine(counts_.size(), 0);
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t q = 0; q < n; ++q) {
      const std::size_t i = static_cast<std::size_t>(q);
      for_partners(s, grid, i, [&](std::size_t j) {
        const double dx = min_image(s.x[j] - s.x[i], Lx, Lx / 2), dy = min_image(s.y[j] - s.y[i], Ly, Ly / 2),
                     dz = min_image(s.z[j] - s.z[i], Lz, Lz / 2);
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 < r2max) ++mine[std::min<std::size_t>(bins_ - 1, std::size_t(std::sqrt(r2) * inv_dr))];
      });
    }
#pragma omp critical(dpdrng_rdf)
    for (std::size_t b = 0; b < mine.size(); ++b) counts_[b] += mine[b];
  }
  ++samples_;
}

Rdf RdfHistogram::finish(const System& s) const {
  Rdf out;
  out.samples = samples_;
  if (samples_ == 0) return out;
  const double n = double(s.size()), dr = rmax_ / bins_;
  const double pair_density = n * (n - 1) / 2 / s.box.volume();
  for (int b = 0; b < bins_; ++b) {
    const double r0 = b * dr, r1 = r0 + dr;
    const double shell = 4.0 / 3.0 * std::numbers::pi * (r1 * r1 * r1 - r0 * r0 * r0);
    out.r.push_back(r0 + 0.5 * dr);
    out.g.push_back(counts_[b] / (samples_ * pair_density * shell));
  }
  return out;
}

}  // namespace dpdrng::dpd
