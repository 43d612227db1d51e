// The report's tables, Markdown for reading and CSV for plotting elsewhere.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/study/observables.hpp"
#include "dpdrng/study/report.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace {

using detail::fmt;
using detail::num;
using detail::csv_quote;

std::string pass_cell(const PassSummary& p) {
  if (!p.available || p.trials == 0) return "–";
  const std::string b = p.decision.differs ? "**" : "";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3f [%.3f, %.3f] (%zu)", p.fraction, p.ci_low, p.ci_high, p.trials);
  std::string s = buf;
  return b + s.substr(0, s.find(' ')) + b + s.substr(s.find(' '));
}

// The corrected P-value of a decided test, floored; "–" for one that could not be made.
std::string adjusted(const Decision& d) { return detail::p_text(d.p_adjusted); }

const PassSummary* find_pass(const VariantReport& v, const std::string& test, const std::string& stream) {
  for (const auto& p : v.passes)
    if (p.test == test && p.stream == stream) return &p;
  return nullptr;
}

std::vector<std::string> streams_of(const VariantReport& v) {
  std::vector<std::string> s;
  for (const auto& p : v.passes)
    if (std::find(s.begin(), s.end(), p.stream) == s.end()) s.push_back(p.stream);
  if (s.empty()) s.push_back("x");
  return s;
}

// A run's speed against the 8-round run of its generator, in words that never say "0.6× faster".
std::string speed_vs_8(double at8_ms, double step_ms) {
  if (!std::isfinite(at8_ms) || !(step_ms > 0)) return "–";
  const double r = at8_ms / step_ms;
  return r >= 1 ? fmt("%.2f× faster", r) : fmt("%.2f× slower", 1 / r);
}

std::string pretty(const std::string& o) { return observable_label(o); }

// A shift on its own scale: "+0.12 %" for relative ones, "+0.0012" for absolute ones.
std::string shift_text(const Comparison& c, double x) {
  return c.relative ? fmt("%+.2f %%", 100 * x) : fmt("%+.3g", x);
}

// An observable's cell in a table: the shift [95 % CI] first, bold when it differs, then the outcome and the
// corrected two-sided P-value.
std::string effect_cell(const Comparison& c) {
  const std::string b = c.decision.differs ? "**" : "";
  std::string s = b + shift_text(c, c.shift) + b;
  if (std::isfinite(c.ci_low)) s += " [" + shift_text(c, c.ci_low) + ", " + shift_text(c, c.ci_high) + "]";
  const char* mark = c.outcome == Outcome::equivalent ? "equiv." : c.outcome == Outcome::differs ? "differs"
                     : c.outcome == Outcome::inconclusive ? "?" : "";
  if (*mark) s += std::string(" ") + mark;
  return s + " (p " + adjusted(c.decision) + ")";
}

}  // namespace

std::string pass_table_markdown(const Analysis& a, const std::string& distribution) {
  std::ostringstream o;
  const std::string ci = fmt("%g", 100 * (1 - a.alpha)) + " % CI";
  o << "| generator | output | χ² pass fraction [" << ci << "] (steps) | lag-1 t pass fraction [" << ci
    << "] (pairs) |\n|---|---|---|---|\n";
  for (const auto& v : a.variants) {
    if (v.key.noise() != distribution) continue;
    for (const auto& s : streams_of(v)) {
      const auto* c = find_pass(v, "chi2", s);
      const auto* t = find_pass(v, "ttest", s);
      o << "| " << v.key.label_and_seeding() << " | "
        << (s == "x" ? "" : s) << " | " << (c ? pass_cell(*c) : "–") << " | " << (t ? pass_cell(*t) : "–")
        << " |\n";
    }
  }
  return o.str();
}

std::string pass_table_csv(const Analysis& a) {
  std::ostringstream o;
  o << "generator,rounds,distribution,seeding,dt,output,test,trials,passed,fraction,ci_low,ci_high,binomial_p,"
       "p_adjusted,differs\n";
  for (const auto& v : a.variants)
    for (const auto& p : v.passes)
      o << v.key.generator << ',' << v.key.rounds << ',' << v.key.noise() << ',' << v.key.seeding_name() << ','
        << num(v.key.dt) << ',' << p.stream << ',' << p.test << ',' << p.trials << ',' << p.passed << ','
        << num(p.fraction) << ',' << num(p.ci_low) << ',' << num(p.ci_high) << ',' << detail::p_csv(p.decision.p) << ','
        << detail::p_csv(p.decision.p_adjusted) << ',' << int(p.decision.differs) << '\n';
  return o.str();
}

