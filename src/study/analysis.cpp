#include "dpdrng/study/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/multiple.hpp"
#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/summary.hpp"

namespace dpdrng::study {
namespace {

using detail::CurveSpec;
using detail::ScalarSpec;
using detail::values_of;

// What the paper compares (T, the velocity PDF against Maxwell–Boltzmann, D) plus pressure and T's fluctuation.
constexpr ScalarSpec kScalars[] = {{"temperature_mean", "temperature_sem", false},
                                   {"temperature_std", "temperature_std_sem", false},
                                   {"pressure_mean", "pressure_sem", false},
                                   {"diffusion_coefficient", "diffusion_sem", false},
                                   {"vpdf_error_mb", "vpdf_error_mb_sem", true}};
// The velocity PDF's tails (below 1 % of its peak) and g(r) inside the core (below 0.1) are counting noise.
constexpr CurveSpec kCurves[] = {{"vpdf_vs_mt", "vpdf/p", "vpdf/jackknife", 0.01, true, 0.5},
                                 {"rdf_vs_mt", "rdf/g", "rdf/jackknife", 0.1, false, 0.5},
                                 {"msd_vs_mt", "msd/msd", "msd/jackknife", 0.0, false, 1.0}};
// The membrane's structure as curves: bins where the density is below a tenth of its peak (the empty core for
// water, the bulk water for tails) are left out.
constexpr CurveSpec kBilayerCurves[] = {{"head_profile_vs_mt", "profile/head", nullptr, 0.1, true, 0.5},
                                        {"tail_profile_vs_mt", "profile/tail", nullptr, 0.1, true, 0.5},
                                        {"water_profile_vs_mt", "profile/water", nullptr, 0.1, true, 0.5}};

struct Tested {
  Decision* decision;
  std::string what;
};

// Every test of a variant that produced a P-value: the members of its family.
std::vector<Tested> tests_of(VariantReport& v) {
  std::vector<Tested> t;
  for (auto& o : v.observables)
    if (o.available && o.decision.tested()) t.push_back({&o.decision, o.observable});
  for (auto& p : v.passes)
    if (p.available && p.decision.tested()) t.push_back({&p.decision, p.test + "." + p.stream + " pass fraction"});
  for (auto& c : v.correlations)
    if (c.available && c.decision.tested())
      t.push_back({&c.decision, c.what == "pair" ? "ζ correlation across pairs" : "ζ correlation across steps"});
  return t;
}

void holm(std::vector<Tested>& family, double alpha) {
  std::vector<double> p;
  for (const auto& t : family) p.push_back(t.decision->p);
  const auto adjusted = stats::holm_adjust(p);
  for (std::size_t k = 0; k < family.size(); ++k) {
    family[k].decision->p_adjusted = adjusted[k];
    family[k].decision->differs = adjusted[k] < alpha;
  }
}

// Reference replicas that are missing from the store, unreadable, or failed: without them every comparison
// against the reference would rest on a different set of initial states, or on none.
std::string missing_reference(const VariantReport* ref, int replicas, const std::string& name) {
  std::size_t usable = 0;
  if (ref) {
    usable = ref->cells.size();
    for (const auto* c : ref->broken) usable += c->status == CellStatus::unstable;
  }
  if (usable >= std::size_t(replicas)) return "";
  return "no reference data (" + name + ": " + std::to_string(std::size_t(replicas) - usable) + " of " +
         std::to_string(replicas) + " replicas missing, unreadable or failed)";
}

void compare(VariantReport& v, const VariantReport& ref, bool bilayer) {
  if (bilayer) {
    for (const auto& o : bilayer_observables()) v.observables.push_back(detail::compare_paired(o.name, v, ref));
    for (const auto& c : kBilayerCurves) v.observables.push_back(detail::compare_curve(c, v, ref));
    return;
  }
  for (const auto& s : kScalars) v.observables.push_back(detail::compare_scalar(s, v, ref));
  for (const auto& c : kCurves) v.observables.push_back(detail::compare_curve(c, v, ref));
}

void set_verdict(VariantReport& v, const std::vector<Tested>& tests) {
  if (v.cells.empty()) {
    v.verdict = v.broken.empty() ? "no data yet" : "unstable: " + v.broken.front()->reason;
    return;
  }
  if (!v.no_reference.empty()) {
    v.verdict = v.no_reference;
    return;
  }
  const Tested* best = nullptr;
  for (const auto& t : tests)
    if (!best || t.decision->p_adjusted < best->decision->p_adjusted) best = &t;
  if (!best) {
    v.verdict = v.key.reference ? "reference" : "no comparable data";
    return;
  }
  v.min_p = best->decision->p_adjusted;
  v.min_p_what = best->what;
  char buf[200];
  if (best->decision->differs) {
    std::snprintf(buf, sizeof buf, "differs (p = %.2g: %s)", v.min_p, best->what.c_str());
    v.verdict = v.key.reference ? std::string("reference; ") + buf : std::string(buf);
  } else {
    v.verdict = v.key.reference ? "reference (its own tests pass)" : "indistinguishable from MT at this sample size";
  }
  if (!v.broken.empty()) v.verdict += " [" + std::to_string(v.broken.size()) + " replica(s) unstable/failed]";
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
        const double m = r.applicable;
        r.proportion_ok = r.passed / m >= stats::nist::proportion_range(alpha, m).low;
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

std::vector<VariantReport> group(const StudyConfig& config, const std::vector<CellResult>& cells) {
  // Variants in sweep order (reference first), whatever order the cells were stored in.
  std::vector<VariantKey> order;
  for (const auto& c : enumerate_cells(config)) {
    const VariantKey k = variant_of(c);
    if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
  }
  std::stable_partition(order.begin(), order.end(), [](const VariantKey& k) { return k.reference; });
  std::vector<VariantReport> out;
  for (const auto& k : order) {
    VariantReport v;
    v.key = k;
    for (const auto& c : cells)
      if (variant_of(c.cell) == k) (c.status == CellStatus::ok ? v.cells : v.broken).push_back(&c);
    out.push_back(std::move(v));
  }
  return out;
}

void measure(VariantReport& v, double alpha) {
  v.passes = detail::summarise_passes(v, alpha);
  v.correlations = detail::summarise_correlations(v);
  read_nist(v, alpha);
  v.ns_per_number = stats::mean(values_of(v.cells, "cost.ns_per_number"));
  v.step_ms = stats::mean(values_of(v.cells, "cost.step_seconds")) * 1e3;
  v.rng_share = stats::mean(values_of(v.cells, "cost.rng_share"));
  std::size_t n = 0;
  double s[4] = {0, 0, 0, 0};
  for (const auto* c : v.cells) {
    if (!c->has("zeta_n")) continue;
    n += static_cast<std::size_t>(c->scalar("zeta_n", 0));
    for (int k = 0; k < 4; ++k) s[k] += c->scalar("zeta_s" + std::to_string(k + 1), 0);
  }
  if (n >= 4) v.zeta = stats::moments_of(stats::MomentSums::from_powers(n, s[0], s[1], s[2], s[3]));
}

// The ⟨ζ²⟩ = 1 tests of every variant with ζ, Holm-corrected together; and each variant's predicted shift.
void decide_zeta(Analysis& a) {
  std::vector<double> p;
  std::vector<VariantReport*> tested;
  for (auto& v : a.variants)
    if (v.zeta.n >= 4 && std::isfinite(v.zeta.second_moment_p))
      p.push_back(v.zeta.second_moment_p), tested.push_back(&v);
  const std::vector<double> adj = stats::holm_adjust(p);
  for (std::size_t k = 0; k < tested.size(); ++k) {
    Decision& d = tested[k]->zeta_decision;
    d.p = p[k], d.p_adjusted = adj[k], d.differs = adj[k] < a.alpha;
  }
  for (auto& v : a.variants) {
    const VariantReport* ref = a.reference_for(v.key);
    if (ref && ref->zeta.second_moment > 0 && v.zeta.second_moment > 0)
      v.zeta_predicted_shift = v.zeta.second_moment / ref->zeta.second_moment - 1;
  }
}

}  // namespace

std::string VariantKey::label() const {
  if (reference) return generator;
  return rng::describe(rng::GeneratorSpec{generator, rounds, rng::kPaperTeaKey});
}

std::string VariantKey::label_and_seeding() const {
  std::string s = label();
  if (!reference) s.append(" ").append(seeding_name());
  return s;
}

std::string VariantKey::noise() const { return noise_name(distribution, feed); }
std::string VariantKey::seeding_name() const { return study::seeding_name(seeding, reference); }

VariantKey variant_of(const Cell& c) {
  // The reference's seeding is not part of its variant: it draws from its stream.
  const rng::Seeding seeding = c.reference ? rng::Seeding::distance : c.seeding;
  return {c.generator, c.rounds, c.distribution, c.feed, seeding, c.dt, c.reference, c.integrator};
}

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
  const stats::MeanCI ci = stats::mean_ci(v, 0.95);
  r.mean = ci.mean;
  if (v.size() >= 2) {
    r.ci95 = ci.half_width;
  } else if (only->has(sem_name)) {
    r.ci95 = 1.959963984540054 * only->scalar(sem_name, NAN);
    r.from_run_sem = true;
  }
  return r;
}

const VariantReport* Analysis::reference_for(const VariantKey& k) const {
  for (const auto& v : variants)
    if (v.key.reference && v.key.distribution == k.distribution && v.key.feed == k.feed && v.key.dt == k.dt &&
        v.key.integrator == k.integrator)
      return &v;
  return nullptr;
}

std::string Analysis::error_control_sentence() const {
  char buf[400];
  if (error_control == ErrorControl::study)
    std::snprintf(buf, sizeof buf,
                  "Error control: the family-wise error rate is held at α = %g over the whole study (Holm's "
                  "procedure over all %zu tests of every variant, observables, pass fractions and ζ correlations "
                  "alike): the chance that a study of generators as good as the reference shows any \"differs\" "
                  "is at most α.",
                  alpha, family_size);
  else
    std::snprintf(buf, sizeof buf,
                  "Error control: the family-wise error rate is held at α = %g within each variant (Holm's "
                  "procedure over each variant's own tests; %zu tests in %zu families): each verdict errs with "
                  "probability at most α, so a study of %zu variants as good as the reference can show up to "
                  "%zu × α false \"differs\" on average.",
                  alpha, family_size, families, families, families);
  return buf;
}

Analysis analyse(const StudyConfig& config, const std::vector<CellResult>& cells) {
  Analysis a;
  a.alpha = config.tests.alpha;
  a.error_control = config.tests.error_control;
  a.bilayer = config.scene.is_bilayer();
  a.variants = group(config, cells);
  for (auto& v : a.variants) measure(v, a.alpha);
  for (auto& v : a.variants) {
    const VariantReport* ref = a.reference_for(v.key);
    if (v.key.reference) continue;  // its own tests need no reference
    v.no_reference = missing_reference(ref, config.replicas, config.reference);
    if (v.no_reference.empty()) compare(v, *ref, a.bilayer);
  }
  // The families: a variant without its reference has no verdict, so none of its tests is decided.
  std::vector<std::vector<Tested>> tests(a.variants.size());
  std::vector<Tested> study;
  for (std::size_t k = 0; k < a.variants.size(); ++k) {
    if (!a.variants[k].no_reference.empty() || a.variants[k].cells.empty()) continue;
    tests[k] = tests_of(a.variants[k]);
    a.variants[k].tests = tests[k].size();
    if (tests[k].empty()) continue;
    a.family_size += tests[k].size();
    if (a.error_control == ErrorControl::variant) {
      holm(tests[k], a.alpha);
      ++a.families;
    } else {
      study.insert(study.end(), tests[k].begin(), tests[k].end());
    }
  }
  if (a.error_control == ErrorControl::study) {
    holm(study, a.alpha);
    a.families = study.empty() ? 0 : 1;
  }
  for (std::size_t k = 0; k < a.variants.size(); ++k) set_verdict(a.variants[k], tests[k]);
  decide_zeta(a);
  return a;
}

TemperatureLimit temperature_limit(const Analysis& a, double power) {
  TemperatureLimit out;
  out.power = power;
  std::vector<double> shifts;
  std::size_t largest_family = 0;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.tests == 0) continue;
    const std::size_t m = a.error_control == ErrorControl::study ? a.family_size : v.tests;
    for (const auto& c : v.observables) {
      if (c.observable != "temperature_mean" && c.observable != "temperature") continue;
      // Paired (bilayer) comparisons keep absolute errors: relative to the reference's temperature here.
      const double se = c.paired ? c.sigma / std::abs(c.ref) : c.sigma;
      const double d = stats::detectable_difference(se, c.dof, a.alpha / double(m), power);
      if (!std::isfinite(d)) continue;
      shifts.push_back(d);
      largest_family = std::max(largest_family, m);
    }
  }
  out.variants = shifts.size();
  if (shifts.empty()) return out;
  out.median = stats::median(shifts);
  out.low = *std::min_element(shifts.begin(), shifts.end());
  out.high = *std::max_element(shifts.begin(), shifts.end());
  out.threshold = a.alpha / double(largest_family);
  return out;
}

std::string temperature_limit_sentence(const Analysis& a) {
  const TemperatureLimit t = temperature_limit(a);
  if (t.variants == 0) return "";
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "Detection limit from this study's own spread: a temperature error of %.2g %% (median over %zu "
                "variants; %.2g–%.2g %%) is detected %.0f %% of the time by the temperature t-test at Holm's "
                "strictest threshold α/m = %.2g (the t approximation of its power, with each comparison's "
                "standard error and degrees of freedom; a model, not a calibration).",
                100 * t.median, t.variants, 100 * t.low, 100 * t.high, 100 * t.power, t.threshold);
  return buf;
}

}  // namespace dpdrng::study
