// The error budget: for each observable with a known target, a variant's error split into what its noise adds
// (variant − reference at the same settings) and what the integrator adds (reference − target). Only the
// comparison with a reference at the same settings separates the two; the variant's own error against the target
// (their sum) can cancel to nothing while both parts are large.
#include <cmath>
#include <sstream>

#include "dpdrng/study/observables.hpp"
#include "dpdrng/study/report.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace {

using detail::fmt;
using detail::num;


const Comparison* budget_comparison(const VariantReport& v, const std::string& name) {
  for (const auto& c : v.observables)
    if (c.observable == name && c.available) return &c;
  return nullptr;
}

// A replica mean's error against the target, with its 95 % interval, on the budget's scale.
BudgetPart budget_against_target(const ReplicaMean& m, double target, double scale) {
  if (m.n == 0) return {};
  return {(m.mean - target) / scale, (m.mean - m.ci95 - target) / scale, (m.mean + m.ci95 - target) / scale};
}

std::string budget_label(const std::string& observable) {
  for (const auto& o : bilayer_observables())
    if (observable == o.name) return o.label;
  return observable_label(observable);
}

std::string budget_part_text(const BudgetPart& p, bool relative) {
  if (!std::isfinite(p.value)) return "–";
  const auto f = [&](double x) { return relative ? fmt("%+.2f", 100 * x) : fmt("%+.3g", x); };
  std::string s = f(p.value);
  if (std::isfinite(p.ci_low)) s += " [" + f(p.ci_low) + ", " + f(p.ci_high) + "]";
  return s + (relative ? " %" : "");
}

}  // namespace

std::vector<BudgetRow> error_budget(const Analysis& a, double kT) {
  std::vector<BudgetRow> rows;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.cells.empty()) continue;
    const VariantReport* ref = a.reference_for(v.key);
    if (!ref) continue;
    for (const auto& t : budget_observables(a.bilayer ? kBilayer : kWater)) {
      const Comparison* c = budget_comparison(v, t.name);
      if (!c) continue;
      // Errors against k_BT as fractions of it; against 0, absolute.
      const bool temperature = t.budget == BudgetTarget::kT;
      BudgetRow r;
      r.variant = &v;
      r.observable = t.name;
      r.relative = temperature;
      r.target = temperature ? kT : 0.0;
      const double scale = temperature ? kT : 1.0;
      // The comparison's shift back on the observable's own scale (water's are relative to the reference's
      // mean), so that noise + integrator = variant − target.
      const double to_abs = c->relative ? std::abs(c->ref) : 1.0;
      r.noise = {c->shift * to_abs / scale, c->ci_low * to_abs / scale, c->ci_high * to_abs / scale};
      r.integrator = budget_against_target(replica_mean(ref->cells, t.key, t.sem), r.target, scale);
      r.total = budget_against_target(replica_mean(v.cells, t.key, t.sem), r.target, scale);
      rows.push_back(r);
    }
  }
  return rows;
}

std::string error_budget_csv(const std::vector<BudgetRow>& rows) {
  std::ostringstream o;
  o << "variant,seeding,distribution,feed,integrator,dt,replicas,observable,target,scale,noise_error,noise_ci_low,"
       "noise_ci_high,integrator_error,integrator_ci_low,integrator_ci_high,variant_error,variant_ci_low,"
       "variant_ci_high\n";
  for (const auto& r : rows) {
    const VariantKey& k = r.variant->key;
    const bool uniform = k.distribution == rng::Distribution::uniform;
    o << detail::csv_line({k.label(), k.seeding_name(), std::string(rng::to_string(k.distribution)),
                           uniform ? std::string() : std::string(rng::to_string(k.feed)), k.integrator, num(k.dt),
                           std::to_string(r.variant->cells.size()), r.observable, num(r.target),
                           r.relative ? "fraction of target" : "absolute", num(r.noise.value), num(r.noise.ci_low),
                           num(r.noise.ci_high), num(r.integrator.value), num(r.integrator.ci_low),
                           num(r.integrator.ci_high), num(r.total.value), num(r.total.ci_low),
                           num(r.total.ci_high)});
  }
  return o.str();
}

std::string error_budget_markdown(const std::vector<BudgetRow>& rows) {
  if (rows.empty()) return "(no variant has an observable with a target and its reference's data)\n";
  std::ostringstream o;
  o << "| variant | noise | seeding | observable | noise error: variant − reference [95 % CI] | integrator error: "
       "reference − target [95 % CI] | variant − target [95 % CI] |\n|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const VariantKey& k = r.variant->key;
    o << "| " << k.label() << " | " << k.noise() << " | " << k.seeding_name() << " | " << budget_label(r.observable)
      << " | " << budget_part_text(r.noise, r.relative) << " | " << budget_part_text(r.integrator, r.relative) << " | "
      << budget_part_text(r.total, r.relative) << " |\n";
  }
  return o.str();
}

std::string error_budget_text(double kT) {
  return "Target: k_BT = " + fmt("%g", kT) +
         " for the kinetic, configurational and per-component temperatures (in % of it), 0 for the membrane's "
         "P_xx − P_yy (pressure units). *Noise error*: the variant against the reference run with the same "
         "settings, the comparison behind the verdict with its 95 % CI. *Integrator error*: the reference "
         "against the target (its replicas' mean, Student 95 % CI), what Δt and the integrator alone make. "
         "*Variant − target*: their sum as a user running the variant alone would see it: the two parts can "
         "cancel, so a small error here says nothing about the generator.\n";
}

}  // namespace dpdrng::study
