#pragma once
// The one table of observables: what each is called in a cell (its key and standard-error key), its unit, its
// label, how a variant is compared with its reference, in which scenes, and its equivalence margin. Measurement,
// analysis, the store's units, the report's tables and charts read it from here. An observable joins the verdicts
// of every study whose cells store it (cells without it leave it out), and its margin key joins [tests.margins]
// of the config. To add one, add its row to observables() in observables.cpp.
//
// Units are DPD reduced units: lengths in r_c, times in τ, velocities in √(k_BT/m), energies in k_BT, pressures
// in k_BT/r_c³, counts and ratios "1".
#include <string>
#include <string_view>
#include <vector>

namespace dpdrng::study {

// How a variant is compared with its reference: a scalar's shift relative to the reference's mean (water, with a
// margin as a fraction: 0.005 = 0.5 %), a paired difference of replicas (the membrane, absolute), or a curve bin
// by bin.
enum class Rule { shift, paired, curve };
enum Scene : unsigned { kWater = 1, kBilayer = 2 };
// What the error budget splits an observable's error against: k_BT (errors as fractions of it) or 0 (absolute).
enum class BudgetTarget { none, kT, zero };

struct Observable {
  const char* name;    // the comparison's name in reports and CSVs ("pressure_mean"; the membrane's "tension")
  const char* key;     // the cell's scalar or series it is read from ("tension_mean", "rdf/g")
  const char* sem;     // the cell's standard error of it ("tension_sem"), or nullptr
  const char* unit;    // DPD reduced units
  const char* label;   // "T": table headers and chart axes
  Rule rule;
  unsigned scenes;     // Scene bits
  const char* margin_key = "";  // "temperature": the key in [tests.margins]; "" without a margin
  double margin = 0;            // the default margin δ
  const char* what = "";        // a sentence for the membrane's table
  BudgetTarget budget = BudgetTarget::none;
  // Curves: bins where the pooled mean curve (all replicas of both groups) lies below `threshold` (times its
  // maximum when `relative_threshold`) are left out; each bin enters the L² test divided by the pooled mean to the
  // power `weight_exponent`: 1/2 for histograms, whose counting noise grows as the square root of the count, 1 for
  // curves whose noise grows with their value (the MSD). The margin bounds every kept bin's relative difference.
  const char* jackknife = nullptr;  // the cells' leave-one-block-out curves, or nullptr if none
  double threshold = 0;
  bool relative_threshold = false;
  double weight_exponent = 0;
};
// The views of the table the analysis iterates over keep the names they are read by.
using ScalarSpec = Observable;
using CurveSpec = Observable;
using BilayerObservable = Observable;

const std::vector<Observable>& observables();
// Rows of one scene and rule, in table order.
const std::vector<Observable>& scalar_observables();  // water, shift
const std::vector<Observable>& curve_observables();   // water, curve
const std::vector<Observable>& bilayer_observables(); // membrane, paired
const std::vector<Observable>& bilayer_curves();      // membrane, curve (no margin)
// The error budget's rows of a scene.
std::vector<Observable> budget_observables(Scene scene);

// The kinetic temperature's row (water's comparison; its cell key is the membrane's too), and whether a
// comparison's name is the kinetic temperature's in either scene.
const Observable& kinetic_temperature();
bool is_kinetic_temperature(std::string_view comparison);
// The row of a comparison name (std::out_of_range for one not listed).
const Observable& observable_row(std::string_view name);

// Every margin key with its default, in table order: what [tests.margins] accepts. Observables may share a key
// (the pressure tensor's components); the first sets the default.
struct MarginDefault {
  std::string key;
  double margin;
  std::string observable;  // the first observable it applies to
};
std::vector<MarginDefault> margin_defaults();

// The table label of an observable ("T" for the kinetic temperature); the name itself when it has none.
std::string observable_label(const std::string& name);

// What the store writes beside a cell's number or dataset: its unit ("" when unknown) and whether it is a count
// (stored as an integer).
std::string unit_of(std::string_view key);
bool is_count(std::string_view key);

}  // namespace dpdrng::study
