#include "dpdrng/dpd/observables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dpdrng/common/numbers.hpp"
#include "dpdrng/dpd/line_fit.hpp"
#include "dpdrng/dpd/neighbours.hpp"

namespace dpdrng::dpd {

void VelocityHistogram::sample(const System& s, int block) {
  const std::vector<double>* v[3] = {&s.vx, &s.vy, &s.vz};
  for (int c = 0; c < 3; ++c) {
    auto& counts = counts_[std::size_t(block) * 3 + std::size_t(c)];
    for (double u : *v[c]) {
      const double b = std::floor((u - lo_) / w_);
      if (b >= 0 && b < bins_) ++counts[static_cast<std::size_t>(b)];
    }
  }
  block_samples_[std::size_t(block)] += s.size();
}

namespace {

// The paper's error rate, the mean of |P − P_th| / P_th over the bins where MB at k_BT (mb_kT) has probability
// mass ≥ 1e-3, per component and pooled, of densities P = counts / (samples · w) against the bin-averaged MB
// densities mb.
struct ErrorRates {
  std::array<double, 3> per_component{};
  double pooled = 0;
};
ErrorRates error_rates(const std::array<std::vector<double>, 3>& pdf, const std::vector<double>& mb,
                       const std::vector<double>& mb_kT, double w) {
  ErrorRates e;
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    int used = 0;
    for (std::size_t b = 0; b < mb.size(); ++b) {
      if (mb_kT[b] * w < 1e-3) continue;
      sum += std::abs(pdf[c][b] - mb[b]) / mb[b];
      ++used;
    }
    // No bin to average over, or a bin where the reference density vanishes (a fluid frozen far below k_BT has
    // all its Maxwell–Boltzmann mass inside one bin): the rate has no value.
    e.per_component[c] = used && std::isfinite(sum) ? sum / used : NAN;
    e.pooled += e.per_component[c] / 3;
  }
  return e;
}

std::array<std::vector<double>, 3> densities(const std::array<std::vector<std::uint64_t>, 3>& counts,
                                             std::size_t samples, double w) {
  std::array<std::vector<double>, 3> pdf;
  for (int c = 0; c < 3; ++c)
    for (const std::uint64_t n : counts[c]) pdf[c].push_back(n / (double(samples) * w));
  return pdf;
}

}  // namespace

VelocityPdf VelocityHistogram::finish(double kT, double measured_kT) const {
  VelocityPdf out;
  std::array<std::vector<std::uint64_t>, 3> total;
  for (auto& t : total) t.assign(std::size_t(bins_), 0);
  std::size_t samples = 0;
  for (std::size_t blk = 0; blk < std::size_t(blocks_); ++blk) {
    samples += block_samples_[blk];
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t b = 0; b < std::size_t(bins_); ++b) total[c][b] += counts_[blk * 3 + c][b];
  }
  out.samples = samples;
  if (samples == 0) return out;
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
  out.pdf = densities(total, samples, w_);
  const ErrorRates at_kT = error_rates(out.pdf, out.mb_kT, out.mb_kT, w_);
  const ErrorRates at_measured = error_rates(out.pdf, out.mb_measured, out.mb_kT, w_);
  out.error_rate_kT = at_kT.per_component;
  out.error_rate_measured = at_measured.per_component;
  out.error_rate_kT_mean = at_kT.pooled;
  out.error_rate_measured_mean = at_measured.pooled;
  if (!std::isfinite(at_measured.pooled))
    out.measured_not_applicable = "the Maxwell-Boltzmann density at the measured k_BT (" + format_g(measured_kT) +
                                  ") vanishes in bins the rate averages over";
  jackknife(total, samples, out);
  return out;
}

