// verdicts.csv and the report's verdict table: one row per variant × observable with its shift, 95 % CI,
// margin and outcome, and one row per variant ("all") with the variant's verdict.
#include <cmath>
#include <map>
#include <sstream>

#include "dpdrng/stats/binomial.hpp"
#include "dpdrng/study/observables.hpp"
#include "dpdrng/study/report.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace {

using detail::fmt;
using detail::num;

struct VerdictRow {
  const VariantReport* v;
  std::string observable;
  double shift = NAN, ci_low = NAN, ci_high = NAN, margin = NAN, p_adjusted = NAN, p_equivalence = NAN;
  Outcome outcome = Outcome::none;
};

// A test without a margin can flag a difference but never show equivalence.
Outcome flag_of(const Decision& d) { return d.differs ? Outcome::differs : Outcome::inconclusive; }

void verdict_rows_of(const Analysis& a, const VariantReport& v, std::vector<VerdictRow>& out) {
  for (const auto& c : v.observables)
    if (c.outcome != Outcome::none)
      out.push_back({&v, c.observable, c.shift, c.ci_low, c.ci_high, c.margin, c.decision.p_adjusted,
                     c.equivalence.p_adjusted, c.outcome});
  if (v.zeta_decision.tested())
    out.push_back({&v, "zeta_second_moment", v.zeta.second_moment - 1, v.zeta.second_moment_ci.low - 1,
                   v.zeta.second_moment_ci.high - 1, NAN, v.zeta_decision.p_adjusted, NAN, flag_of(v.zeta_decision)});
  for (const auto& p : v.passes)
    if (p.available && p.decision.tested()) {
      const auto [low, high] = stats::clopper_pearson(p.passed, p.trials, 0.95);
      const double target = 1 - a.alpha;
      out.push_back({&v, "pass_" + p.test + "_" + p.stream, p.fraction - target, low - target, high - target, NAN,
                     p.decision.p_adjusted, NAN, flag_of(p.decision)});
    }
  for (const auto& c : v.correlations)
    if (c.available && c.decision.tested())
      out.push_back({&v, "zeta_correlation_" + c.what, c.worst_r, NAN, NAN, NAN, c.decision.p_adjusted, NAN,
                     flag_of(c.decision)});
  out.push_back({&v, "all", NAN, NAN, NAN, NAN, v.min_p, NAN, v.outcome});
}

std::vector<VerdictRow> verdict_rows(const Analysis& a) {
  std::vector<VerdictRow> out;
  for (const auto& v : a.variants)
    if (!v.key.reference && v.outcome != Outcome::none) verdict_rows_of(a, v, out);
  return out;
}

// Every observable with a margin, in table order: its name and margin in force.
std::vector<std::pair<std::string, double>> all_margins(const Analysis& a) {
  std::vector<std::pair<std::string, double>> out;
  const auto in_force = [&](const char* key, double fallback) {
    const auto it = a.margins.find(key);
    return it == a.margins.end() ? fallback : it->second;
  };
  for (const auto& s : scalar_observables()) out.push_back({s.name, in_force(s.margin_key, s.margin)});
  for (const auto& c : curve_observables()) out.push_back({c.name, in_force(c.margin_key, c.margin)});
  return out;
}

// The observables with a margin that some variant holds, in table order, with the margin.
std::vector<std::pair<std::string, double>> margin_observables(const Analysis& a) {
  std::vector<std::pair<std::string, double>> names;
  for (const auto& m : all_margins(a)) {
    bool held = false;
    for (const auto& v : a.variants)
      for (const auto& c : v.observables) held = held || (c.observable == m.first && std::isfinite(c.margin));
    if (held) names.push_back(m);
  }
  return names;
}

std::string pct_text(double x) { return fmt("%+.2f", 100 * x); }

std::string verdict_cell(const Comparison& c) {
  if (c.outcome == Outcome::none) return "–";
  const std::string b = c.outcome == Outcome::differs ? "**" : "";
  std::string s = b + (c.relative ? pct_text(c.shift) : fmt("%+.3g", c.shift)) + b;
  if (std::isfinite(c.ci_low))
    s += " [" + (c.relative ? pct_text(c.ci_low) + ", " + pct_text(c.ci_high) : fmt("%+.3g", c.ci_low) + ", " +
                                                                                fmt("%+.3g", c.ci_high)) + "]";
  return s + " " + to_string(c.outcome);
}

}  // namespace

