#pragma once
// Accumulators for the run's observables; each is fed sampled production steps and fills its part of the
// RunResult at the end. They know nothing of the noise that produced the trajectory.
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

class VelocityHistogram {
 public:
  VelocityHistogram(int bins, double half_range) : bins_(bins), lo_(-half_range), w_(2 * half_range / bins) {
    for (auto& c : counts_) c.assign(bins, 0);
  }
  void sample(const System& s);
  VelocityPdf finish(double kT, double measured_kT) const;

 private:
  int bins_;
  double lo_, w_;
  std::vector<std::uint64_t> counts_[3];
  std::size_t samples_ = 0;
};

// Unwrapped positions at regular intervals; MSD over all time origins up to half the stored span.
class MsdRecorder {
 public:
  MsdRecorder(std::size_t particles, double interval, std::size_t max_samples)
      : n_(particles), interval_(interval), max_samples_(max_samples) {}
  void sample(const System& s);
  Msd finish() const;

 private:
  std::size_t n_;
  double interval_;
  std::size_t max_samples_;
  std::vector<std::vector<double>> frames_;  // 3n unwrapped coordinates each
};

class RdfHistogram {
 public:
  // Counts are integers, so a team of `threads` gives the same histogram as one thread.
  RdfHistogram(int bins, double rmax, int threads = 1)
      : bins_(bins), rmax_(rmax), threads_(threads), counts_(bins, 0) {}
  void sample(const System& s);
  Rdf finish(const System& s) const;

 private:
  int bins_;
  double rmax_;
  int threads_;
  std::vector<std::uint64_t> counts_;
  std::size_t samples_ = 0;
};

}  // namespace dpdrng::dpd
