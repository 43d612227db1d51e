#include "dpdrng/dpd/observables.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

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

namespace msd_sums {

// Sums over the coordinates of the squared displacements between origin frames and the frames a lag after them:
// for each origin and lag, their total over all coordinates and their total over each group of beads, each
// added coordinate after coordinate in order (the group's inside the total's). The frames are transposed a
// chunk of coordinates at a time (coordinate-major), so that one coordinate's values at all the lags of an
// origin are contiguous; a block of lags keeps its two sums in registers while the chunk's coordinates pass.
// Every lag's sums still see the coordinates one after another, so they hold the bits of a loop over one lag at
// a time.
class LagSums {
 public:
  LagSums(const std::vector<std::vector<double>>& frames, std::size_t stride, std::size_t lmax,
          const std::vector<std::size_t>& first)
      : frames_(frames), nf_(frames.size()), stride_(stride), lmax_(lmax), first_(first) {}

  // Origins per pass: the pass holds two sums per origin and lag.
  std::size_t origin_block() const { return std::max<std::size_t>(1, (std::size_t{1} << 19) / (lmax_ + 1)); }

  // Origins [o0, o1): each origin's totals per lag into sum (divided by n), raw and cnt, its groups' into gsum,
  // origin after origin.
  void add(std::size_t o0, std::size_t o1, std::size_t n, std::vector<double>& sum, std::vector<double>& raw,
           std::vector<std::vector<double>>& gsum, std::vector<std::size_t>& cnt) const {
    const std::size_t w = lmax_ + 1, origins = o1 - o0;
    std::vector<double> d2(origins * w, 0.0), dg(origins * w, 0.0);
    const std::size_t chunk = std::max<std::size_t>(1, (std::size_t{1} << 15) / nf_);
    std::vector<double> t(chunk * nf_ + kBlock);  // the last block of lags may read kBlock past the end
    for (std::size_t g = 0; g + 1 < first_.size(); ++g) {
      for (std::size_t k0 = 3 * first_[g], end = 3 * first_[g + 1]; k0 < end; k0 += chunk) {
        const std::size_t k1 = std::min(end, k0 + chunk);
        transpose(k0, k1, t.data());
        for (std::size_t o = o0; o < o1; ++o)
          accumulate(t.data() + o * stride_, nf_, k1 - k0, lags(o), d2.data() + (o - o0) * w,
                     dg.data() + (o - o0) * w);
      }
      for (std::size_t o = o0; o < o1; ++o)
        for (std::size_t l = 1; l <= lags(o); ++l) gsum[g][l] += dg[(o - o0) * w + l], dg[(o - o0) * w + l] = 0;
    }
    for (std::size_t o = o0; o < o1; ++o)
      for (std::size_t l = 1; l <= lags(o); ++l) {
        double x = d2[(o - o0) * w + l];
        raw[l] += x;
        x /= double(n);
        sum[l] += x, ++cnt[l];
      }
  }

 private:
  // The lags of origin o: up to lmax, and within the frames.
  std::size_t lags(std::size_t o) const { return std::min(lmax_, nf_ - 1 - o * stride_); }

  // Coordinates [k0, k1) of every frame into t, coordinate-major; eight frames at a time, so that each store
  // fills a cache line's worth of t rather than one value a line.
  void transpose(std::size_t k0, std::size_t k1, double* t) const {
    for (std::size_t f0 = 0; f0 < nf_; f0 += 8) {
      const std::size_t f1 = std::min(nf_, f0 + 8);
      for (std::size_t k = k0; k < k1; ++k)
        for (std::size_t f = f0; f < f1; ++f) t[(k - k0) * nf_ + f] = frames_[f][k];
    }
  }

  using Lanes = double __attribute__((vector_size(64)));  // GNU vector: any target, split where 512 bits lack
  static constexpr std::size_t kLanes = 8, kBlock = 4 * kLanes;

  // Coordinates [0, kn) of one origin, coordinate k's values at at[k·nf] (the origin) and at[k·nf + l] (a lag
  // l later): lags [1, lags] into d2 and dg, kBlock lags at a time in registers. The last lags go as a whole
  // block on copies of their sums, whose lanes past `lags` (reading the next values in memory) are dropped.
  static void accumulate(const double* at, std::size_t nf, std::size_t kn, std::size_t lags, double* d2,
                         double* dg) {
    std::size_t l = 1;
    for (; l + kBlock <= lags + 1; l += kBlock) block(at + l, at, nf, kn, d2 + l, dg + l);
    if (l > lags) return;
    const std::size_t r = lags + 1 - l;
    double s[kBlock] = {}, g[kBlock] = {};
    std::copy_n(d2 + l, r, s), std::copy_n(dg + l, r, g);
    block(at + l, at, nf, kn, s, g);
    std::copy_n(s, r, d2 + l), std::copy_n(g, r, dg + l);
  }