std::string observables_csv(const Analysis& a) {
  std::ostringstream o;
  o << "generator,rounds,distribution,seeding,dt,observable,shift,ci_low,ci_high,relative,margin,outcome,replicas,"
       "value,value_sd,reference_replicas,reference,reference_sd,error_rate,sigma,test,statistic,dof,dof2,p_value,"
       "p_adjusted,differs,p_equivalence,p_equivalence_adjusted,equivalent,score,score_runs,note\n";
  for (const auto& v : a.variants)
    for (const auto& c : v.observables)
      o << v.key.generator << ',' << v.key.rounds << ',' << v.key.noise() << ',' << v.key.seeding_name() << ','
        << num(v.key.dt) << ',' << c.observable << ',' << num(c.shift) << ',' << num(c.ci_low) << ','
        << num(c.ci_high) << ',' << int(c.relative) << ',' << num(c.margin) << ',' << to_string(c.outcome) << ','
        << c.n << ',' << num(c.value) << ',' << num(c.value_sd) << ','
        << c.n_ref << ',' << num(c.ref) << ',' << num(c.ref_sd) << ',' << num(c.error_rate) << ',' << num(c.sigma)
        << ',' << c.test << ',' << num(c.statistic) << ',' << num(c.dof) << ',' << num(c.dof2) << ','
        << detail::p_csv(c.decision.p) << ',' << detail::p_csv(c.decision.p_adjusted) << ',' << int(c.decision.differs) << ','
        << detail::p_csv(c.equivalence.p) << ',' << detail::p_csv(c.equivalence.p_adjusted) << ',' << int(c.equivalence.equivalent)
        << ',' << num(c.score) << ',' << num(c.score_runs) << ',' << csv_quote(c.note) << '\n';
  return o.str();
}

std::string observables_markdown(const Analysis& a, const std::string& distribution) {
  std::ostringstream o;
  // One column per observable: effect_cell, bold where the error control says it differs.
  std::vector<std::string> names;
  for (const auto& v : a.variants)
    for (const auto& c : v.observables)
      if (std::find(names.begin(), names.end(), c.observable) == names.end()) names.push_back(c.observable);
  if (names.empty()) return "(no observable comparisons yet)\n";
  o << "| generator |";
  for (const auto& n : names) o << ' ' << pretty(n) << " |";
  o << "\n|---|";
  for (std::size_t k = 0; k < names.size(); ++k) o << "---|";
  o << '\n';
  for (const auto& v : a.variants) {
    if (v.key.reference || v.key.noise() != distribution) continue;
    o << "| " << v.key.label() << ' ' << v.key.seeding_name() << " |";
    for (const auto& n : names) {
      const Comparison* c = nullptr;
      for (const auto& x : v.observables)
        if (x.observable == n) c = &x;
      if (!c || !c->available) {
        o << " – |";
        continue;
      }
      o << ' ' << effect_cell(*c) << " |";
    }
    o << '\n';
  }
  return o.str();
}

std::string summary_markdown(const Analysis& a) {
  std::ostringstream o;
  o << "| generator | distribution | seeding | replicas | verdict | smallest corrected p | NIST columns failed | "
       "ns per number | step (ms) | RNG share |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& v : a.variants) {
    o << "| " << v.key.label() << " | " << v.key.noise() << " | " << v.key.seeding_name()
      << " | " << v.cells.size() << (v.broken.empty() ? std::string() : fmt("+%.0f broken", double(v.broken.size())))
      << " | " << v.verdict << " | " << detail::p_text(v.min_p) << " | "
      << (std::isfinite(v.nist_failed) ? fmt("%.0f", v.nist_failed) + " / " + fmt("%.0f", v.nist_columns) : "–")
      << " | " << fmt("%.2f", v.ns_per_number) << " | " << fmt("%.3f", v.step_ms) << " | "
      << fmt("%.0f %%", 100 * v.rng_share) << " |\n";
  }
  return o.str();
}

