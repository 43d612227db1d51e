#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/stats/summary.hpp"
#include "dpdrng/study/analysis.hpp"

namespace dpdrng::study {
namespace {

struct Samples {
  std::vector<double> sd, dof, n, n_ref;
  double margin = NAN;
  bool curve = false;
};

}  // namespace

std::vector<EquivalenceReplicas> equivalence_replicas(const Analysis& a, double power) {
  std::vector<std::string> order;
  std::map<std::string, Samples> by_name;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.tests == 0) continue;
    for (const auto& c : v.observables) {
      if (!c.available || !std::isfinite(c.margin) || !c.equivalence.tested()) continue;
      auto [it, fresh] = by_name.try_emplace(c.observable);
      if (fresh) order.push_back(c.observable);
      Samples& s = it->second;
      s.margin = c.margin;
      // A curve's shift is its furthest-reaching bin: no one spread stands for it.
      if (!std::isfinite(c.sigma) || !c.relative) {
        s.curve = true;
        continue;
      }
      if (!(c.sigma > 0) || !(c.dof > 0) || c.n == 0 || c.n_ref == 0) continue;
      // The comparison's own standard error, back to one replica's spread: the pooled one under the pooled model.
      s.sd.push_back(c.sigma / std::sqrt(1.0 / double(c.n) + 1.0 / double(c.n_ref)));
      s.dof.push_back(c.dof);
      s.n.push_back(double(c.n));
      s.n_ref.push_back(double(c.n_ref));
    }
  }
  std::vector<EquivalenceReplicas> out;
  const double threshold = a.equivalence_tests ? a.alpha / double(a.equivalence_tests) : NAN;
  for (const auto& name : order) {
    const Samples& s = by_name.at(name);
    EquivalenceReplicas r;
    r.observable = name;
    r.margin = s.margin;
    r.threshold = threshold;
    r.comparisons = s.sd.size();
    if (s.curve || s.sd.empty()) {
      r.not_modelled = s.curve ? "a curve is equivalent when every kept bin's interval lies inside the margin"
                               : "no comparison with a replica spread";
      out.push_back(r);
      continue;
    }
    r.sd = stats::median(s.sd);
    r.dof = stats::median(s.dof);
    r.replicas = int(std::lround(stats::median(s.n)));
    r.reference_replicas = int(std::lround(stats::median(s.n_ref)));
    const double se = r.sd * std::sqrt(1.0 / r.replicas + 1.0 / r.reference_replicas);
    r.power_now = stats::equivalence_power(se, r.dof, threshold, r.margin);
    r.needed = stats::replicas_for_equivalence(r.sd, double(r.reference_replicas) / r.replicas, r.dof, threshold,
                                               r.margin, power);
    if (r.needed < 0) r.not_modelled = "the spread or the equivalence family is empty";
    out.push_back(r);
  }
  return out;
}

}  // namespace dpdrng::study