  // kBlock lags from `lag` on (at[k·nf] the origin's coordinate k).
  static void block(const double* lag, const double* at, std::size_t nf, std::size_t kn, double* d2, double* dg) {
    Lanes s[4], g[4];
    for (std::size_t v = 0; v < 4; ++v) s[v] = load(d2 + v * kLanes), g[v] = load(dg + v * kLanes);
    for (std::size_t k = 0; k < kn; ++k) {
      const double a = at[k * nf];
      for (std::size_t v = 0; v < 4; ++v) {
        const Lanes d = load(lag + k * nf + v * kLanes) - a, x = d * d;
        s[v] += x, g[v] += x;
      }
    }
    for (std::size_t v = 0; v < 4; ++v) store(d2 + v * kLanes, s[v]), store(dg + v * kLanes, g[v]);
  }
  static Lanes load(const double* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static void store(double* p, const Lanes& v) { std::memcpy(p, &v, sizeof v); }

  const std::vector<std::vector<double>>& frames_;
  std::size_t nf_, stride_, lmax_;
  const std::vector<std::size_t>& first_;
};

}  // namespace msd_sums

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
  const msd_sums::LagSums lags{frames_, stride, lmax, first};
  for (std::size_t o0 = 0; o0 < norigins; o0 += lags.origin_block())
    lags.add(o0, std::min(norigins, o0 + lags.origin_block()), n_, sum, raw, gsum, cnt);
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

namespace rdf_pairs {

// Minimum-image r² of (x, y, z)[t] − (xi, yi, zi) for t in [0, m), into r2; no control flow, so it vectorises.
// The separation of a pair is the negation of its reverse's, bit for bit (min_image is odd), so either bead
// may be the centre.
void r2_from(const Box& box, double xi, double yi, double zi, const double* __restrict x, const double* __restrict y,
             const double* __restrict z, std::size_t m, double* __restrict r2) {
  const double Lx = box.L[0], Ly = box.L[1], Lz = box.L[2];
  const double hx = Lx / 2, hy = Ly / 2, hz = Lz / 2;
  for (std::size_t t = 0; t < m; ++t) {
    const double dx = min_image(x[t] - xi, Lx, hx), dy = min_image(y[t] - yi, Ly, hy), dz = min_image(z[t] - zi, Lz, hz);
    r2[t] = dx * dx + dy * dy + dz * dz;
  }
}

// Counts r² values into bins of r up to r_max. About half of all pairs in a small box lie beyond r_max, at
// random, so a branch per pair would mispredict: the values inside are first moved to the front (inside), then
// binned in a loop without a branch that vectorises. Four histograms, summed at the end, take consecutive values
// in turn, so that increments of one bin do not wait for each other.
class Binner {
 public:
  Binner(int bins, double rmax)
      : r2max_(rmax * rmax), inv_dr_(bins / rmax), last_(bins - 1), width_(std::size_t(bins)),
        counts_(4 * std::size_t(bins), 0) {}
  void add(const double* r2, std::size_t m) {
    in_.resize(m + kLanes);
    const std::size_t k = inside(r2, m, r2max_, in_.data());
    bin_.resize(k);
    const double* in = in_.data();
    std::int32_t* out = bin_.data();
    const double inv_dr = inv_dr_;
    const std::int32_t last = last_;  // locals: the bin stores could alias the members
    for (std::size_t t = 0; t < k; ++t) out[t] = std::min(last, std::int32_t(std::sqrt(in[t]) * inv_dr));
    const std::size_t w = width_;
    std::uint64_t* c = counts_.data();
    std::size_t t = 0;
    for (; t + 4 <= k; t += 4)
      ++c[std::size_t(out[t])], ++c[w + std::size_t(out[t + 1])], ++c[2 * w + std::size_t(out[t + 2])],
          ++c[3 * w + std::size_t(out[t + 3])];
    for (; t < k; ++t) ++c[std::size_t(out[t])];
  }
  // Adds the counts to total.
  void add_to(std::vector<std::uint64_t>& total) const {
    const std::size_t w = width_;
    for (std::size_t b = 0; b < total.size(); ++b)
      total[b] += counts_[b] + counts_[w + b] + counts_[2 * w + b] + counts_[3 * w + b];
  }