std::string summary_csv(const Analysis& a) {
  std::ostringstream o;
  o << "generator,rounds,distribution,seeding,dt,replicas,broken,verdict,min_p_adjusted,min_p_what,"
       "nist_failed_columns,nist_columns,ns_per_number,step_ms,rng_share\n";
  for (const auto& v : a.variants)
    o << v.key.generator << ',' << v.key.rounds << ',' << v.key.noise() << ','
      << v.key.seeding_name() << ',' << num(v.key.dt) << ',' << v.cells.size() << ','
      << v.broken.size() << ',' << csv_quote(v.verdict) << ',' << detail::p_csv(v.min_p) << ',' << csv_quote(v.min_p_what)
      << ',' << num(v.nist_failed) << ',' << num(v.nist_columns) << ','
      << num(v.ns_per_number) << ',' << num(v.step_ms) << ','
      << num(v.rng_share) << '\n';
  return o.str();
}

std::string cost_markdown(const Analysis& a) {
  std::ostringstream o;
  o << "| generator | distribution | ns per number | step (ms) | RNG share of the step | run time vs 8 rounds |\n"
       "|---|---|---|---|---|---|\n";
  for (const auto& v : a.variants) {
    double at8 = NAN;
    for (const auto& w : a.variants)
      if (w.key.generator == v.key.generator && w.key.rounds == 8 && w.key.noise() == v.key.noise() &&
          w.key.seeding_name() == v.key.seeding_name() && w.key.dt == v.key.dt)
        at8 = w.step_ms;
    o << "| " << v.key.label() << " | " << v.key.noise() << " | " << fmt("%.2f", v.ns_per_number) << " | "
      << fmt("%.3f", v.step_ms) << " | " << fmt("%.0f %%", 100 * v.rng_share) << " | "
      << speed_vs_8(at8, v.step_ms) << " |\n";
  }
  return o.str();
}

std::string nist_final_analysis_report(const VariantReport& v, double alpha) {
  std::ostringstream o;
  const char* rule = "------------------------------------------------------------------------------\n";
  o << rule << "RESULTS FOR THE UNIFORMITY OF P-VALUES AND THE PROPORTION OF PASSING SEQUENCES\n" << rule
    << "   generator is <" << v.key.label() << " " << v.key.noise() << ", cell " << v.nist_cell << ">\n"
    << rule << " C1  C2  C3  C4  C5  C6  C7  C8  C9 C10  P-VALUE  PROPORTION  STATISTICAL TEST\n" << rule;
  std::size_t fail_prop = 0, fail_unif = 0;
  double max_m = 0;
  for (const auto& r : v.nist) {
    char line[160];
    int at = 0;
    for (double c : r.histogram) at += std::snprintf(line + at, sizeof line - std::size_t(at), "%3.0f ", c);
    std::string p = r.applicable > 0 ? fmt("%.6f", r.p_uniformity) : "   ----";
    if (r.applicable > 0 && !r.uniformity_ok) p += " *";
    else p += "  ";
    char prop[32];
    std::snprintf(prop, sizeof prop, "%4.0f/%-4.0f%s", r.passed, r.applicable,
                  r.applicable > 0 && !r.proportion_ok ? " *" : "  ");
    o << line << ' ' << p << "  " << prop << "   " << r.test
      << (r.variant.empty() || r.variant == "-" ? "" : " " + r.variant) << '\n';
    fail_prop += r.applicable > 0 && !r.proportion_ok;
    fail_unif += r.applicable > 0 && !r.uniformity_ok;
    max_m = std::max(max_m, r.applicable);
  }
  o << "\n\n" << rule
    << "The minimum pass rate for each statistical test with the exception of the\n"
       "random excursion (variant) test is approximately = "
    << fmt("%.6f", stats::nist::proportion_range(alpha, std::max(1.0, max_m)).low) << " for a\n"
    << "sample size = " << max_m << " binary sequences.\n\n"
    << "The minimum pass rate for the random excursion (variant) test is computed from\n"
       "the number of sequences with enough cycles (the PROPORTION denominator).\n\n"
    << "For further guidelines construct a probability table using the MAPLE program\n"
       "provided in the addendum section of the documentation.\n"
    << rule << "Summary: " << fail_prop << " of " << v.nist.size()
    << " P-value series fail the proportion bound, " << fail_unif << " fail the uniformity test (P_T < 0.0001).\n";
  return o.str();
}

}  // namespace dpdrng::study

