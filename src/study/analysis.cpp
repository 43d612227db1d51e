#include "dpdrng/study/analysis.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "dpdrng/rng/registry.hpp"

namespace dpdrng::study {
namespace {

double mean(const std::vector<double>& v) {
  return v.empty() ? NAN : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}
double sd(const std::vector<double>& v) {
  if (v.size() < 2) return NAN;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size() - 1));
}

// Element-wise mean of the curves, skipping `skip` (the left-out replica); empty if no curve is left.
std::vector<double> mean_curve(const std::vector<const std::vector<double>*>& curves, std::size_t skip) {
  std::vector<double> out;
  std::size_t n = 0;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    if (k == skip || !curves[k]) continue;
    if (out.empty()) out.assign(curves[k]->size(), 0.0);
    if (curves[k]->size() != out.size()) continue;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += (*curves[k])[i];
    ++n;
  }
  for (double& x : out) x /= double(n);
  return out;
}

struct ScalarObservable {
  const char* name;
  bool absolute;  // the observable is itself an error rate: compare by difference, not by ratio
};
// What the paper compares (T, the velocity PDF against Maxwell–Boltzmann, D) plus pressure and T's fluctuation.
constexpr ScalarObservable kScalars[] = {{"temperature_mean", false}, {"temperature_std", false},
                                         {"pressure_mean", false},    {"diffusion_coefficient", false},
                                         {"vpdf_error_mb", true}};
struct CurveObservable {
  const char* name;
  const char* series;
  double threshold;        // bins where the reference is below this are left out (relative errors blow up there)
  bool relative_threshold; // threshold is a fraction of the reference's maximum
};
constexpr CurveObservable kCurves[] = {{"vpdf_vs_mt", "vpdf/p", 0.01, true}, {"rdf_vs_mt", "rdf/g", 0.1, false}};

// The membrane's structure as curves: bins where the reference's density is below a tenth of its peak (the
// empty core for water, the bulk water for tails) are left out.
constexpr CurveObservable kBilayerCurves[] = {{"head_profile_vs_mt", "profile/head", 0.1, true},
                                              {"tail_profile_vs_mt", "profile/tail", 0.1, true},
                                              {"water_profile_vs_mt", "profile/water", 0.1, true}};

std::map<int, double> by_replica(const std::vector<const CellResult*>& cells, const std::string& name) {
  std::map<int, double> m;
  for (const auto* c : cells)
    if (c->has(name) && std::isfinite(c->scalar(name, NAN))) m[c->cell.replica] = c->scalar(name, NAN);
  return m;
}

std::vector<double> values_of(const std::vector<const CellResult*>& cells, const std::string& name) {
  std::vector<double> v;
  for (const auto* c : cells)
    if (c->has(name) && std::isfinite(c->scalar(name, NAN))) v.push_back(c->scalar(name, NAN));
  return v;
}

// Root mean square of the cells' "<x>_sem" beside a "<x>_mean" (0 when the observable has none).
double rms_sem(const std::vector<const CellResult*>& cells, const std::string& name) {
  const std::string suffix = "_mean";
  if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return 0;
  const auto sem = values_of(cells, name.substr(0, name.size() - suffix.size()) + "_sem");
  double sum = 0;
  for (double e : sem) sum += e * e;
  return sem.empty() ? 0 : std::sqrt(sum / double(sem.size()));
}

