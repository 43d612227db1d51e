#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "dpdrng/dpd/result.hpp"
#include "dpdrng/stats/curve_test.hpp"
#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/stats/multiple.hpp"
#include "dpdrng/stats/pass_fraction.hpp"
#include "dpdrng/stats/summary.hpp"

namespace dpdrng::study::detail {
namespace {

// A run's own standard error of `sem_name` as a variance estimate of the run's value, with the degrees of
// freedom the cell stores beside it ("<sem_name>_dof"; stores without it held 20-block errors). Missing or
// zero errors give none.
stats::VarianceEstimate run_error(const CellResult& c, const std::string& sem_name) {
  const double e = c.scalar(sem_name, NAN);
  if (!(e > 0) || !std::isfinite(e)) return {0, 0};
  const double dof = c.scalar(sem_name + "_dof", double(dpd::kStatBlocks - 1));
  return {e * e, std::isfinite(dof) && dof > 0 ? dof : 0.0};
}

std::map<int, const CellResult*> by_replica(const std::vector<const CellResult*>& cells, const std::string& name) {
  std::map<int, const CellResult*> m;
  for (const auto* c : cells)
    if (c->has(name) && std::isfinite(c->scalar(name, NAN))) m[c->cell.replica] = c;
  return m;
}

void set_test(Comparison& c, const stats::TTest& t, const char* name, double scale) {
  c.test = name;
  c.statistic = t.t;
  c.dof = t.dof;
  c.sigma = t.se / scale;
  c.decision.p = t.p_value;
  if (!std::isfinite(t.p_value)) c.note = "too few replicas for a P-value";
}

// Bins kept by a curve spec, judged on the pooled mean curve of every replica of both groups.
std::vector<std::size_t> kept_bins(const CurveSpec& spec, const std::vector<double>& pooled) {
  const double top = pooled.empty() ? 0 : *std::max_element(pooled.begin(), pooled.end());
  const double thr = spec.relative_threshold ? spec.threshold * top : spec.threshold;
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < pooled.size(); ++i)
    if (pooled[i] > 0 && pooled[i] >= thr) k.push_back(i);
  return k;
}

std::vector<double> mean_of(const stats::Curves& curves) {
  std::vector<double> m(curves.front().size(), 0.0);
  for (const auto& c : curves)
    for (std::size_t i = 0; i < m.size(); ++i) m[i] += c[i] / double(curves.size());
  return m;
}

// The curves of the cells that hold the series at length `len` (0: the first one found sets it).
stats::Curves curves_of(const std::vector<const CellResult*>& cells, const std::string& series, std::size_t& len) {
  stats::Curves out;
  for (const auto* c : cells)
    if (const auto* s = c->find_series(series)) {
      if (len == 0) len = s->size();
      if (s->size() == len && std::all_of(s->begin(), s->end(), [](double x) { return std::isfinite(x); }))
        out.push_back(*s);
    }
  return out;
}

// Each cell's leave-one-block-out curves (matrix `name`, a row per block) that match the curves' length.
std::vector<stats::Curves> jackknife_of(const std::vector<const CellResult*>& cells, const char* name,
                                        std::size_t len) {
  std::vector<stats::Curves> out;
  if (!name) return out;
  for (const auto* c : cells) {
    const auto it = c->matrices.find(name);
    if (it == c->matrices.end() || it->second.cols != len || it->second.rows < 2) continue;
    stats::Curves rows;
    for (std::size_t r = 0; r < it->second.rows; ++r)
      rows.emplace_back(it->second.data.begin() + long(r * len), it->second.data.begin() + long((r + 1) * len));
    out.push_back(std::move(rows));
  }
  return out;
}

stats::Curves weighted(const stats::Curves& curves, const std::vector<std::size_t>& bins,
                       const std::vector<double>& pooled, double exponent) {
  stats::Curves out;
  for (const auto& c : curves) {
    std::vector<double> w;
    for (const std::size_t k : bins) w.push_back(c[k] / std::pow(pooled[k], exponent));
    out.push_back(std::move(w));
  }
  return out;
}

}  // namespace

std::vector<double> values_of(const std::vector<const CellResult*>& cells, const std::string& name) {
  std::vector<double> v;
  for (const auto* c : cells)
    if (c->has(name) && std::isfinite(c->scalar(name, NAN))) v.push_back(c->scalar(name, NAN));
  return v;
}

namespace {

// A group's spread as an estimate of one replica's variance, with its degrees of freedom (none below 2 values).
stats::VarianceEstimate spread_of(const std::vector<double>& x) {
  if (x.size() < 2) return {0, 0};
  const double sd = stats::sample_sd(x);
  return {sd * sd, double(x.size() - 1)};
}

std::vector<stats::VarianceEstimate> pool_spreads(const ReferencePool& pool, const std::string& name) {
  std::vector<stats::VarianceEstimate> out;
  for (const auto* r : pool) out.push_back(spread_of(values_of(r->cells, name)));
  return out;
}

// The replicas' means and spreads on both sides; false, with the reason in the note, when a side has none.
bool describe(Comparison& c, const std::vector<double>& x, const std::vector<double>& y) {
  c.n = x.size();
  c.n_ref = y.size();
  if (x.empty() || y.empty()) {
    c.note = x.empty() ? "not measured" : "no reference data";
    return false;
  }
  c.available = true;
  c.value = stats::mean(x);
  c.value_sd = stats::sample_sd(x);
  c.ref = stats::mean(y);
  c.ref_sd = stats::sample_sd(y);
  return true;
}

}  // namespace