// Leave-one-block-out error rates (var = (B − 1)/B Σ (θ_b − θ̄)² over the B blocks that hold samples) and the
// pooled density of each leave-one-block-out histogram.
void VelocityHistogram::jackknife(const std::array<std::vector<std::uint64_t>, 3>& total, std::size_t samples,
                                  VelocityPdf& out) const {
  std::vector<double> theta;
  for (std::size_t blk = 0; blk < std::size_t(blocks_); ++blk) {
    if (block_samples_[blk] == 0 || block_samples_[blk] == samples) continue;
    auto rest = total;
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t b = 0; b < std::size_t(bins_); ++b) rest[c][b] -= counts_[blk * 3 + c][b];
    const auto pdf = densities(rest, samples - block_samples_[blk], w_);
    theta.push_back(error_rates(pdf, out.mb_kT, out.mb_kT, w_).pooled);
    std::vector<double> pooled(pdf[0].size());
    for (std::size_t k = 0; k < pooled.size(); ++k) pooled[k] = (pdf[0][k] + pdf[1][k] + pdf[2][k]) / 3.0;
    out.jackknife.push_back(std::move(pooled));
  }
  out.error_rate_kT_mean_sem_dof = double(theta.size()) - 1.0;
  if (theta.size() < 2) {
    out.error_rate_kT_mean_sem = NAN;
    return;
  }
  double m = 0, v = 0;
  for (const double t : theta) m += t / double(theta.size());
  for (const double t : theta) v += (t - m) * (t - m);
  out.error_rate_kT_mean_sem = std::sqrt(v * double(theta.size() - 1) / double(theta.size()));
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
  return fit_line(std::span(x).subspan(lo, hi - lo), std::span(y).subspan(lo, hi - lo)).slope;
}
}  // namespace

Msd MsdRecorder::finish() const {
  Msd out;
  const std::size_t nf = frames_.size();
  if (nf < 8) {
    out.not_applicable = "fewer than 8 MSD frames (" + std::to_string(nf) + " sampled; a longer run or a smaller "
                         "--sample-every gives more)";
    return out;
  }
  const std::size_t lmax = nf / 2;
  // Every frame up to 400 origins. The beads fall into kStatBlocks groups; leaving one group out at a time
  // gives D a jackknife error, and the MSD curve a jackknife covariance.
  const std::size_t stride = std::max<std::size_t>(1, (nf - 1) / 400);
  const std::size_t groups = std::min(kStatBlocks, n_);
  std::vector<std::size_t> first(groups + 1);
  for (std::size_t g = 0; g <= groups; ++g) first[g] = g * n_ / groups;
  std::vector<double> sum(lmax + 1, 0), raw(lmax + 1, 0);
  std::vector<std::vector<double>> gsum(groups, std::vector<double>(lmax + 1, 0));
  std::vector<std::size_t> cnt(lmax + 1, 0);
  const std::size_t norigins = (nf - 1) / stride + 1;
  for (std::size_t o = 0; o < norigins; ++o) {
    const std::size_t t0 = o * stride;
    const auto& a = frames_[t0];
    for (std::size_t l = 1; l <= lmax && t0 + l < nf; ++l) {
      const auto& b = frames_[t0 + l];
      double d2 = 0;
      for (std::size_t g = 0; g < groups; ++g) {
        double dg = 0;
        for (std::size_t k = 3 * first[g]; k < 3 * first[g + 1]; ++k) {
          const double x = (b[k] - a[k]) * (b[k] - a[k]);
          d2 += x, dg += x;
        }
        gsum[g][l] += dg;
      }
      raw[l] += d2;
      d2 /= double(n_);
      sum[l] += d2, ++cnt[l];
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
  if (groups < 2) return out;
  std::vector<double> d(groups);
  double m = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    const double beads = double(n_ - (first[g + 1] - first[g]));
    std::vector<double> y(lmax + 1, 0);
    for (std::size_t l = 1; l <= lmax; ++l) y[l] = cnt[l] ? (raw[l] - gsum[g][l]) / (beads * double(cnt[l])) : 0;
    d[g] = slope(out.tau, y, lo, hi) / 6.0;
    m += d[g] / double(groups);
    out.jackknife.push_back(std::move(y));
  }
  double v = 0;
  for (const double x : d) v += (x - m) * (x - m);
  out.diffusion_sem = std::sqrt(v * double(groups - 1) / double(groups));
  out.diffusion_sem_dof = double(groups) - 1.0;
  return out;
}

namespace {
// Squared minimum-image separations of bead i to its partners j > i (all of them, or those in the 27 cells
// around i), into r2. Without a grid the partners are contiguous and the pass has no control flow, so it
// vectorises.
void partner_r2(const System& s, const CellGrid& grid, std::size_t i, std::vector<double>& r2) {
  const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
  const double hx = Lx / 2, hy = Ly / 2, hz = Lz / 2;
  const double xi = s.x[i], yi = s.y[i], zi = s.z[i];
  auto sep2 = [&](double x, double y, double z) {
    const double dx = min_image(x - xi, Lx, hx), dy = min_image(y - yi, Ly, hy), dz = min_image(z - zi, Lz, hz);
    return dx * dx + dy * dy + dz * dz;
  };
  r2.clear();
  if (!grid.usable()) {
    const std::size_t m = s.size() - i - 1;
    r2.resize(m);
    const double *x = s.x.data() + i + 1, *y = s.y.data() + i + 1, *z = s.z.data() + i + 1;
    double* out = r2.data();
    for (std::size_t t = 0; t < m; ++t) out[t] = sep2(x[t], y[t], z[t]);
    return;
  }
  int cells[27];
  grid.stencil(grid.cell_of(xi, yi, zi), cells);
  for (int c : cells)
    for (std::uint32_t k = grid.start()[c]; k < grid.start()[c + 1]; ++k) {
      const std::uint32_t j = grid.beads()[k];
      if (j > i) r2.push_back(sep2(s.x[j], s.y[j], s.z[j]));
    }
}
}  // namespace

void RdfHistogram::sample(const System& s, int block) {
  const double r2max = rmax_ * rmax_, inv_dr = bins_ / rmax_;
  CellGrid grid;
  if (s.size() > 2000) grid.build(s, rmax_);
  const std::int64_t n = static_cast<std::int64_t>(s.size());
#pragma omp parallel num_threads(threads_) if (grid.usable())
  {
    // One spare bin collects the partners beyond r_max: about half of all pairs in a small box, at random, so
    // a branch per pair would mispredict; the bins are found in a loop without one, and it vectorises.
    std::vector<std::uint64_t> mine(std::size_t(bins_) + 1, 0);
    std::vector<double> r2;
    std::vector<std::int32_t> bin;
    const std::int32_t last = bins_ - 1, spare = bins_;  // locals: the bin stores could alias the member
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t q = 0; q < n; ++q) {
      partner_r2(s, grid, static_cast<std::size_t>(q), r2);
      bin.resize(r2.size());
      const double* v = r2.data();
      std::int32_t* out = bin.data();
      for (std::size_t t = 0, m = r2.size(); t < m; ++t) {
        const bool inside = v[t] < r2max;
        const std::int32_t b = std::int32_t(std::sqrt(inside ? v[t] : 0.0) * inv_dr);
        out[t] = inside ? std::min(last, b) : spare;
      }
      for (const std::int32_t b : bin) ++mine[std::size_t(b)];
    }
    mine.pop_back();
#pragma omp critical(dpdrng_rdf)
    for (std::size_t b = 0; b < mine.size(); ++b) counts_[std::size_t(block)][b] += mine[b];
  }
  ++block_samples_[std::size_t(block)];
}