Comparison compare_scalar(const std::string& name, bool absolute, const VariantReport& v, const VariantReport& ref) {
  Comparison c;
  c.observable = name;
  const auto x = values_of(v.cells, name), y = values_of(ref.cells, name);
  c.n = x.size();
  c.n_ref = y.size();
  if (x.empty() || y.empty()) {
    c.note = x.empty() ? "not measured" : "no reference data";
    return c;
  }
  c.available = true;
  c.value = mean(x);
  c.value_sd = sd(x);
  c.ref = mean(y);
  c.ref_sd = sd(y);
  const double scale = absolute ? 1.0 : std::abs(c.ref);
  c.error_rate = std::abs(c.value - c.ref) / scale;
  // The 1σ size of |mean_G − mean_MT| if G were MT, from the MT replicas' spread or, if larger, from the
  // runs' own block standard errors: four replicas estimate a spread with three degrees of freedom, and an
  // unlucky small one (it happened: 0.0004 where the runs' SEMs were 0.0025) would inflate every ratio.
  const double spread = std::max(std::isfinite(c.ref_sd) ? c.ref_sd : 0.0, rms_sem(ref.cells, name));
  c.noise_floor = spread > 0 ? spread * std::sqrt(1.0 / double(c.n) + 1.0 / double(c.n_ref)) / scale : NAN;
  c.p_value = welch_p(x, y);
  if (!std::isfinite(c.p_value)) c.note = "too few replicas for a P-value";
  return c;
}

// The water report's scalar comparison in absolute units (a tensionless membrane's Σ is near 0, so ratios mean
// nothing), with the paired t-test across replicas in place of Welch's: same MT-vs-MT noise floor.
Comparison compare_paired(const std::string& base, const VariantReport& v, const VariantReport& ref) {
  const std::string name = base + "_mean";
  Comparison c = compare_scalar(name, true, v, ref);
  c.observable = base;
  if (!c.available) return c;
  const PairedTest t = paired_test(by_replica(v.cells, name), by_replica(ref.cells, name));
  c.paired = true;
  c.n_pairs = t.n;
  c.diff = t.diff;
  c.diff_ci = t.ci95;
  c.p_value = t.p_value;
  c.note = std::isfinite(t.p_value) ? "" : "too few paired replicas for a P-value";
  return c;
}

// Each replica's curve against the mean of the reference replicas other than its own index; the reference's
// replicas against the others likewise. Both sides then average over the same number of reference curves,
// so the reference-vs-reference errors are the honest noise floor of the generator-vs-reference ones.
Comparison compare_curve(const CurveObservable& obs, const VariantReport& v, const VariantReport& ref) {
  Comparison c;
  c.observable = obs.name;
  std::vector<const std::vector<double>*> ref_curves;
  std::vector<int> ref_rep;
  for (const auto* r : ref.cells) {
    ref_curves.push_back(r->find_series(obs.series));
    ref_rep.push_back(r->cell.replica);
  }
  const auto skip_for = [&](int replica) {
    for (std::size_t k = 0; k < ref_rep.size(); ++k)
      if (ref_rep[k] == replica) return k;
    return ref_rep.size();  // no counterpart: against all reference replicas
  };
  const auto err = [&](const std::vector<double>& curve, std::size_t skip) -> double {
    const auto m = mean_curve(ref_curves, skip);
    if (m.empty() || m.size() != curve.size()) return NAN;
    const double thr = obs.relative_threshold ? obs.threshold * *std::max_element(m.begin(), m.end()) : obs.threshold;
    return curve_error(curve, m, thr);
  };
  std::vector<double> x, y;
  for (const auto* cell : v.cells)
    if (const auto* s = cell->find_series(obs.series)) {
      const double e = err(*s, ref.cells.size() > 1 ? skip_for(cell->cell.replica) : ref.cells.size());
      if (std::isfinite(e)) x.push_back(e);
    }
  if (ref.cells.size() > 1)
    for (std::size_t k = 0; k < ref.cells.size(); ++k)
      if (ref_curves[k]) {
        const double e = err(*ref_curves[k], k);
        if (std::isfinite(e)) y.push_back(e);
      }
  c.n = x.size();
  c.n_ref = y.size();
  if (x.empty()) {
    c.note = "not measured";
    return c;
  }
  c.available = true;
  c.value = c.error_rate = mean(x);
  c.value_sd = sd(x);
  c.ref = 0;
  c.noise_floor = y.empty() ? NAN : mean(y);
  c.ref_sd = sd(y);
  c.p_value = welch_p(x, y);
  if (std::isfinite(c.p_value)) {
    // One-sided: only a larger deviation than MT's own is a difference.
    c.p_value = mean(x) > mean(y) ? c.p_value / 2 : 1 - c.p_value / 2;
  } else {
    c.note = "too few replicas for a P-value";
  }
  return c;
}

