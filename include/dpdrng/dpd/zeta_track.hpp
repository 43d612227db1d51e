#pragma once
// The correlations of the ζ a run's force used, on a deterministic sample of pairs: beads spread evenly over the
// bead numbers ("stars"), each with two partners found inside r_c at the start of a window of steps and followed
// while they stay inside r_c. A pair's ζ over consecutive steps gives the autocorrelation at lags 1…K; the two
// partners of one star at the same step give the correlation across pairs sharing a bead. The ζ are those the
// pair loop drew (PairForces::zeta_of, recomputed from the separation the loop saw), so the sample costs the hot
// path nothing: a few dozen pairs a step, and a partner search per star and window.
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/pair_forces.hpp"
#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

class ZetaTracker {
 public:
  // lags ≥ 1; stars beads (at most the bead count), windows of max(4·lags, 20) steps.
  ZetaTracker(int lags, std::size_t beads, double rc, int stars = 64);
  // After the forces of step `step` at positions s (each step once, in order).
  void record(const System& s, const PairForces& pair, std::uint64_t step);
  ZetaCorrelation finish() const;

 private:
  struct Track {
    std::uint32_t i = 0, j = 0;
    bool alive = false;
    std::vector<double> zeta;  // this window's ζ while inside r_c
  };
  void start_window(const System& s);
  void close_window();
  void add_segment(const std::vector<double>& z);

  int lags_, window_;
  double rc2_;
  std::vector<std::uint32_t> stars_;
  std::vector<Track> tracks_;  // two per star
  std::vector<std::size_t> live_;  // record()'s tracks inside r_c, their pairs and ζ
  std::vector<std::uint32_t> live_i_, live_j_;
  std::vector<double> live_zeta_;
  int in_window_ = 0;
  bool unknown_ = false;       // a ζ the pair forces cannot recompute
  // Σζ², their count; per lag Σ products, Σ products², count; the shared-bead products likewise.
  double s0_ = 0;
  std::uint64_t n0_ = 0, segments_ = 0;
  std::vector<double> sum_, sum2_;
  std::vector<std::uint64_t> count_;
  double shared_ = 0, shared2_ = 0;
  std::uint64_t shared_n_ = 0;
};

}  // namespace dpdrng::dpd
