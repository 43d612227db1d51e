#pragma once
// Summaries of a sample: mean, spread, median, and the Student-t confidence interval of a mean.
#include <cstddef>
#include <span>

namespace dpdrng::stats {

double mean(std::span<const double> x);       // NaN for no values
double sample_sd(std::span<const double> x);  // n − 1 in the denominator; NaN below 2 values
double median(std::span<const double> x);     // mean of the middle two for an even count; NaN for no values

// Mean with its confidence half-width t_{n−1, (1+confidence)/2} · sd / √n; half_width is NaN below 2 values.
struct MeanCI {
  std::size_t n = 0;
  double mean = 0, half_width = 0;
};
MeanCI mean_ci(std::span<const double> x, double confidence);

// The two-sided Student-t quantile t_{dof, (1+confidence)/2}: a confidence half-width is this × the standard error.
double t_half_width_factor(double dof, double confidence);

}  // namespace dpdrng::stats