std::string verdicts_csv(const Analysis& a) {
  std::ostringstream o;
  o << "variant,seeding,distribution,feed,integrator,dt,replicas,observable,shift,ci_low,ci_high,margin,p_adjusted,"
       "p_equivalence_adjusted,verdict\n";
  for (const auto& r : verdict_rows(a)) {
    const VariantKey& k = r.v->key;
    const bool uniform = k.distribution == rng::Distribution::uniform;
    o << detail::csv_line({k.label(), k.seeding_name(), std::string(rng::to_string(k.distribution)),
                           uniform ? std::string() : std::string(rng::to_string(k.feed)), k.integrator, num(k.dt),
                           std::to_string(r.v->cells.size()), r.observable, num(r.shift), num(r.ci_low),
                           num(r.ci_high), num(r.margin), detail::p_csv(r.p_adjusted), detail::p_csv(r.p_equivalence),
                           to_string(r.outcome)});
  }
  return o.str();
}

std::string verdict_table_markdown(const Analysis& a) {
  const auto names = margin_observables(a);
  std::ostringstream o;
  o << "| variant | noise | seeding | replicas | verdict |";
  for (const auto& [n, margin] : names)
    o << ' ' << observable_label(n) << " shift % [95 % CI] (δ = " << fmt("%g", 100 * margin) << " %) |";
  o << " tests without a margin that differ |\n|---|---|---|---|---|";
  for (std::size_t k = 0; k < names.size(); ++k) o << "---|";
  o << "---|\n";
  std::vector<VerdictRow> all = verdict_rows(a);
  for (const auto& v : a.variants) {
    if (v.key.reference) continue;
    o << "| " << v.key.label() << " | " << v.key.noise() << " | " << v.key.seeding_name() << " | " << v.cells.size()
      << " | " << (v.outcome == Outcome::differs ? "**" + v.verdict + "**" : v.verdict) << " |";
    for (const auto& [n, margin] : names) {
      const Comparison* c = nullptr;
      for (const auto& x : v.observables)
        if (x.observable == n) c = &x;
      o << ' ' << (c ? verdict_cell(*c) : "–") << " |";
    }
    std::string flagged;
    for (const auto& r : all)
      if (r.v == &v && r.outcome == Outcome::differs && !std::isfinite(r.margin) && r.observable != "all")
        flagged += (flagged.empty() ? "" : ", ") + r.observable;
    o << ' ' << (flagged.empty() ? "none" : flagged) << " |\n";
  }
  return o.str();
}

std::string score_check_markdown(const Analysis& a) {
  const auto checks = score_dispersion(a, known_good);
  if (checks.empty())
    return "No variant of this study is a generator known to be good (philox4x32, threefry2x64, splitmix64, TEA at "
           "16 rounds or more), so it holds no null comparison to check the error model on; the test suite checks "
           "it on a null study (StudyErrorModel) and tools/z_dispersion.py on any report/cells.csv.\n";
  std::ostringstream o;
  o << "Null comparisons: the variants of generators known to be good (philox4x32, threefry2x64, splitmix64, TEA "
       "at 16 rounds or more) against the reference. Under a right error model each shift's normal score has "
       "variance 1; the ratio is its mean square over the null comparisons, with a 95 % χ² interval (variants "
       "that share a reference share its noise, so the interval is too narrow by an unknown amount).\n\n"
    << "| observable | null comparisons | replicas' spread (used) [95 % CI] | runs' block errors pooled [95 % CI] |\n"
       "|---|---|---|---|\n";
  const auto ratio = [](const stats::Dispersion& d) {
    return fmt("%.2f", d.ratio) + " [" + fmt("%.2f", d.low) + ", " + fmt("%.2f", d.high) + "]";
  };
  for (const auto& c : checks)
    o << "| " << observable_label(c.observable) << " | " << c.chosen.k << " | " << ratio(c.chosen) << " | "
      << (c.runs.k ? ratio(c.runs) : "–") << " |\n";
  return o.str();
}

namespace {

std::string calibrated_text(const std::map<std::string, Rate>& calibrated, const std::string& observable) {
  const auto it = calibrated.find(observable);
  if (it == calibrated.end()) return "";
  const Rate& r = it->second;
  return std::to_string(r.events) + "/" + std::to_string(r.trials) + " = " + fmt("%.1f", 100 * r.rate) + " % [" +
         fmt("%.1f", 100 * r.low) + ", " + fmt("%.1f", 100 * r.high) + "]";
}

std::string needed_text(const EquivalenceReplicas& r) {
  if (r.needed > 0) return std::to_string(r.needed) + " (reference " +
                           std::to_string(int(std::ceil(double(r.needed) * r.reference_replicas / r.replicas))) + ")";
  return r.needed == 0 ? "more than 100 000" : "not applicable: " + r.not_modelled;
}

}  // namespace

