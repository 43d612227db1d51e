#include "dpdrng/dpd/bilayer_observables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace dpdrng::dpd {

namespace {
bool is_tail_bead(std::size_t i) { return (i % kLipidBeads) >= static_cast<std::size_t>(kTailA); }
bool is_head_bead(std::size_t i) { return (i % kLipidBeads) < static_cast<std::size_t>(kTailA); }
double rel_z(const System& s, std::size_t i, double zmid) {
  const double L = s.box.L[2];
  return min_image(s.z[i] - zmid, L, 0.5 * L);
}
}  // namespace

double bilayer_midplane(const System& s, std::size_t lipids) {
  const double L = s.box.L[2], k = 2.0 * std::numbers::pi / L;
  double c = 0, sn = 0;
  for (std::size_t i = 0; i < lipids * kLipidBeads; ++i)
    if (is_tail_bead(i)) c += std::cos(k * s.z[i]), sn += std::sin(k * s.z[i]);
  double z = std::atan2(sn, c) / k;
  if (z < 0) z += L;
  return z;
}

int lipids_out(const System& s, std::size_t lipids, double zmid, double escape) {
  int out = 0;
  for (std::size_t l = 0; l < lipids; ++l) {
    double m = 0;
    for (int b = kTailA; b < kLipidBeads; ++b) m += rel_z(s, l * kLipidBeads + b, zmid);
    out += std::abs(m / (kLipidBeads - kTailA)) > escape ? 1 : 0;
  }
  return out;
}

double head_separation(const System& s, std::size_t lipids, double zmid) {
  double up = 0, down = 0;
  std::size_t nu = 0, nd = 0;
  for (std::size_t i = 0; i < lipids * kLipidBeads; ++i) {
    if (!is_head_bead(i)) continue;
    const double d = rel_z(s, i, zmid);
    if (d >= 0)
      up += d, ++nu;
    else
      down += d, ++nd;
  }
  if (nu == 0 || nd == 0) return 0.0;
  return up / double(nu) - down / double(nd);
}

TailOrder tail_order(const System& s, std::size_t lipids) {
  TailOrder t;
  if (lipids == 0) return t;
  const auto& L = s.box.L;
  for (std::size_t l = 0; l < lipids; ++l)
    for (int first : {kTailA, kTailB})
      for (int k = 0; k + 1 < kTailLength; ++k) {
        const std::size_t i = l * kLipidBeads + first + k, j = i + 1;
        const double dx = min_image(s.x[j] - s.x[i], L[0], 0.5 * L[0]);
        const double dy = min_image(s.y[j] - s.y[i], L[1], 0.5 * L[1]);
        const double dz = min_image(s.z[j] - s.z[i], L[2], 0.5 * L[2]);
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 > 0) t.by_bond[k] += 1.5 * dz * dz / r2 - 0.5;
      }
  double sum = 0;
  for (auto& v : t.by_bond) v /= 2.0 * double(lipids), sum += v;
  t.mean = sum / double(t.by_bond.size());
  return t;
}

std::vector<std::array<double, 3>> lipid_axes(const System& s, std::size_t lipids) {
  const auto& L = s.box.L;
  std::vector<std::array<double, 3>> axes;
  axes.reserve(lipids);
  for (std::size_t l = 0; l < lipids; ++l) {
    const std::size_t i = l * kLipidBeads, j = i + kTailA + kTailLength - 1;
    axes.push_back({min_image(s.x[j] - s.x[i], L[0], 0.5 * L[0]), min_image(s.y[j] - s.y[i], L[1], 0.5 * L[1]),
                    min_image(s.z[j] - s.z[i], L[2], 0.5 * L[2])});
  }
  return axes;
}

double nematic_order(const std::vector<std::array<double, 3>>& axes) {
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();
  std::size_t used = 0;
  for (const auto& u : axes) {
    const double r2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    if (!(r2 > 0)) continue;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) Q(a, b) += 1.5 * u[a] * u[b] / r2;
    ++used;
  }
  if (used == 0) return 0.0;
  Q /= double(used);
  Q.diagonal().array() -= 0.5;
  // Q is symmetric: its eigenvalues come out in increasing order.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Q, Eigen::EigenvaluesOnly);
  return eig.eigenvalues()(2);
}