 private:
  static constexpr std::size_t kLanes = 8;  // out's room past the m values: inside's whole-vector stores

  // The values of r2[0, m) below r2max, in order, to out; returns their number.
  static std::size_t inside(const double* r2, std::size_t m, double r2max, double* out) {
    std::size_t n = 0, t = 0;
#if defined(__AVX512F__)
    const __m512d lim = _mm512_set1_pd(r2max);
    for (; t + kLanes <= m; t += kLanes) {
      const __m512d v = _mm512_loadu_pd(r2 + t);
      const __mmask8 below = _mm512_cmp_pd_mask(v, lim, _CMP_LT_OQ);
      _mm512_storeu_pd(out + n, _mm512_maskz_compress_pd(below, v));
      n += std::size_t(std::popcount(unsigned(below)));
    }
#endif
    for (; t < m; ++t) out[n] = r2[t], n += r2[t] < r2max;
    return n;
  }

  double r2max_, inv_dr_;
  std::int32_t last_;
  std::size_t width_;
  std::vector<std::uint64_t> counts_;
  std::vector<double> in_;
  std::vector<std::int32_t> bin_;
};

// Beads sorted by the grid's cells, as contiguous copies of their positions.
struct SortedPositions {
  std::vector<double> x, y, z;
  SortedPositions() = default;
  SortedPositions(const System& s, const CellGrid& grid) {
    const std::vector<std::uint32_t>& beads = grid.beads();
    x.resize(beads.size()), y.resize(beads.size()), z.resize(beads.size());
    for (std::size_t k = 0; k < beads.size(); ++k) x[k] = s.x[beads[k]], y[k] = s.y[beads[k]], z[k] = s.z[beads[k]];
  }
};

// Every pair once: bead i against the beads after it.
void all_pairs(const System& s, std::int64_t q, std::vector<double>& r2, Binner& bins) {
  const std::size_t i = static_cast<std::size_t>(q), m = s.size() - i - 1;
  r2.resize(m);
  r2_from(s.box, s.x[i], s.y[i], s.z[i], s.x.data() + i + 1, s.y.data() + i + 1, s.z.data() + i + 1, m, r2.data());
  bins.add(r2.data(), m);
}

// Every pair of neighbouring cells once: cell c's beads each against the beads after it in c, and all of them
// against the 13 cells of the stencil's forward half (distinct from each other and from c's backward half, as
// the grid has at least 3 cells along each axis).
void cell_pairs(const System& s, const CellGrid& grid, const SortedPositions& p, int c, std::vector<double>& r2,
                Binner& bins) {
  constexpr int kOwn = 13;  // the stencil's centre; the forward half follows it
  int cells[27];
  grid.stencil(c, cells);
  const std::uint32_t* start = grid.start().data();
  for (std::uint32_t a = start[c]; a < start[c + 1]; ++a) {
    r2.clear();
    for (int k = kOwn; k < 27; ++k) {
      const std::uint32_t lo = k == kOwn ? a + 1 : start[cells[k]], hi = start[cells[k] + 1];
      const std::size_t done = r2.size();
      r2.resize(done + (hi - lo));
      r2_from(s.box, p.x[a], p.y[a], p.z[a], p.x.data() + lo, p.y.data() + lo, p.z.data() + lo, hi - lo,
              r2.data() + done);
    }
    bins.add(r2.data(), r2.size());
  }
}

}  // namespace rdf_pairs

void RdfHistogram::sample(const System& s, int block) {
  CellGrid grid;
  if (s.size() > 2000) grid.build(s, rmax_);
  const bool cells = grid.usable();
  const rdf_pairs::SortedPositions sorted = cells ? rdf_pairs::SortedPositions(s, grid) : rdf_pairs::SortedPositions{};
  const std::int64_t n = cells ? std::int64_t(grid.start().size()) - 1 : static_cast<std::int64_t>(s.size());
#pragma omp parallel num_threads(team_size(threads_)) if (cells)
  {
    rdf_pairs::Binner mine(bins_, rmax_);
    std::vector<double> r2;
#pragma omp for schedule(dynamic, 16)
    for (std::int64_t q = 0; q < n; ++q) {
      if (cells)
        rdf_pairs::cell_pairs(s, grid, sorted, int(q), r2, mine);
      else
        rdf_pairs::all_pairs(s, q, r2, mine);
    }
#pragma omp critical(dpdrng_rdf)
    mine.add_to(counts_[std::size_t(block)]);
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
