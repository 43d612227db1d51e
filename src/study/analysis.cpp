#include "dpdrng/study/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/multiple.hpp"
#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/study/observables.hpp"
#include "dpdrng/stats/summary.hpp"

namespace dpdrng::study {
namespace {

using detail::values_of;

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
  if (v.zeta_decision.tested()) t.push_back({&v.zeta_decision, "⟨ζ²⟩ = 1"});
  return t;
}

// The equivalence tests of every variant with a verdict, Holm-corrected together: a false "equivalent" is the
// error a user pays for, so the study's family-wise rate of it is held at α.
std::size_t decide_equivalence(std::vector<VariantReport>& variants, const std::vector<bool>& judged, double alpha) {
  std::vector<Equivalence*> family;
  for (std::size_t k = 0; k < variants.size(); ++k)
    if (judged[k])
      for (auto& o : variants[k].observables)
        if (o.available && o.equivalence.tested()) family.push_back(&o.equivalence);
  std::vector<double> p;
  for (const auto* e : family) p.push_back(e->p);
  const auto adjusted = stats::holm_adjust(p);
  for (std::size_t k = 0; k < family.size(); ++k)
    family[k]->p_adjusted = adjusted[k], family[k]->equivalent = adjusted[k] < alpha;
  return family.size();
}

Outcome outcome_of(const Comparison& c) {
  if (!c.available) return Outcome::none;
  if (c.decision.differs) return Outcome::differs;
  return c.equivalence.equivalent ? Outcome::equivalent : Outcome::inconclusive;
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

double margin_of(const std::map<std::string, double>& margins, const std::string& key, double fallback) {
  const auto it = margins.find(key);
  return it == margins.end() ? fallback : it->second;
}

// The reference variants other than `ref` at its Δt and integrator (the other feeds and distributions).
detail::ReferencePool reference_pool(const Analysis& a, const VariantReport& ref) {
  detail::ReferencePool pool;
  for (const auto& r : a.variants)
    if (r.key.reference && &r != &ref && r.key.dt == ref.key.dt && r.key.integrator == ref.key.integrator)
      pool.push_back(&r);
  return pool;
}

// Water observables the cells do not store are left out (not a verdict's member); the membrane's stay in its
// table as "not measured" (its cells are costly, so stores older than an observable are common), untested.
void compare(VariantReport& v, const VariantReport& ref, const detail::ReferencePool& pool, bool bilayer,
             const std::map<std::string, double>& margins) {
  const auto keep = [&](Comparison c) {
    if (c.note != "not measured") v.observables.push_back(std::move(c));
  };
  if (bilayer) {
    for (const auto& o : bilayer_observables()) v.observables.push_back(detail::compare_paired(o, v, ref));
    for (const auto& c : bilayer_curves()) keep(detail::compare_curve(c, v, ref, {}, NAN));
    return;
  }
  for (const auto& s : scalar_observables())
    keep(detail::compare_scalar(s, v, ref, pool, margin_of(margins, s.margin_key, s.margin)));
  for (const auto& c : curve_observables())
    keep(detail::compare_curve(c, v, ref, pool, margin_of(margins, c.margin_key, c.margin)));
}

std::string percent_or_plain(const Comparison& c, double x) {
  char buf[40];
  if (c.relative)
    std::snprintf(buf, sizeof buf, "%+.2f %%", 100 * x);
  else
    std::snprintf(buf, sizeof buf, "%+.3g", x);
  return buf;
}

// "T +3.52 % [+2.90, +4.14]": an observable's shift with its 95 % CI.
std::string effect_text(const Comparison& c) {
  std::string s = observable_label(c.observable) + " " + percent_or_plain(c, c.shift);
  if (std::isfinite(c.ci_low)) s += " [" + percent_or_plain(c, c.ci_low) + ", " + percent_or_plain(c, c.ci_high) + "]";
  return s;
}

// The variant's outcome from its tests: any differs → differs; every observable with a margin equivalent (and
// at least one) → equivalent; otherwise inconclusive.
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
  if (best) v.min_p = best->decision->p_adjusted, v.min_p_what = best->what;
  if (v.key.reference) {
    v.verdict = best && best->decision->differs ? "reference; its own test differs: " + best->what
                                                : std::string("reference");
    return;
  }
  for (auto& o : v.observables) o.outcome = outcome_of(o);
  std::size_t margins = 0, equivalent = 0;
  const Comparison* differing = nullptr;
  for (const auto& o : v.observables) {
    if (o.outcome == Outcome::none) continue;
    if (std::isfinite(o.margin)) ++margins, equivalent += o.outcome == Outcome::equivalent;
    if (o.outcome == Outcome::differs && !differing) differing = &o;  // the first in table order: T before curves
  }
  if (best && best->decision->differs) {
    v.outcome = Outcome::differs;
    v.verdict = "differs: " + (differing ? effect_text(*differing) : best->what);
  } else if (margins > 0 && equivalent == margins) {
    v.outcome = Outcome::equivalent;
    v.verdict = "equivalent within the margins";
  } else if (!best && margins == 0) {
    v.verdict = "no comparable data";
    return;
  } else {
    v.outcome = Outcome::inconclusive;
    v.verdict = margins == 0 ? "inconclusive (no observable has a margin: none can be shown equivalent)"
                             : "inconclusive (" + std::to_string(equivalent) + " of " + std::to_string(margins) +
                                   " observables shown equivalent)";
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
  // The reference_gammas series has no variants to judge: it belongs to the stability report alone.
  for (const auto& c : enumerate_cells(config)) {
    if (c.gamma > 0) continue;
    const VariantKey k = variant_of(c);
    if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
  }
  std::stable_partition(order.begin(), order.end(), [](const VariantKey& k) { return k.reference; });
  std::vector<VariantReport> out;
  for (const auto& k : order) {
    VariantReport v;
    v.key = k;
    for (const auto& c : cells)
      if (c.cell.gamma == 0 && variant_of(c.cell) == k) (c.status == CellStatus::ok ? v.cells : v.broken).push_back(&c);
    out.push_back(std::move(v));
  }
  return out;
}

// The mean over the replicas of a cell estimate `name` with its standard error `se_name`: the replicas' errors
// combined as those of independent runs. NaN unless every replica stores both.
stats::Measured replica_average(const std::vector<const CellResult*>& cells, const std::string& name,
                                const std::string& se_name) {
  stats::Measured m;
  double sum = 0, var = 0;
  for (const auto* c : cells) {
    const double x = c->scalar(name, NAN), e = c->scalar(se_name, NAN);
    if (!std::isfinite(x) || !std::isfinite(e)) return m;
    sum += x, var += e * e;
  }
  if (cells.empty()) return m;
  const double n = double(cells.size());
  m.mean = sum / n, m.se = std::sqrt(var) / n;
  return m;
}

void measure_noise_power(VariantReport& v) {
  const stats::Measured m2w =
      replica_average(v.cells, "zeta_weighted_second_moment_mean", "zeta_weighted_second_moment_sem");
  if (!std::isfinite(m2w.mean)) return;
  std::vector<stats::Measured> rho;
  for (int lag = 1;; ++lag) {
    const std::string k = "zeta_autocorrelation_" + std::to_string(lag);
    const stats::Measured r = replica_average(v.cells, k, k + "_se");
    if (!std::isfinite(r.mean)) break;
    rho.push_back(r);
  }
  v.power_lags = rho.size();
  v.noise_power = stats::effective_noise_power(m2w, rho);
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
  measure_noise_power(v);
}

// The ⟨ζ²⟩ = 1 test of a variant with ζ (a member of the study's family) and its predicted temperature shifts.
void zeta_test(Analysis& a) {
  for (auto& v : a.variants) {
    if (v.zeta.n >= 4 && std::isfinite(v.zeta.second_moment_p)) v.zeta_decision.p = v.zeta.second_moment_p;
    const VariantReport* ref = a.reference_for(v.key);
    if (ref && ref->zeta.second_moment > 0 && v.zeta.second_moment > 0)
      v.zeta_predicted_shift = v.zeta.second_moment / ref->zeta.second_moment - 1;
    // A reference that stores no ζ of its own (the mt19937 stream in cells mode, as in the membrane) draws
    // independent unit-variance numbers: its effective power is 1 exactly.
    const stats::NoisePower ideal{1.0, 0.0};
    const stats::NoisePower* ref_power =
        !ref ? nullptr : ref->noise_power.value > 0 ? &ref->noise_power : ref->cells.empty() ? nullptr : &ideal;
    if (ref_power && v.noise_power.value > 0) {
      const stats::NoisePower ratio = stats::predicted_temperature_ratio(v.noise_power, *ref_power);
      v.power_predicted_shift = {ratio.value - 1, ratio.se};
    }
  }
}

}  // namespace

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::equivalent: return "equivalent";
    case Outcome::differs: return "differs";
    case Outcome::inconclusive: return "inconclusive";
    case Outcome::none: break;
  }
  return "";
}

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