std::string equivalence_replicas_csv(const std::vector<EquivalenceReplicas>& rows,
                                     const std::map<std::string, Rate>& calibrated) {
  std::ostringstream o;
  o << "observable,margin,comparisons,replica_sd,dof,replicas,reference_replicas,threshold,predicted_equivalent,"
       "replicas_for_90,calibrated_equivalent,calibrated_trials,calibrated_low,calibrated_high,note\n";
  for (const auto& r : rows) {
    const auto it = calibrated.find(r.observable);
    const bool cal = it != calibrated.end();
    o << r.observable << "," << num(r.margin) << "," << r.comparisons << "," << num(r.sd) << "," << num(r.dof)
      << "," << (r.replicas ? std::to_string(r.replicas) : "") << ","
      << (r.reference_replicas ? std::to_string(r.reference_replicas) : "") << "," << num(r.threshold) << ","
      << num(r.power_now) << "," << (r.needed >= 0 ? std::to_string(r.needed) : "") << ","
      << (cal ? num(it->second.rate) : "") << "," << (cal ? std::to_string(it->second.trials) : "") << ","
      << (cal ? num(it->second.low) : "") << "," << (cal ? num(it->second.high) : "") << ","
      << (r.not_modelled.empty() ? "" : detail::csv_quote("not modelled: " + r.not_modelled)) << "\n";
  }
  return o.str();
}

std::string equivalence_replicas_markdown(const std::vector<EquivalenceReplicas>& rows,
                                          const std::map<std::string, Rate>& calibrated) {
  if (rows.empty()) return "No observable of this study has an equivalence margin.\n";
  int replicas = 0;
  for (const auto& r : rows) replicas = replicas ? replicas : r.replicas;
  std::ostringstream o;
  o << "How many replicas a generator as good as the reference needs to come out *equivalent* 90 % of the time: "
       "the two one-sided tests at Holm's strictest threshold α/m = "
    << fmt("%.2g", rows.front().threshold)
    << ", a shift's standard error s × √(1/R + 1/R_ref) with s one replica's spread under the error model (median "
       "over the variants' comparisons) and R_ref/R kept at this study's ratio, Student t on the comparisons' "
       "degrees of freedom. A model: it adds no degrees of freedom with R and ignores Holm's looser later "
       "thresholds (both make it ask for more replicas than needed), and it leaves out the comparisons whose "
       "replicas scatter more than the pool (5 % of good ones, judged on their own spread alone, which rarely "
       "pass). Runs n times as long shrink s about √n-fold, so replicas × steps is what an observable needs. "
    << (calibrated.empty() ? "No calibration at this study's own size was found to check the model against."
                           : "*Calibrated*: the rate at which good generators came out equivalent in the null "
                             "studies at this study's own size (95 % Clopper–Pearson), the model's check.")
    << " The table is `equivalence_replicas.csv`.\n\n"
    << "| observable | margin | s (per replica) | predicted at R = " << replicas
    << (calibrated.empty() ? "" : " | calibrated at the same R") << " | replicas for 90 % |\n|---|---|---|---|"
    << (calibrated.empty() ? "" : "---|") << "---|\n";
  for (const auto& r : rows) {
    o << "| " << observable_label(r.observable) << " | ±" << fmt("%.3g", 100 * r.margin) << " % | "
      << (std::isfinite(r.sd) ? fmt("%.3g", 100 * r.sd) + " %" : "–") << " | "
      << (std::isfinite(r.power_now) ? fmt("%.1f", 100 * r.power_now) + " %" : "–") << " | ";
    if (!calibrated.empty()) o << calibrated_text(calibrated, r.observable) << " | ";
    o << needed_text(r) << " |\n";
  }
  return o.str();
}

std::string how_to_read_verdicts(const StudyConfig& config, const Analysis& a) {
  std::ostringstream o;
  o << "**How to read a verdict.** A verdict compares one variant with " << config.reference
    << " under the same assumptions: the variant's pair seeding of the noise (distance: the separation's bits; "
       "pair-step: pair ids and step), its distribution (gauss, uniform) and, for the Gaussian, its feed "
       "(halves, blocks, inverse), the same integrator and Δt, the same scene and initial states, "
    << config.replicas << " replicas of the variant and " << config.reference_replica_count()
    << " of the reference; it holds for those settings only. *Equivalent*: for every observable with a margin δ, the "
       "shift's (1 − 2α′) confidence interval lies inside ±δ (two one-sided tests, α′ Holm's threshold over the "
       "study's equivalence tests), and no test differs. *Differs*: some test rejects equality after the error "
       "control below. *Inconclusive*: neither — the replicas cannot tell a shift smaller than δ from one larger. "
       "Margins (shifts relative to the reference's value; curves bin by bin): ";
  bool first = true;
  for (const auto& d : margin_defaults()) {
    const double m = a.margins.count(d.key) ? a.margins.at(d.key) : d.margin;
    o << (first ? "" : ", ") << d.key << " " << fmt("%g", 100 * m) << " %";
    first = false;
  }
  o << " ([tests.margins] of the config). Tests without a margin (⟨ζ²⟩ = 1, pass fractions, ζ correlations) "
       "can make a variant differ but cannot make it equivalent. Each table leads with the shift and its 95 % "
       "CI; P-values are secondary, corrected, and printed no smaller than 1e-12.\n";
  return o.str();
}

}  // namespace dpdrng::study