// The shift's normal score over the runs' own block errors: each side's mean has the variance Σ sem²/n².
double runs_score(const std::vector<const CellResult*>& a, const std::vector<const CellResult*>& b,
                  const std::string& name, const std::string& sem, double diff) {
  double var = 0;
  for (const auto* g : {&a, &b}) {
    double s = 0;
    std::size_t n = 0;
    for (const auto* c : *g) {
      const double e = c->scalar(sem, NAN);
      if (!c->has(name) || !std::isfinite(c->scalar(name, NAN))) continue;
      if (!std::isfinite(e)) return NAN;
      s += e * e, ++n;
    }
    if (n == 0) return NAN;
    var += s / double(n * n);
  }
  return var > 0 ? diff / std::sqrt(var) : NAN;
}

void set_shift(Comparison& c, double shift, double half_width) {
  c.shift = shift;
  c.ci_low = shift - half_width;
  c.ci_high = shift + half_width;
}

Comparison compare_scalar(const ScalarSpec& spec, const VariantReport& v, const VariantReport& ref,
                          const ReferencePool& pool, double margin) {
  Comparison c;
  c.observable = spec.name;
  const auto x = values_of(v.cells, spec.key), y = values_of(ref.cells, spec.key);
  if (!describe(c, x, y)) return c;
  const double scale = std::abs(c.ref);
  if (!(scale > 0)) {
    c.available = false;
    c.note = "not applicable: the reference's mean is 0, so no relative shift";
    return c;
  }
  c.error_rate = std::abs(c.value - c.ref) / scale;
  const stats::TTest t = stats::pooled_t(x, y, pool_spreads(pool, spec.key));
  set_test(c, t, "t", scale);
  set_shift(c, t.diff / scale, t.ci_half_width(0.95) / scale);
  c.margin = margin;
  c.equivalence.p = stats::equivalence_p(c.shift, c.sigma, t.dof, margin);
  c.score = stats::normal_score(t.t, t.dof);
  c.score_runs = runs_score(v.cells, ref.cells, spec.key, spec.sem, t.diff);
  return c;
}

Comparison compare_paired(const Observable& o, const VariantReport& v, const VariantReport& ref) {
  Comparison c;
  c.observable = o.name;
  const std::string name = o.key, sem = o.sem;
  if (!describe(c, values_of(v.cells, name), values_of(ref.cells, name))) return c;
  c.paired = true;
  c.error_rate = std::abs(c.value - c.ref);
  // A difference's variance is the sum of its two runs' (their noise is independent), with Satterthwaite's
  // degrees of freedom for a sum of two estimates.
  std::vector<double> d;
  std::vector<stats::VarianceEstimate> runs;
  const auto gx = by_replica(v.cells, name), gy = by_replica(ref.cells, name);
  for (const auto& [rep, cx] : gx) {
    const auto it = gy.find(rep);
    if (it == gy.end()) continue;
    d.push_back(cx->scalar(name, NAN) - it->second->scalar(name, NAN));
    const auto a = run_error(*cx, sem), b = run_error(*it->second, sem);
    if (a.dof > 0 && b.dof > 0)
      runs.push_back(
          {a.variance + b.variance,
           std::pow(a.variance + b.variance, 2) / (a.variance * a.variance / a.dof + b.variance * b.variance / b.dof)});
  }
  c.n_pairs = d.size();
  const stats::TTest t = stats::paired_t(d, runs);
  c.diff = t.diff;
  c.diff_ci = t.ci_half_width(0.95);
  set_test(c, t, "paired t", 1.0);
  c.relative = false;
  set_shift(c, t.diff, c.diff_ci);
  c.score = stats::normal_score(t.t, t.dof);
  if (!std::isfinite(t.p_value)) c.note = "too few paired replicas for a P-value";
  return c;
}

