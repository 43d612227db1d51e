#pragma once
// The tests behind a variant's verdict (analysis.cpp decides on them): each observable against the
// reference's, the pass fractions and the correlations of ζ; internal to src/study.
#include <string>
#include <vector>

#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/observables.hpp"

namespace dpdrng::study::detail {

// The study's other reference variants (the reference under the other feeds and distributions at the same Δt and
// integrator): runs of one generator, whose replicas' spreads estimate the same variance as the reference's own.
using ReferencePool = std::vector<const VariantReport*>;

// Student's two-sample t-test of the replicas' values, the relative shift with its 95 % CI, and the equivalence
// test at `margin` (NaN: none). The error model: one replica's variance pooled from the spreads of the variant's
// replicas, its reference's and every `pool` reference's (stats::pooled_t, which keeps the pool out when the
// compared replicas vary more than it does).
Comparison compare_scalar(const ScalarSpec& spec, const VariantReport& v, const VariantReport& ref,
                          const ReferencePool& pool, double margin);
// The bilayer's: paired t-test replica by replica on the observable's key, the runs' own standard errors pooled in.
Comparison compare_paired(const Observable& o, const VariantReport& v, const VariantReport& ref);
// The L² F test of the replicas' curves (stats::curve_test), its effective number of bins from the runs'
// leave-one-block-out curves where the cells hold them. Equivalence is the intersection of every kept bin's
// equivalence test at `margin` on its relative difference (each bin a Student t of the replicas): the curves are
// equivalent when every bin is, so the P-value is the largest of the bins' and needs no correction over them.
Comparison compare_curve(const CurveSpec& spec, const VariantReport& v, const VariantReport& ref,
                         const ReferencePool& pool, double margin);

std::vector<PassSummary> summarise_passes(const VariantReport& v, double alpha);
std::vector<CorrelationSummary> summarise_correlations(const VariantReport& v);

// Values of a cell scalar over the cells that hold a finite one.
std::vector<double> values_of(const std::vector<const CellResult*>& cells, const std::string& name);

}  // namespace dpdrng::study::detail
