#pragma once
// Structure of a bilayer normal to z: midplane, density profiles relative to it, thickness, tail order and
// the integrity check. Lipids are the first 15·lipids beads (bilayer.hpp's layout); nothing here knows the noise.
#include <array>
#include <cstddef>
#include <vector>

#include "dpdrng/dpd/bilayer.hpp"

namespace dpdrng::dpd {

// Circular mean of the tail beads' z: the midplane, even if the bilayer has drifted across the boundary.
double bilayer_midplane(const System& s, std::size_t lipids);

// Lipids whose tail beads' mean |z − z_mid| exceeds `escape` (they have left the hydrophobic core).
int lipids_out(const System& s, std::size_t lipids, double zmid, double escape);

// Mean z − z_mid of heads above the midplane minus that of heads below.
double head_separation(const System& s, std::size_t lipids, double zmid);

struct TailOrder {
  double mean = 0;                              // over all T–T bonds
  std::array<double, kTailLength - 1> by_bond{};  // bond k joins tail beads k and k+1 (both tails pooled)
};
TailOrder tail_order(const System& s, std::size_t lipids);

// Each lipid's axis: its backbone end to end, first head bead H1 to the last bead of tail a (not normalised;
// 8 bond lengths when straight, well inside half a box side).
std::vector<std::array<double, 3>> lipid_axes(const System& s, std::size_t lipids);

// The nematic order parameter S: the largest eigenvalue of Q = ⟨3/2 u uᵀ − 1/2 I⟩ over the unit vectors u along
// `axes` (zero-length axes are skipped; none gives 0). S = 1 when all axes are parallel, 0 for an isotropic
// infinite set (a finite one gives S ≈ 1/√N); unlike tail_order's P2 it needs no reference direction.
double nematic_order(const std::vector<std::array<double, 3>>& axes);

// Position of the maximum of y over bins with centre z in (lo, hi), refined by a parabola through the
// neighbouring bins.
double peak_position(const std::vector<double>& z, const std::vector<double>& y, double lo, double hi);

// Number-density profiles of H, T and W along z − z_mid, whole run and per block (for the thickness's error).
class ProfileAccumulator {
 public:
  ProfileAccumulator(const Box& box, double bin, int blocks);
  void sample(const System& s, double zmid, int block);
  DensityProfile finish() const;
  // Peak-to-peak distance of the head profile: whole run as the mean, block spread as the error.
  Stat thickness() const;

 private:
  std::vector<double> density(const std::vector<double>& counts, std::size_t samples) const;
  Box box_;
  double bin_;
  int nbins_;
  std::vector<double> counts_[3];
  std::vector<std::vector<double>> block_heads_;
  std::vector<std::size_t> block_samples_;
  std::size_t samples_ = 0;
};

}  // namespace dpdrng::dpd