// Every kept bin's relative difference from the reference, a Student t of the replicas: the bin whose 95 % CI
// reaches furthest from 0 is the curve's shift, and the largest of the bins' equivalence P-values its
// equivalence P-value (NaN when a bin cannot be tested).
void bin_shifts(Comparison& c, const stats::Curves& x, const stats::Curves& y, const std::vector<stats::Curves>& pool,
                const std::vector<std::size_t>& bins, const std::vector<double>& my, double margin) {
  double reach = -1, p = 0;
  const auto column = [](const stats::Curves& curves, std::size_t k) {
    std::vector<double> v;
    for (const auto& curve : curves) v.push_back(curve[k]);
    return v;
  };
  for (const std::size_t k : bins) {
    if (!(my[k] > 0)) continue;
    std::vector<stats::VarianceEstimate> extra;
    for (const auto& g : pool) extra.push_back(spread_of(column(g, k)));
    const stats::TTest t = stats::pooled_t(column(x, k), column(y, k), extra);
    const double rel = t.diff / my[k], half = t.ci_half_width(0.95) / my[k];
    if (!std::isfinite(half)) return;
    if (std::abs(rel) + half > reach) reach = std::abs(rel) + half, set_shift(c, rel, half);
    if (margin > 0) p = std::max(p, stats::equivalence_p(rel, t.se / my[k], t.dof, margin));
  }
  if (!(margin > 0) || reach < 0) return;
  c.margin = margin;
  c.equivalence.p = p;
}

Comparison compare_curve(const CurveSpec& spec, const VariantReport& v, const VariantReport& ref,
                         const ReferencePool& pool, double margin) {
  Comparison c;
  c.observable = spec.name;
  c.test = "F";
  std::size_t len = 0;
  const auto y = curves_of(ref.cells, spec.key, len);
  const auto x = curves_of(v.cells, spec.key, len);
  c.n = x.size();
  c.n_ref = y.size();
  if (x.empty() || y.empty()) {
    c.note = x.empty() ? "not measured" : "no reference data";
    return c;
  }
  auto all = x;
  all.insert(all.end(), y.begin(), y.end());
  const auto pooled = mean_of(all);
  const auto bins = kept_bins(spec, pooled);
  if (bins.empty()) {
    c.note = "no bin above the threshold";
    return c;
  }
  c.available = true;
  const auto mx = mean_of(x), my = mean_of(y);
  double rel = 0;
  for (const std::size_t k : bins) rel += my[k] > 0 ? std::abs(mx[k] - my[k]) / my[k] / double(bins.size()) : 0;
  c.error_rate = rel;
  std::vector<stats::Curves> runs;
  for (const auto* g : {&v.cells, &ref.cells})
    for (const auto& j : jackknife_of(*g, spec.jackknife, len))
      runs.push_back(weighted(j, bins, pooled, spec.weight_exponent));
  const stats::CurveTest t = stats::curve_test(weighted(x, bins, pooled, spec.weight_exponent),
                                               weighted(y, bins, pooled, spec.weight_exponent), runs);
  c.statistic = t.f;
  c.dof = t.dof1;
  c.dof2 = t.dof2;
  c.decision.p = t.p_value;
  std::vector<stats::Curves> pool_curves;
  for (const auto* r : pool) pool_curves.push_back(curves_of(r->cells, spec.key, len));
  bin_shifts(c, x, y, pool_curves, bins, my, margin);
  if (!std::isfinite(t.p_value)) c.note = "too few replicas for a P-value";
  return c;
}

std::vector<PassSummary> summarise_passes(const VariantReport& v, double alpha) {
  std::vector<PassSummary> out;
  for (const char* test : {"chi2", "ttest"})
    for (const char* stream : {"x", "a", "b"}) {
      PassSummary p;
      p.test = test;
      p.stream = stream;
      const std::string base = std::string(test) + "." + stream + ".";
      for (const auto* c : v.cells)
        if (c->has(base + "trials")) {
          p.trials += static_cast<std::size_t>(c->scalar(base + "trials", 0));
          p.passed += static_cast<std::size_t>(c->scalar(base + "passed", 0));
          p.available = true;
        }
      if (!p.available) continue;
      if (p.trials > 0 && p.passed <= p.trials) {
        const stats::PassFraction f = stats::pass_fraction(p.passed, p.trials, {alpha, 1.0 - alpha});
        p.fraction = f.fraction;
        p.ci_low = f.ci_low;
        p.ci_high = f.ci_high;
        p.decision.p = f.binomial_p;
      }
      out.push_back(p);
    }
  return out;
}

std::vector<CorrelationSummary> summarise_correlations(const VariantReport& v) {
  std::vector<CorrelationSummary> out;
  for (const char* what : {"pair", "time"}) {
    CorrelationSummary s;
    s.what = what;
    std::vector<double> p, sign;
    const std::string r_name = std::string("corr.") + what + ".r", p_name = std::string("corr.") + what + ".p";
    for (const auto* c : v.cells) {
      const double r = c->scalar(r_name, NAN), pv = c->scalar(p_name, NAN);
      if (!c->has(r_name) || !std::isfinite(r) || !std::isfinite(pv)) continue;
      p.push_back(pv);
      sign.push_back(r);
      if (!std::isfinite(s.worst_r) || std::abs(r) > std::abs(s.worst_r)) s.worst_r = r;
    }
    if (p.empty()) continue;
    s.available = true;
    s.replicas = p.size();
    s.decision.p = stats::stouffer_two_sided(p, sign);
    out.push_back(s);
  }
  return out;
}

}  // namespace dpdrng::study::detail
