#pragma once
// The tests behind a variant's verdict (analysis.cpp decides on them): each observable against the
// reference's, the pass fractions and the correlations of ζ; internal to src/study.
#include <string>
#include <vector>

#include "dpdrng/study/analysis.hpp"

namespace dpdrng::study::detail {

// A scalar every cell stores, with the run's own standard error beside it.
struct ScalarSpec {
  const char* name;  // "temperature_mean"
  const char* sem;   // "temperature_sem"
  bool absolute;     // the observable is itself an error rate: compare by difference, not by ratio
};

// A curve every cell stores as a series. Bins where the pooled mean curve (all replicas of both groups) lies
// below `threshold` (times its maximum when `relative_threshold`) are left out; each bin enters the test
// divided by the pooled mean to the power `weight_exponent`: 1/2 for histograms, whose counting noise grows
// as the square root of the count, 1 for curves whose noise grows with their value (the MSD).
struct CurveSpec {
  const char* name;       // "rdf_vs_mt"
  const char* series;     // "rdf/g"
  const char* jackknife;  // the cells' leave-one-block-out curves ("rdf/jackknife"), or nullptr if none
  double threshold;
  bool relative_threshold;
  double weight_exponent;
};

// Pooled two-sample t-test of the replicas' values, both groups' spreads and every run's own standard error
// in the variance (error_rate relative unless spec.absolute).
Comparison compare_scalar(const ScalarSpec& spec, const VariantReport& v, const VariantReport& ref);
// The bilayer's: paired t-test replica by replica on <base>_mean, the runs' own <base>_sem pooled in.
Comparison compare_paired(const std::string& base, const VariantReport& v, const VariantReport& ref);
// The L² F test of the replicas' curves (stats::curve_test), its effective number of bins from the runs'
// leave-one-block-out curves where the cells hold them.
Comparison compare_curve(const CurveSpec& spec, const VariantReport& v, const VariantReport& ref);

std::vector<PassSummary> summarise_passes(const VariantReport& v, double alpha);
std::vector<CorrelationSummary> summarise_correlations(const VariantReport& v);

// Values of a cell scalar over the cells that hold a finite one.
std::vector<double> values_of(const std::vector<const CellResult*>& cells, const std::string& name);

}  // namespace dpdrng::study::detail