// GSL's gsl_cdf_beta_Pinv gives NaN for some skewed cases (e.g. a = 792, b = 9); bisection on the CDF
// cannot fail, and 60 halvings reach double precision on [0, 1].
double beta_quantile(double q, double a, double b) {
  double lo = 0, hi = 1;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (gsl_cdf_beta_P(mid, a, b) < q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void summarise_passes(VariantReport& v, double alpha) {
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
      p.fraction = p.trials ? double(p.passed) / double(p.trials) : NAN;
      // Clopper–Pearson 99 % interval and the exact binomial test against 1 − α.
      const double conf = 0.99;
      const double lo_q = (1 - conf) / 2;
      p.ci_low = p.passed == 0 ? 0.0 : beta_quantile(lo_q, double(p.passed), double(p.trials - p.passed + 1));
      p.ci_high = p.passed == p.trials ? 1.0
                                       : beta_quantile(1 - lo_q, double(p.passed + 1), double(p.trials - p.passed));
      const double fails = double(p.trials - p.passed);
      // Two-sided by doubling the smaller tail (binomial in the failures, success probability α).
      if (p.trials > 0) {
        const double lower = gsl_cdf_binomial_P(static_cast<unsigned>(fails), alpha, static_cast<unsigned>(p.trials));
        const double upper = fails == 0 ? 1.0
                                        : gsl_cdf_binomial_Q(static_cast<unsigned>(fails) - 1, alpha,
                                                             static_cast<unsigned>(p.trials));
        p.binomial_p = std::min(1.0, 2 * std::min(lower, upper));
      }
      v.passes.push_back(p);
    }
}

void read_nist(VariantReport& v, double alpha) {
  for (const auto* c : v.cells) {
    auto t = c->strings.find("nist/test");
    auto var = c->strings.find("nist/variant");
    auto hist = c->matrices.find("nist/histogram");
    const auto* pu = c->find_series("nist/p_uniformity");
    const auto* passed = c->find_series("nist/passed");
    const auto* appl = c->find_series("nist/applicable");
    const auto* stored_ok = c->find_series("nist/ok");
    if (t == c->strings.end() || var == c->strings.end() || hist == c->matrices.end() || !pu || !passed || !appl)
      continue;
    const std::size_t n = t->second.size();
    if (var->second.size() != n || pu->size() != n || passed->size() != n || appl->size() != n ||
        hist->second.rows != n || hist->second.cols != 10)
      continue;
    for (std::size_t i = 0; i < n; ++i) {
      NistRow r;
      r.test = t->second[i];
      r.variant = var->second[i];
      r.histogram.assign(hist->second.data.begin() + long(i * 10), hist->second.data.begin() + long(i * 10 + 10));
      r.p_uniformity = (*pu)[i];
      r.passed = (*passed)[i];
      r.applicable = (*appl)[i];
      if (r.applicable > 0) {
        // SP800-22 §4.2.1: the proportion passing must lie within (1−α) ± 3√(α(1−α)/m).
        const double m = r.applicable;
        const double lo = (1 - alpha) - 3 * std::sqrt(alpha * (1 - alpha) / m);
        r.proportion_ok = r.passed / m >= lo;
        r.uniformity_ok = !(r.p_uniformity < 0.0001);
      }
      r.ok = stored_ok && stored_ok->size() == n ? (*stored_ok)[i] != 0 : (r.proportion_ok && r.uniformity_ok);
      v.nist.push_back(r);
    }
    v.nist_cell = c->cell.id();
    auto text = c->strings.find("nist/final_analysis_report");
    if (text != c->strings.end() && !text->second.empty()) v.nist_report = text->second.front();
    v.nist_sequences = c->scalar("nist.sequences", 0);
    v.nist_columns = c->scalar("nist.columns", double(n));
    v.nist_failed = c->scalar("nist.failed_columns", NAN);
    return;
  }
}

}  // namespace