std::vector<double> RdfHistogram::g_of(const std::vector<std::uint64_t>& counts, std::size_t samples,
                                       const System& s) const {
  const double n = double(s.size()), dr = rmax_ / bins_;
  const double pair_density = n * (n - 1) / 2 / s.box.volume();
  std::vector<double> g;
  for (int b = 0; b < bins_; ++b) {
    const double r0 = b * dr, r1 = r0 + dr;
    const double shell = 4.0 / 3.0 * std::numbers::pi * (r1 * r1 * r1 - r0 * r0 * r0);
    g.push_back(counts[std::size_t(b)] / (samples * pair_density * shell));
  }
  return g;
}

Rdf RdfHistogram::finish(const System& s) const {
  Rdf out;
  std::vector<std::uint64_t> total(std::size_t(bins_), 0);
  std::size_t samples = 0;
  for (std::size_t blk = 0; blk < counts_.size(); ++blk) {
    samples += block_samples_[blk];
    for (std::size_t b = 0; b < total.size(); ++b) total[b] += counts_[blk][b];
  }
  out.samples = samples;
  if (samples == 0) return out;
  const double dr = rmax_ / bins_;
  for (int b = 0; b < bins_; ++b) out.r.push_back(b * dr + 0.5 * dr);
  out.g = g_of(total, samples, s);
  for (std::size_t blk = 0; blk < counts_.size(); ++blk) {
    if (block_samples_[blk] == 0 || block_samples_[blk] == samples) continue;
    auto rest = total;
    for (std::size_t b = 0; b < rest.size(); ++b) rest[b] -= counts_[blk][b];
    out.jackknife.push_back(g_of(rest, samples - block_samples_[blk], s));
  }
  return out;
}

}  // namespace dpdrng::dpd