double peak_position(const std::vector<double>& z, const std::vector<double>& y, double lo, double hi) {
  std::size_t best = z.size();
  for (std::size_t k = 0; k < z.size(); ++k)
    if (z[k] > lo && z[k] < hi && (best == z.size() || y[k] > y[best])) best = k;
  if (best == z.size()) return 0.5 * (lo + hi);
  if (best == 0 || best + 1 >= z.size()) return z[best];
  const double ym = y[best - 1], y0 = y[best], yp = y[best + 1];
  const double curv = ym - 2 * y0 + yp;
  // Vertex of the parabola through three equally spaced points; flat tops keep the bin centre.
  const double shift = curv < 0 ? 0.5 * (ym - yp) / curv : 0.0;
  return z[best] + shift * (z[best + 1] - z[best]);
}

ProfileAccumulator::ProfileAccumulator(const Box& box, double bin, int blocks) : box_(box) {
  nbins_ = std::max(1, static_cast<int>(std::lround(box.L[2] / bin)));
  bin_ = box.L[2] / nbins_;
  for (auto& c : counts_) c.assign(nbins_, 0.0);
  block_heads_.assign(std::max(1, blocks), std::vector<double>(nbins_, 0.0));
  block_samples_.assign(block_heads_.size(), 0);
}

void ProfileAccumulator::sample(const System& s, double zmid, int block) {
  const double half = 0.5 * box_.L[2];
  auto& bh = block_heads_[std::clamp<std::size_t>(block, 0, block_heads_.size() - 1)];
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double d = rel_z(s, i, zmid);
    const int k = std::clamp(static_cast<int>(std::floor((d + half) / bin_)), 0, nbins_ - 1);
    const int t = std::min<int>(s.type[i], 2);
    counts_[t][k] += 1;
    if (t == kHead) bh[k] += 1;
  }
  ++block_samples_[std::clamp<std::size_t>(block, 0, block_samples_.size() - 1)];
  ++samples_;
}

std::vector<double> ProfileAccumulator::density(const std::vector<double>& counts, std::size_t samples) const {
  std::vector<double> rho(counts.size(), 0.0);
  if (samples == 0) return rho;
  const double slab = box_.L[0] * box_.L[1] * bin_;
  for (std::size_t k = 0; k < counts.size(); ++k) rho[k] = counts[k] / (slab * double(samples));
  return rho;
}

DensityProfile ProfileAccumulator::finish() const {
  DensityProfile p;
  p.samples = samples_;
  p.z.resize(nbins_);
  for (int k = 0; k < nbins_; ++k) p.z[k] = -0.5 * box_.L[2] + (k + 0.5) * bin_;
  p.head = density(counts_[kHead], samples_);
  p.tail = density(counts_[kTail], samples_);
  p.water = density(counts_[kWater], samples_);
  return p;
}

Stat ProfileAccumulator::thickness() const {
  Stat st;
  const DensityProfile p = finish();
  const double half = 0.5 * box_.L[2];
  auto peak_to_peak = [&](const std::vector<double>& h) {
    return peak_position(p.z, h, 0.0, half) - peak_position(p.z, h, -half, 0.0);
  };
  if (samples_ == 0) return st;
  st.mean = peak_to_peak(p.head);
  std::vector<double> per_block;
  for (std::size_t b = 0; b < block_heads_.size(); ++b)
    if (block_samples_[b] > 0) per_block.push_back(peak_to_peak(density(block_heads_[b], block_samples_[b])));
  st.n = per_block.size();
  if (per_block.size() > 1) {
    double m = 0, v = 0;
    for (double x : per_block) m += x;
    m /= double(per_block.size());
    for (double x : per_block) v += (x - m) * (x - m);
    st.std = std::sqrt(v / double(per_block.size() - 1));
    st.sem = st.std / std::sqrt(double(per_block.size()));
    st.sem_dof = double(per_block.size()) - 1.0;
  }
  return st;
}

}  // namespace dpdrng::dpd