std::string Analysis::equivalence_text() const {
  if (equivalence_tests == 0) return "no observable has a margin, so there are no equivalence tests.";
  return "the " + std::to_string(equivalence_tests) +
         " equivalence tests are Holm-corrected together over the whole study, so the chance of any false "
         "\"equivalent\" is at most α as well.";
}

std::string Analysis::error_control_sentence() const {
  char buf[900];
  if (error_control == ErrorControl::study)
    std::snprintf(buf, sizeof buf,
                  "Error control: one family per study. Every two-sided test of every variant (observables, "
                  "⟨ζ²⟩ = 1, isotropy where the cells hold components, pass fractions and ζ correlations, %zu "
                  "tests) is Holm-corrected together, so the chance that a study of generators as good as the "
                  "reference shows any \"differs\" is at most α = %g; %s",
                  family_size, alpha, equivalence_text().c_str());
  else
    std::snprintf(buf, sizeof buf,
                  "Error control: the family-wise error rate is held at α = %g within each variant (Holm's "
                  "procedure over each variant's own tests, ⟨ζ²⟩ = 1 included; %zu tests in %zu families): each "
                  "verdict errs with probability at most α, so a study of %zu variants as good as the reference can "
                  "show up to %zu × α false \"differs\" on average; %s",
                  alpha, family_size, families, families, families, equivalence_text().c_str());
  return buf;
}