namespace dpdrng::study {
namespace {

const Comparison* find_observable(const VariantReport& v, const std::string& name) {
  for (const auto& c : v.observables)
    if (c.observable == name && c.available) return &c;
  return nullptr;
}

// The measured shift of k_BT against the reference, (T − T_MT) / T_MT, and its 1σ (the comparison's).
std::string measured_shift(const VariantReport& v) {
  const Comparison* t = find_observable(v, kinetic_temperature().name);
  if (!t || !(t->ref != 0)) return "–";
  const std::string b = t->decision.differs ? "**" : "";
  std::string s = b + fmt("%+.2f %%", 100 * (t->value - t->ref) / t->ref) + b;
  if (std::isfinite(t->sigma)) s += " ± " + fmt("%.2f %%", 100 * 1.959963984540054 * t->sigma);
  return s;
}

std::string interval(const stats::Interval& i) { return "[" + fmt("%.4f", i.low) + ", " + fmt("%.4f", i.high) + "]"; }

// The variant's flag for a group of pass fractions: "flag" when any of its streams differs.
std::string pass_flag(const VariantReport& v, const std::string& test) {
  bool any = false, differs = false;
  for (const auto& p : v.passes)
    if (p.test == test && p.available && p.trials > 0) any = true, differs |= p.decision.differs;
  return any ? (differs ? "**flags**" : "pass") : "–";
}

// The NIST battery reads the pair's first block, the same words under every feed: a variant of another feed
// shows the battery of its halves sibling (or of the feed that ran it).
const VariantReport* nist_source(const Analysis& a, const VariantReport& v) {
  if (!v.nist.empty()) return &v;
  for (const auto& w : a.variants)
    if (!w.nist.empty() && w.key.generator == v.key.generator && w.key.rounds == v.key.rounds &&
        w.key.seeding_name() == v.key.seeding_name() && w.key.dt == v.key.dt && w.key.reference == v.key.reference &&
        w.key.distribution == v.key.distribution)
      return &w;
  return nullptr;
}

std::string physics_flags(const VariantReport& v) {
  std::string out;
  for (const auto& c : v.observables)
    if (c.available && c.decision.differs) out += (out.empty() ? "" : ", ") + pretty(c.observable);
  if (v.observables.empty() || !v.no_reference.empty()) return "–";
  return out.empty() ? "pass" : "**" + out + "**";
}

}  // namespace

namespace {

// The shift the effective noise power predicts, ± 1.96 standard errors, and the lags behind it; "n/a" without it.
std::string power_shift(const VariantReport& v) {
  if (!std::isfinite(v.power_predicted_shift.value)) return "n/a";
  return fmt("%+.2f", 100 * v.power_predicted_shift.value) + fmt(" ± %.2f %%", 196 * v.power_predicted_shift.se) +
         " (ρ to lag " + std::to_string(v.power_lags) + ")";
}

}  // namespace

std::string zeta_markdown(const Analysis& a) {
  std::ostringstream o;
  o << "| generator | noise | seeding | replicas | ζ draws | ⟨ζ²⟩ [95 % CI] | excess kurtosis | ⟨ζ²⟩ = 1: corrected p | "
       "T shift predicted by ⟨ζ²⟩ | T shift predicted by the effective power (95 %) | T shift measured vs MT (95 %) |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& v : a.variants) {
    if (v.zeta.n == 0) continue;
    const std::string b = v.zeta_decision.differs ? "**" : "";
    o << "| " << v.key.label() << " | " << v.key.noise() << " | " << v.key.seeding_name()
      << " | " << v.cells.size() << " | " << fmt("%.3g", double(v.zeta.n)) << " | " << b
      << fmt("%.4f", v.zeta.second_moment) << b << " " << interval(v.zeta.second_moment_ci)
      << " | " << fmt("%.3f", v.zeta.kurtosis) << " | " << adjusted(v.zeta_decision) << " | "
      << (v.key.reference ? "(reference)" : fmt("%+.2f %%", 100 * v.zeta_predicted_shift)) << " | "
      << (v.key.reference ? "(reference)" : power_shift(v)) << " | "
      << (v.key.reference ? "(reference)" : measured_shift(v)) << " |\n";
  }
  return o.str();
}