std::string VariantKey::label() const {
  if (reference) return generator;
  return rng::describe(rng::GeneratorSpec{generator, rounds, rng::kPaperTeaKey});
}

VariantKey variant_of(const Cell& c) { return {c.generator, c.rounds, c.distribution, c.seeding, c.dt, c.reference}; }

double curve_error(const std::vector<double>& curve, const std::vector<double>& ref, double threshold) {
  if (curve.size() != ref.size()) return NAN;
  double s = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < ref.size(); ++i)
    if (ref[i] >= threshold && ref[i] > 0 && std::isfinite(curve[i])) {
      s += std::abs(curve[i] - ref[i]) / ref[i];
      ++n;
    }
  return n ? s / double(n) : NAN;
}

const std::vector<BilayerObservable>& bilayer_observables() {
  static const std::vector<BilayerObservable> obs = {
      {"temperature", "T", "kinetic temperature k_BT"},
      {"pressure_xx", "P_xx", "pressure tensor P_xx"},
      {"pressure_yy", "P_yy", "pressure tensor P_yy"},
      {"pressure_zz", "P_zz", "pressure tensor P_zz (normal to the membrane)"},
      {"tension", "Σ", "tension L_z[P_zz − (P_xx+P_yy)/2]"},
      {"thickness", "thickness", "head-density peak to peak"},
      {"tail_order", "order", "tail order P2 against z"},
  };
  return obs;
}

ReplicaMean replica_mean(const std::vector<const CellResult*>& cells, const std::string& name,
                         const std::string& sem_name) {
  ReplicaMean r;
  std::vector<double> v;
  const CellResult* only = nullptr;
  for (const auto* c : cells)
    if (c->has(name) && std::isfinite(c->scalar(name, NAN))) v.push_back(c->scalar(name, NAN)), only = c;
  r.n = v.size();
  if (v.empty()) return r;
  r.mean = mean(v);
  if (v.size() >= 2) {
    r.ci95 = gsl_cdf_tdist_Qinv(0.025, double(v.size() - 1)) * sd(v) / std::sqrt(double(v.size()));
  } else if (only->has(sem_name)) {
    r.ci95 = 1.959963984540054 * only->scalar(sem_name, NAN);
    r.from_run_sem = true;
  }
  return r;
}

PairedTest paired_test(const std::map<int, double>& x, const std::map<int, double>& y) {
  std::vector<double> d;
  for (const auto& [rep, v] : x)
    if (auto it = y.find(rep); it != y.end()) d.push_back(v - it->second);
  PairedTest t;
  t.n = d.size();
  if (d.empty()) return t;
  t.diff = mean(d);
  if (d.size() < 2) return t;
  const double se = sd(d) / std::sqrt(double(d.size()));
  const double dof = double(d.size() - 1);
  t.ci95 = gsl_cdf_tdist_Qinv(0.025, dof) * se;
  t.p_value = se > 0 ? 2 * gsl_cdf_tdist_Q(std::abs(t.diff) / se, dof) : (t.diff == 0 ? 1.0 : 0.0);
  return t;
}

double welch_p(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 2 || y.size() < 2) return NAN;
  const double vx = std::pow(sd(x), 2) / double(x.size()), vy = std::pow(sd(y), 2) / double(y.size());
  if (!(vx + vy > 0)) return mean(x) == mean(y) ? 1.0 : 0.0;
  const double t = (mean(x) - mean(y)) / std::sqrt(vx + vy);
  const double dof = (vx + vy) * (vx + vy) /
                     (vx * vx / double(x.size() - 1) + vy * vy / double(y.size() - 1));
  return 2 * gsl_cdf_tdist_Q(std::abs(t), dof);
}