std::string Analysis::error_model_sentence() const {
  if (bilayer)
    return "Error model: each paired difference's variance pools the pairs' spread with both runs' own block "
           "errors (weighted by their degrees of freedom); the membrane's observables have no margins, so its "
           "verdicts are \"differs\" or \"inconclusive\".";
  return "Error model: a scalar's shift is tested against the replicas' spread (Student's t): one replica's "
         "variance pooled from the variant's replicas, its reference's and the reference's under the study's other "
         "feeds and distributions, weighted by their degrees of freedom, unless the compared replicas vary more "
         "than that pool (one-sided F test at 5 %), when their own spread alone is used. The runs' own block errors "
         "are not pooled in, because over null comparisons they understate the spread (the z-score check below). "
         "Curves: the L² F test for a difference, and every kept bin's t-test under the same pooled model for "
         "equivalence.";
}

bool known_good(const VariantKey& k) {
  if (k.reference) return false;
  if (k.generator == "philox4x32") return k.rounds >= 7;
  if (k.generator == "threefry2x64") return k.rounds >= 13;
  if (k.generator == "splitmix64") return true;
  if (k.generator == "tea32" || k.generator == "tea64") return k.rounds >= 16;
  return false;
}

std::vector<ScoreCheck> score_dispersion(const Analysis& a, const std::function<bool(const VariantKey&)>& is_null,
                                         double confidence) {
  std::vector<ScoreCheck> out;
  for (const auto& spec : scalar_observables()) {
    std::vector<double> chosen, runs;
    for (const auto& v : a.variants) {
      if (v.key.reference || !is_null(v.key)) continue;
      for (const auto& o : v.observables)
        if (o.observable == spec.name && o.available) chosen.push_back(o.score), runs.push_back(o.score_runs);
    }
    if (chosen.empty()) continue;
    out.push_back({spec.name, stats::score_dispersion(chosen, confidence), stats::score_dispersion(runs, confidence)});
  }
  return out;
}

Analysis analyse(const StudyConfig& config, const std::vector<CellResult>& cells) {
  Analysis a;
  a.alpha = config.tests.alpha;
  a.error_control = config.tests.error_control;
  a.bilayer = config.scene.is_bilayer();
  a.margins = config.tests.margins;
  a.variants = group(config, cells);
  for (auto& v : a.variants) measure(v, a.alpha);
  zeta_test(a);
  for (auto& v : a.variants) {
    const VariantReport* ref = a.reference_for(v.key);
    if (v.key.reference) continue;  // its own tests need no reference
    v.no_reference = missing_reference(ref, config.reference_replica_count(), config.reference);
    if (v.no_reference.empty()) compare(v, *ref, reference_pool(a, *ref), a.bilayer, a.margins);
  }
  // The families: a variant without its reference has no verdict, so none of its tests is decided.
  std::vector<std::vector<Tested>> tests(a.variants.size());
  std::vector<Tested> study;
  std::vector<bool> judged(a.variants.size(), false);
  for (std::size_t k = 0; k < a.variants.size(); ++k) {
    if (!a.variants[k].no_reference.empty() || a.variants[k].cells.empty()) continue;
    judged[k] = true;
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
  a.equivalence_tests = decide_equivalence(a.variants, judged, a.alpha);
  for (std::size_t k = 0; k < a.variants.size(); ++k) set_verdict(a.variants[k], tests[k]);
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
      if (!is_kinetic_temperature(c.observable)) continue;
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