namespace {

// The temperature's measured shift against the reference as a fraction of the reference's value, with its 1σ and
// 95 % CI: the water's relative comparison as it is, the membrane's paired (absolute) one divided by the
// reference's mean. NaN without a comparison.
struct MeasuredShift {
  double shift = NAN, sigma = NAN, ci_low = NAN, ci_high = NAN;
};
MeasuredShift measured_temperature_shift(const VariantReport& v) {
  const Comparison* t = nullptr;
  for (const auto& c : v.observables)
    if (!t && c.available && is_kinetic_temperature(c.observable)) t = &c;
  if (!t || !(t->ref != 0)) return {};
  const double scale = t->relative ? 1.0 : std::abs(t->ref);
  return {(t->value - t->ref) / t->ref, t->sigma / scale, t->ci_low / scale, t->ci_high / scale};
}

}  // namespace

std::string zeta_csv(const Analysis& a) {
  std::ostringstream o;
  o << "generator,rounds,distribution,feed,seeding,dt,replicas,zeta_n,zeta_mean,zeta_variance,variance_ci_low,"
       "variance_ci_high,second_moment,second_moment_ci_low,second_moment_ci_high,skewness,excess_kurtosis,p,p_adjusted,"
       "predicted_T_shift,power_predicted_T_shift,power_predicted_T_shift_se,power_lags,measured_T_shift,"
       "measured_T_shift_sigma,measured_T_shift_ci_low,measured_T_shift_ci_high,integrator\n";
  for (const auto& v : a.variants) {
    // The membrane's cells hold no tapped ζ, only the force's weighted ⟨ζ²⟩ and its correlations.
    if (v.zeta.n == 0 && !std::isfinite(v.noise_power.value)) continue;
    const MeasuredShift m = measured_temperature_shift(v);
    o << v.key.generator << ',' << v.key.rounds << ',' << v.key.noise() << ',' << rng::to_string(v.key.feed) << ','
      << v.key.seeding_name() << ',' << num(v.key.dt) << ',' << v.cells.size() << ','
      << v.zeta.n << ',' << num(v.zeta.mean) << ',' << num(v.zeta.variance) << ',' << num(v.zeta.variance_ci.low)
      << ',' << num(v.zeta.variance_ci.high) << ',' << num(v.zeta.second_moment) << ','
      << num(v.zeta.second_moment_ci.low) << ',' << num(v.zeta.second_moment_ci.high) << ',' << num(v.zeta.skewness)
      << ',' << num(v.zeta.kurtosis) << ',' << detail::p_csv(v.zeta_decision.p) << ',' << detail::p_csv(v.zeta_decision.p_adjusted)
      << ',' << num(v.zeta_predicted_shift) << ',' << num(v.power_predicted_shift.value) << ','
      << num(v.power_predicted_shift.se) << ',' << v.power_lags << ',' << num(m.shift) << ',' << num(m.sigma) << ','
      << num(m.ci_low) << ',' << num(m.ci_high) << ',' << detail::csv_quote(v.key.integrator) << '\n';
  }
  return o.str();
}

std::string flags_markdown(const Analysis& a) {
  std::ostringstream o;
  o << "| generator | noise | seeding | χ² | lag-1 t | NIST columns failed | ⟨ζ²⟩ = 1 | physics (observables that "
       "differ from MT) |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& v : a.variants) {
    if (v.key.reference) continue;
    const VariantReport* n = nist_source(a, v);
    std::string nist = "–";
    if (n && std::isfinite(n->nist_failed))
      nist = fmt("%.0f", n->nist_failed) + " / " + fmt("%.0f", n->nist_columns) +
             (n == &v ? "" : " (words of " + n->key.noise() + ")");
    const std::string zeta = !v.zeta_decision.tested() ? "–"
                             : v.zeta_decision.differs ? "**flags** (" + fmt("%.4f", v.zeta.second_moment) + ")"
                                                       : "pass";
    o << "| " << v.key.label() << " | " << v.key.noise() << " | " << v.key.seeding_name() << " | "
      << pass_flag(v, "chi2") << " | " << pass_flag(v, "ttest") << " | " << nist << " | " << zeta << " | "
      << physics_flags(v) << " |\n";
  }
  return o.str();
}

}  // namespace dpdrng::study
