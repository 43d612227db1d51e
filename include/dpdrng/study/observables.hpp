#pragma once
// The water scene's observables behind a verdict, each with its equivalence margin: one entry per observable.
// An observable joins the verdicts of every study whose cells store it (cells without it leave it out), and its
// margin key joins [tests.margins] of the config. To add one, add its entry to scalar_observables() (a scalar
// every cell stores with its block standard error) or curve_observables() in observables.cpp.
#include <string>
#include <vector>

namespace dpdrng::study {

// A scalar every cell stores, with the run's own block standard error beside it. Shifts are relative to the
// reference's mean (reported in %), so the margin is a fraction: 0.005 = 0.5 %.
struct ScalarSpec {
  const char* name;        // "temperature_mean"
  const char* sem;         // "temperature_sem"
  const char* margin_key;  // "temperature": the key in [tests.margins]
  double margin;           // the default margin δ (a fraction of the reference's value)
  const char* label;       // "T": table headers
};

// A curve every cell stores as a series, compared bin by bin with the reference's mean curve. Bins where the
// pooled mean curve (all replicas of both groups) lies below `threshold` (times its maximum when
// `relative_threshold`) are left out; each bin enters the L² test divided by the pooled mean to the power
// `weight_exponent`: 1/2 for histograms, whose counting noise grows as the square root of the count, 1 for
// curves whose noise grows with their value (the MSD). The margin bounds every kept bin's relative difference
// from the reference.
struct CurveSpec {
  const char* name;       // "rdf_vs_mt"
  const char* series;     // "rdf/g"
  const char* jackknife;  // the cells' leave-one-block-out curves ("rdf/jackknife"), or nullptr if none
  double threshold;
  bool relative_threshold;
  double weight_exponent;
  const char* margin_key;  // "rdf"
  double margin;
  const char* label;
};

const std::vector<ScalarSpec>& scalar_observables();
const std::vector<CurveSpec>& curve_observables();
// The membrane scene's curves (density profiles): compared like the water's, without a margin of their own.
const std::vector<CurveSpec>& bilayer_curves();

// Every margin key with its default, in table order: what [tests.margins] accepts. Observables may share a key
// (the pressure tensor's components); the first sets the default.
struct MarginDefault {
  std::string key;
  double margin;
  std::string observable;  // the first observable it applies to
};
std::vector<MarginDefault> margin_defaults();

// The table label of an observable ("T" for temperature_mean); the name itself when it has none.
std::string observable_label(const std::string& name);

}  // namespace dpdrng::study
