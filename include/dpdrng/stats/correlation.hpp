#pragma once
// Correlations of pair noise ζ(pair, step) across neighbouring pairs at the same step and across steps for the
// same pair. A weak hash fed neighbouring inputs can fill a histogram perfectly (χ² passes) while neighbouring
// outputs are almost equal; these checks catch that.
#include <cstddef>
#include <span>
#include <string>
#include <utility>

#include "dpdrng/stats/verdict.hpp"

namespace dpdrng::stats {

// A read-only pairs × steps view of noise samples, in either storage order, without copying.
class NoiseMatrix {
 public:
  // Row p holds pair p's series over the steps: data[p * steps + t].
  static NoiseMatrix pair_major(std::span<const double> data, std::size_t pairs, std::size_t steps);
  // Row t holds every pair's value at step t, as a per-step tap writes them: data[t * pairs + p].
  static NoiseMatrix step_major(std::span<const double> data, std::size_t pairs, std::size_t steps);

  std::size_t pairs() const { return pairs_; }
  std::size_t steps() const { return steps_; }
  double operator()(std::size_t pair, std::size_t step) const {
    return data_[pair * pair_stride_ + step * step_stride_];
  }

 private:
  NoiseMatrix(std::span<const double> d, std::size_t p, std::size_t s, std::size_t ps, std::size_t ss)
      : data_(d), pairs_(p), steps_(s), pair_stride_(ps), step_stride_(ss) {}
  std::span<const double> data_;
  std::size_t pairs_, steps_, pair_stride_, step_stride_;
};

struct CorrelationResult {
  std::string what;        // e.g. "pair p vs pair p+1, same step"
  std::size_t n = 0;       // number of (x, y) couples pooled
  double r = 0.0;          // Pearson correlation of the pooled couples
  double statistic = 0.0;  // t = r √(n−2)/√(1−r²)
  std::size_t dof = 0;     // n − 2
  double p_value = 1.0;    // two-sided
  double alpha = 0.01;
  Verdict verdict = Verdict::not_applicable;
  std::string reason;
};

// Pearson correlation of two equally long series with its t-test. Throws InputError for unequal lengths or a
// non-finite value; fewer than 3 couples or a constant series: not_applicable.
CorrelationResult correlation_ttest(std::span<const double> x, std::span<const double> y, double alpha = 0.01);

// ζ(p, t) against ζ(p + offset, t), pooled over every p < pairs − offset and every step: the order of the rows
// decides what "neighbouring" means (pair ids j and j+1 of the same i, say).
CorrelationResult cross_pair_correlation(const NoiseMatrix& m, std::size_t offset = 1, double alpha = 0.01);

// The same for an explicit list of row couples (ζ(i,j,t) against ζ(i,k,t) for chosen j, k).
CorrelationResult cross_pair_correlation(const NoiseMatrix& m, std::span<const std::pair<std::size_t, std::size_t>> rows,
                                         double alpha = 0.01);

// ζ(p, t) against ζ(p, t + lag), pooled over every pair and every t < steps − lag.
CorrelationResult across_time_correlation(const NoiseMatrix& m, std::size_t lag = 1, double alpha = 0.01);

}  // namespace dpdrng::stats
