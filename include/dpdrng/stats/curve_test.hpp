#pragma once
// Are two groups of curves (replicas' g(r), velocity PDFs, MSDs, density profiles) drawn around the same mean
// curve? The bins of a curve are many and correlated, the replicas few: a bin-by-bin test would need a
// correction over the bins and a covariance no handful of replicas can estimate. The L²-norm F test (Shen &
// Faraway, Statistica Sinica 14 (2004) 1239; Zhang, Analysis of Variance for Functional Data, 2013) sums the
// squared difference of the mean curves over the bins and calibrates it by the effective number of independent
// bins, d = tr(Σ)²/tr(Σ²) of the bins' covariance Σ.
#include <cstddef>
#include <vector>

namespace dpdrng::stats {

using Curves = std::vector<std::vector<double>>;

struct CurveTest {
  std::size_t n = 0, m = 0, bins = 0;
  double f = 0;               // [nm/(n+m) Σ_k (x̄_k − ȳ_k)²] / tr(Σ̂), Σ̂ the replicas' pooled covariance
  double d = 0;               // effective number of independent bins, in [1, bins]
  double d_dof = 0;           // degrees of freedom of the covariance d was estimated from
  bool d_from_runs = false;   // d from the runs' own leave-one-block-out curves, not from the replicas
  double dof1 = 0, dof2 = 0;  // d and d(n + m − 2)
  double p_value = 0;         // P[F(dof1, dof2) ≥ f]; NaN with fewer than 4 curves in all or no spread
};

// x: n curves, y: m curves, all of one length (already restricted to the bins that matter and weighted as the
// caller wants: each bin's scale sets its weight in the sum). Under equal means and Gaussian bins f is
// ≈ F(d, d(n+m−2)) (Satterthwaite's two-moment fit of both weighted χ² sums).
//
// d comes from `jackknife` when given: per run of either group, its curves with one block of samples left out
// (same bins and weights), whose covariances pooled over the runs estimate Σ with Σ(blocks − 1) degrees of
// freedom; tr(Σ)² and tr(Σ²) are then estimated without bias for a Wishart matrix. A few replicas cannot give
// d: the unbiased estimate from n + m − 2 degrees of freedom scatters so much that the test rejects two to four
// times too often at 1 %, and the plug-in tr(Σ̂)²/tr(Σ̂²) is bounded by n + m − 2 and loses all power. Without
// `jackknife` the plug-in is used, so the test errs on the side of "indistinguishable". The scale of Σ (the
// denominator) always comes from the replicas, so runs whose own errors are too small cannot inflate f.
// Throws InputError for curves of different lengths.
CurveTest curve_test(const Curves& x, const Curves& y, const std::vector<Curves>& jackknife = {});

}  // namespace dpdrng::stats