const VariantReport* Analysis::reference_for(const VariantKey& k) const {
  for (const auto& v : variants)
    if (v.key.reference && v.key.distribution == k.distribution && v.key.dt == k.dt) return &v;
  return nullptr;
}

Analysis analyse(const StudyConfig& config, const std::vector<CellResult>& cells) {
  Analysis a;
  a.alpha = config.tests.alpha;
  a.bilayer = config.scene.is_bilayer();
  // Variants in sweep order (reference first), whatever order the cells were stored in.
  std::vector<VariantKey> order;
  for (const auto& c : enumerate_cells(config)) {
    const VariantKey k = variant_of(c);
    if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
  }
  std::stable_partition(order.begin(), order.end(), [](const VariantKey& k) { return k.reference; });
  for (const auto& k : order) {
    VariantReport v;
    v.key = k;
    for (const auto& c : cells)
      if (variant_of(c.cell) == k) (c.status == "ok" ? v.cells : v.broken).push_back(&c);
    a.variants.push_back(std::move(v));
  }
  for (auto& v : a.variants) {
    summarise_passes(v, a.alpha);
    read_nist(v, a.alpha);
    v.ns_per_number = mean(values_of(v.cells, "cost.ns_per_number"));
    v.step_ms = mean(values_of(v.cells, "cost.step_seconds")) * 1e3;
    v.rng_share = mean(values_of(v.cells, "cost.rng_share"));
  }
  for (auto& v : a.variants) {
    if (v.key.reference) continue;
    const VariantReport* ref = a.reference_for(v.key);
    if (!ref) continue;
    if (a.bilayer) {
      for (const auto& o : bilayer_observables()) v.observables.push_back(compare_paired(o.name, v, *ref));
      for (const auto& c : kBilayerCurves) v.observables.push_back(compare_curve(c, v, *ref));
      continue;
    }
    for (const auto& s : kScalars) v.observables.push_back(compare_scalar(s.name, s.absolute, v, *ref));
    for (const auto& c : kCurves) v.observables.push_back(compare_curve(c, v, *ref));
  }
  for (auto& v : a.variants) {
    if (v.cells.empty()) {
      v.verdict = v.broken.empty() ? "no data yet" : "unstable: " + v.broken.front()->reason;
      continue;
    }
    // Bonferroni over everything this verdict rests on: each observable and each pass fraction.
    std::vector<std::pair<double, std::string>> ps;
    for (const auto& o : v.observables)
      if (o.available && std::isfinite(o.p_value)) ps.emplace_back(o.p_value, o.observable);
    for (const auto& p : v.passes)
      if (p.available && p.trials > 0) ps.emplace_back(p.binomial_p, p.test + "." + p.stream + " pass fraction");
    double worst = NAN;
    for (const auto& o : v.observables)
      if (o.available && o.noise_floor > 0) worst = std::isnan(worst) ? o.error_rate / o.noise_floor
                                                                      : std::max(worst, o.error_rate / o.noise_floor);
    v.worst_error_over_floor = worst;
    if (ps.empty()) {
      v.verdict = v.key.reference ? "reference" : "no comparable data";
      continue;
    }
    auto it = std::min_element(ps.begin(), ps.end());
    v.min_p = std::min(1.0, it->first * double(ps.size()));
    v.min_p_what = it->second;
    char buf[160];
    if (v.min_p < a.alpha) {
      std::snprintf(buf, sizeof buf, "differs (p = %.2g: %s)", v.min_p, it->second.c_str());
      v.verdict = buf;
    } else {
      v.verdict = v.key.reference ? "reference (its own tests pass)" : "indistinguishable from MT at this sample size";
    }
    if (v.key.reference && v.min_p < a.alpha) v.verdict = "reference; " + v.verdict;
    if (!v.broken.empty()) v.verdict += " [" + std::to_string(v.broken.size()) + " replica(s) unstable/failed]";
  }
  return a;
}

}  // namespace dpdrng::study
