#pragma once
// Accumulators for the run's observables; each is fed sampled production steps and fills its part of the
// RunResult at the end. They know nothing of the noise that produced the trajectory.
#include <array>
#include <cstdint>
#include <vector>

#include "dpdrng/dpd/result.hpp"
#include "dpdrng/dpd/system.hpp"

namespace dpdrng::dpd {

// Counts per block of samples as well as in total, so that the error rate against Maxwell–Boltzmann gets a
// jackknife standard error and the density a jackknife covariance (the caller says which block a sample
// belongs to).
class VelocityHistogram {
 public:
  VelocityHistogram(int bins, double half_range, int blocks = 1)
      : bins_(bins), lo_(-half_range), w_(2 * half_range / bins), blocks_(blocks),
        counts_(std::size_t(blocks) * 3, std::vector<std::uint64_t>(std::size_t(bins), 0)),
        block_samples_(std::size_t(blocks), 0) {}
  void sample(const System& s, int block = 0);
  VelocityPdf finish(double kT, double measured_kT) const;

 private:
  void jackknife(const std::array<std::vector<std::uint64_t>, 3>& total, std::size_t samples, VelocityPdf& out) const;
  int bins_;
  double lo_, w_;
  int blocks_;
  std::vector<std::vector<std::uint64_t>> counts_;  // [block · 3 + component][bin]
  std::vector<std::size_t> block_samples_;
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

// Counts per block of samples as well, for the leave-one-block-out curves that estimate g(r)'s covariance.
class RdfHistogram {
 public:
  // Counts are integers, so a team of `threads` gives the same histogram as one thread.
  RdfHistogram(int bins, double rmax, int threads = 1, int blocks = 1)
      : bins_(bins), rmax_(rmax), threads_(threads),
        counts_(std::size_t(blocks), std::vector<std::uint64_t>(std::size_t(bins), 0)),
        block_samples_(std::size_t(blocks), 0) {}
  void sample(const System& s, int block = 0);
  Rdf finish(const System& s) const;

 private:
  std::vector<double> g_of(const std::vector<std::uint64_t>& counts, std::size_t samples, const System& s) const;
  int bins_;
  double rmax_;
  int threads_;
  std::vector<std::vector<std::uint64_t>> counts_;  // [block][bin]
  std::vector<std::size_t> block_samples_;
};

}  // namespace dpdrng::dpd
