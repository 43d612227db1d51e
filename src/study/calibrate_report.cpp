// The calibration's outputs (summary.md, calibration.json, CSV, charts) and the detection-limit sentence that
// every study report reads back from a committed calibration.json.
#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/calibrate.hpp"
#include "report_chart.hpp"
#include "report_common.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;

namespace {

nlohmann::json rate_json(const Rate& r) {
  return {{"events", r.events}, {"trials", r.trials}, {"rate", r.rate}, {"ci95_low", r.low}, {"ci95_high", r.high}};
}

Rate rate_from(const nlohmann::json& j) {
  Rate r;
  r.events = j.at("events").get<std::size_t>(), r.trials = j.at("trials").get<std::size_t>();
  r.rate = j.at("rate").is_number() ? j.at("rate").get<double>() : NAN;
  r.low = j.at("ci95_low").get<double>(), r.high = j.at("ci95_high").get<double>();
  return r;
}

std::string pct(double x, const char* f = "%.2f") {
  if (!std::isfinite(x)) return "–";
  char buf[32];
  std::snprintf(buf, sizeof buf, f, 100 * x);
  return std::string(buf) + " %";
}

std::string rate_text(const Rate& r) {
  return std::to_string(r.events) + "/" + std::to_string(r.trials) + " = " + pct(r.rate) + " [" + pct(r.low) + ", " +
         pct(r.high) + "]";
}

// The config's replica row's null P-values, sorted, and the half-width ε = √(ln(2/0.05) / (2n)) of the
// simultaneous 95 % band of the Dvoretzky–Kiefer–Wolfowitz inequality (Massart's constant) around the uniform
// quantiles (i − ½)/n.
struct NullQuantiles {
  std::vector<double> p;
  double eps = NAN;
};
NullQuantiles null_quantiles(const NullRow& row) {
  NullQuantiles q{row.p_values, NAN};
  std::sort(q.p.begin(), q.p.end());
  if (!q.p.empty()) q.eps = std::sqrt(std::log(2 / 0.05) / (2 * double(q.p.size())));
  return q;
}

const char* kind_what(const std::string& kind) {
  if (kind == "variance") return "ε (⟨ζ²⟩ = 1 + ε)";
  if (kind == "lag1") return "ρ (lag-1 correlation)";
  if (kind == "aniso") return "κ (variance × (1 + κ(3cos²θ − 1)))";
  return "μ (mean shift)";
}

std::string threshold_text(const Threshold& t) {
  if (t.below) return "≤ " + detail::fmt("%.3g", t.size) + " (the smallest tested)";
  if (t.above) return "> largest tested";
  return detail::fmt("%.3g", t.size);
}

// T error per unit of ε, from the variance rows (the DPD thermostat sets kT ∝ σ², so ≈ 1).
double temperature_per_epsilon(const std::vector<PowerRow>& rows) {
  double s = 0;
  std::size_t n = 0;
  for (const auto& r : rows)
    if (r.kind == "variance" && r.size != 0 && std::isfinite(r.temperature_error)) s += r.temperature_error / r.size, ++n;
  return n ? s / double(n) : NAN;
}

void false_alarm_section(const Calibration& c, std::ostream& md) {
  md << "## False alarms\n\n| replicas | null verdicts \"differs\" | studies with any \"differs\" |\n|---|---|---|\n";
  for (const auto& n : c.nulls)
    md << "| " << n.replicas << " | " << rate_text(n.verdicts) << " | " << rate_text(n.studies) << " |\n";
  md << "\nα = " << c.alpha << " bounds the second column's rate under study-wise control (the reference's own "
     << "tests are in the family too).\n\n";
  for (const auto& n : c.nulls) {
    if (n.replicas != c.config_replicas || n.p_values.empty()) continue;
    const auto [p, eps] = null_quantiles(n);
    const double m = double(p.size());
    std::size_t above = 0, below = 0;  // larger P than uniform (conservative), smaller (liberal)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double e = (double(i) + 0.5) / m;
      above += p[i] > e + eps, below += p[i] < e - eps;
    }
    // By reference to the vector, not to the binding: clang before 16 cannot capture a structured binding.
    const auto at = [&sorted = p, m](double q) {
      return detail::num(sorted[std::min(sorted.size() - 1, std::size_t(q * m))]);
    };
    md << "Null P-values (`null_p_qq.csv`, `charts/null_p_qq.png`): the " << p.size()
       << " raw two-sided P-values of every test of every good-generator variant at " << n.replicas
       << " replicas against the uniform distribution, with the simultaneous 95 % band of the "
          "Dvoretzky–Kiefer–Wolfowitz inequality (±"
       << detail::num(eps) << " in P): " << above << " lie above it (larger P than uniform: conservative tests) and "
       << below << " below it (liberal). Their 1 %, 5 %, 25 % and 50 % quantiles: " << at(0.01) << ", " << at(0.05)
       << ", " << at(0.25) << ", " << at(0.5)
       << ". The tests of one study share its reference, so the P-values are not independent and the band is a "
          "guide, not a test. Smallest: "
       << detail::p_text(p.front()) << ".\n\n";
  }
}

void cost_section(const Calibration& c, std::ostream& md) {
  md << "## Cost\n\n" << c.cells << " cells (" << c.computed << " computed by the last invocation, " << c.resumed
     << " resumed, " << c.failed << " failed); wall time " << detail::fmt("%.0f", c.wall_total)
     << " s over every invocation on this pool (the last " << detail::fmt("%.0f", c.seconds)
     << " s); compute time of all cells " << detail::fmt("%.0f", c.cell_seconds)
     << " s (the cells' own wall times, each process computing one cell at a time; on a shared machine they carry "
        "its load); "
     << "machine: " << c.machine << ".\n";
}


// The at-size calibration: null studies with the config's variants, and how often they come out equivalent.
std::string at_size_markdown(const Calibration& c) {
  std::ostringstream md;
  md << "# Calibration of the study verdicts at the study's own size: " << c.config_name << "\n\n"
     << "How often the verdicts of a study with this config's variants, tests and Holm family call a good "
        "generator \"differs\" (false alarms), and how often they show it equivalent within the config's margins: "
     << c.steps << " steps (" << c.production << " production), α = " << c.alpha << ", error control over the "
     << c.error_control << ". Made by `dpdrng study calibrate --at-size`.\n\n"
     << "- **Null studies**: every variant slot of the config (generator × rounds, under every noise) holds its own "
        "good generator, `defect:key=k` (Philox4x32-10 under key (3, k, 5, 6), no defect), against the reference "
        "(MT19937), analysed exactly as `study report` analyses the study. Every variant verdict is a null verdict; "
        "a \"differs\" is a false alarm.\n"
     << "- One pool of " << c.pool_replicas << " variant replicas; null study s of R replicas compares replicas "
        "[sR, sR + R) with the same reference replicas (the same initial states) plus R_ref − R extra reference "
        "replicas of its own (R_ref = "
     << c.reference_replicas << ", the config's), so the studies of one replica count are disjoint and independent.\n"
     << "- Intervals: central 95 % Clopper–Pearson.\n"
     << "- Each null study is analysed once its cells are stored and kept in `pool/null-studies/` (its verdicts, "
        "P-values, equivalence outcomes and normal scores), so the calibration can be carried over several "
        "sittings in those files alone.\n\n";
  if (!c.nulls.empty() && int(c.nulls.front().studies.trials) < c.null_studies_planned)
    md << "**Partial:** " << c.nulls.front().studies.trials << " of the " << c.null_studies_planned
       << " null studies asked for are recorded; rerun the same command to add the others.\n\n";
  for (const auto& n : c.nulls)
    md << "- At " << n.replicas << " replicas a null study's Holm family holds " << n.tests_per_study
       << " tests. The config's own study states its own count in its report; the two differ where the study's "
          "generators give more streams (a 64-bit word's two halves each get χ² and lag-1 t tests), where it runs "
          "the NIST battery, and where a broken variant leaves tests not applicable.\n";
  md << "\n";
  false_alarm_section(c, md);
  if (!c.equivalence.empty()) {
    md << "## Equivalence of good generators\n\nThe fraction of null variant verdicts (slot × noise) whose "
          "equivalence test passes (Holm over the study's equivalence tests): the replicas a good generator needs "
          "to be shown equivalent at the config's margins.\n\n"
       << "| replicas | reference replicas | observable | margin | shown equivalent [95 % CI] |\n|---|---|---|---|---|\n";
    for (const auto& e : c.equivalence)
      md << "| " << e.replicas << " | " << e.reference_replicas << " | " << e.observable << " | "
         << detail::num(e.margin) << " | " << rate_text(e.equivalent) << " |\n";
    md << "\n";
  }
  if (!c.dispersion.empty()) {
    const std::size_t studies = c.nulls.empty() ? 0 : c.nulls.front().studies.trials;
    md << "## Error model check\n\nEvery good variant's shift against the reference, as a normal score under "
          "the error model the verdicts use (stats::normal_score of its t): N(0, 1) when the standard errors are "
          "right. The ratio is the scores' mean square with its 95 % χ² interval (`score_dispersion.csv`); above 1 "
          "the standard errors are too small and the verdicts too bold, below 1 they are conservative. Variants of "
          "one null study share its reference replicas, so their scores are correlated and the interval is too "
          "narrow by an unknown amount. From the "
       << c.scored_studies << " of " << studies << " recorded null studies whose records hold scores.\n\n"
       << "| observable | comparisons | mean square [95 % CI] |\n|---|---|---|\n";
    for (const auto& d : c.dispersion)
      md << "| " << d.observable << " | " << d.scores.k << " | " << detail::fmt("%.3f", d.scores.ratio) << " ["
         << detail::fmt("%.3f", d.scores.low) << ", " << detail::fmt("%.3f", d.scores.high) << "] |\n";
    md << "\n";
  }
  cost_section(c, md);
  return md.str();
}

std::string summary_markdown(const Calibration& c) {
  if (c.at_size) return at_size_markdown(c);
  std::ostringstream md;
  md << "# Calibration of the study verdicts: " << c.config_name << "\n\n"
     << "How often the study's verdicts call a good generator \"differs\" (false alarms), and how large an injected "
        "defect must be before they do (power), for this config's scene and tests: "
     << c.steps << " steps (" << c.production << " production), α = " << c.alpha << ", error control over the "
     << c.error_control << ". Made by `dpdrng study calibrate`.\n\n"
     << "- **Null studies**: the reference (MT19937) and three generators known to be good (philox4x32(10), "
        "threefry2x64(20), splitmix64), analysed exactly as `study report` analyses a study. Each good generator's "
        "verdict is a null verdict; a \"differs\" is a false alarm.\n"
     << "- **Power studies**: the same cells plus one defect generator (`defect:variance=ε` etc.: Philox4x32-10 "
        "with ζ scaled by √(1+ε), see `dpdrng list`), a study of four variants; detected when the defect's verdict "
        "says \"differs\".\n"
     << "- One pool of " << c.pool_replicas << " replicas (the config's seeding of replica r); defect cells on the "
     << "first " << c.defect_replicas << ". A study of R replicas is a block of R consecutive pool replicas, so the "
     << "studies of one replica count are disjoint and independent; null and power studies of a block share its "
        "reference and good-generator cells.\n"
     << "- Intervals: central 95 % Clopper–Pearson.\n\n";
  false_alarm_section(c, md);
  if (!c.power.empty()) {
    md << "## Power\n\n| defect | size | replicas | detected [95 % CI] | T error (measured) |\n|---|---|---|---|---|\n";
    for (const auto& p : c.power)
      md << "| " << p.kind << " | " << detail::num(p.size) << " | " << p.replicas << " | " << rate_text(p.detected)
         << " | " << pct(p.temperature_error, "%.3f") << " |\n";
    md << "\n### Size detected with probability 50 % and 90 % (linear between the sizes that bracket it)\n\n"
       << "| defect | replicas | 50 % | 90 % |\n|---|---|---|---|\n";
    for (std::size_t k = 0; k + 1 < c.thresholds.size(); k += 2)
      md << "| " << kind_what(c.thresholds[k].kind) << " | " << c.thresholds[k].replicas << " | "
         << threshold_text(c.thresholds[k]) << " | " << threshold_text(c.thresholds[k + 1]) << " |\n";
    md << "\n" << detail::chart_link("power", "power against defect size") << "\n\n" << detail::chart_link("false_alarms", "false-alarm rates") << "\n\n";
  }
  cost_section(c, md);
  return md.str();
}

std::string false_alarms_csv(const Calibration& c) {
  std::ostringstream o;
  o << "replicas,null_verdicts,false_differs,rate,ci95_low,ci95_high,studies,studies_with_differs,study_rate,"
       "study_ci95_low,study_ci95_high\n";
  for (const auto& n : c.nulls)
    o << n.replicas << ',' << n.verdicts.trials << ',' << n.verdicts.events << ',' << n.verdicts.rate << ','
      << n.verdicts.low << ',' << n.verdicts.high << ',' << n.studies.trials << ',' << n.studies.events << ','
      << n.studies.rate << ',' << n.studies.low << ',' << n.studies.high << '\n';
  return o.str();
}

std::string score_dispersion_csv(const Calibration& c) {
  std::ostringstream o;
  o << "observable,studies,comparisons,ratio,ci95_low,ci95_high\n";
  for (const auto& d : c.dispersion)
    o << d.observable << "," << c.scored_studies << "," << d.scores.k << "," << detail::num(d.scores.ratio) << ","
      << detail::num(d.scores.low) << "," << detail::num(d.scores.high) << "\n";
  return o.str();
}

std::string equivalence_csv(const Calibration& c) {
  std::ostringstream o;
  o << "replicas,reference_replicas,observable,margin,verdicts,equivalent,rate,ci95_low,ci95_high\n";
  for (const auto& e : c.equivalence)
    o << e.replicas << ',' << e.reference_replicas << ',' << e.observable << ',' << e.margin << ','
      << e.equivalent.trials << ',' << e.equivalent.events << ',' << e.equivalent.rate << ',' << e.equivalent.low
      << ',' << e.equivalent.high << '\n';
  return o.str();
}

std::string power_csv(const Calibration& c) {
  std::ostringstream o;
  o << "kind,size,replicas,studies,detected,power,ci95_low,ci95_high,temperature_error\n";
  for (const auto& p : c.power)
    o << p.kind << ',' << p.size << ',' << p.replicas << ',' << p.detected.trials << ',' << p.detected.events << ','
      << p.detected.rate << ',' << p.detected.low << ',' << p.detected.high << ',' << p.temperature_error << '\n';
  return o.str();
}

// Detection probability against defect size, one panel per defect kind (small multiples), a line per replica
// count, with 95 % CIs; 50 % and 90 % as levels.
void power_chart(const Calibration& c, const fs::path& dir, bool run, std::ostream* log) {
  std::vector<std::string> kinds;
  for (const auto& p : c.power)
    if (p.size > 0 && std::find(kinds.begin(), kinds.end(), p.kind) == kinds.end()) kinds.push_back(p.kind);
  if (kinds.empty()) return;
  detail::Chart ch;
  ch.name = "power";
  ch.title = "Detection probability against defect size (" + c.config_name + ", α = " + detail::num(c.alpha) + ")";
  // One x label for every panel: each panel's title names its defect and its symbol.
  ch.x = detail::Axis{"defect size", "1", detail::Scale::log10};
  ch.y = detail::Axis{"P(verdict \"differs\"), 95 % CI", "1"};
  ch.columns = {"size", "power", "ci_low", "ci_high"};
  ch.key = "inside bottom right";
  ch.extra = "set yrange [0:1.05]\nset offsets graph 0.1, graph 0.1, 0, 0\n" + detail::hline(0.5, "", "#555555") +
             detail::hline(0.9, "", "#555555");
  if (kinds.size() > 1)
    for (const auto& k : kinds) ch.panels.push_back(kind_what(k));
  else
    ch.title += ": " + std::string(kind_what(kinds.front()));
  for (std::size_t panel = 0; panel < kinds.size(); ++panel) {
    std::map<int, detail::Line> lines;
    for (const auto& p : c.power) {
      if (p.kind != kinds[panel] || p.size <= 0) continue;
      detail::Line& l = lines[p.replicas];
      l.title = std::to_string(p.replicas) + " replicas";
      l.panel = panel;
      l.style = "using 2:3:4:5 with yerrorlines lw 2 pt 7 lc " + std::to_string(lines.size());
      l.rows.push_back({p.size, p.detected.rate, p.detected.low, p.detected.high});
    }
    for (auto& [r, l] : lines) ch.lines.push_back(l);
  }
  detail::render(ch, dir, run, log);
}

void false_alarm_chart(const Calibration& c, const fs::path& dir, bool run, std::ostream* log) {
  detail::Chart ch;
  ch.name = "false_alarms";
  ch.title = "False alarms of good generators (" + c.config_name + ")";
  ch.x = detail::Axis{"replicas per variant", "1"};
  ch.y = detail::Axis{"false-alarm rate, 95 % CI", "1"};
  ch.columns = {"replicas", "rate", "ci_low", "ci_high"};
  detail::Line v{"null verdicts \"differs\"", "using 2:3:4:5 with yerrorbars pt 7 ps 1.2", {}, {}};
  detail::Line s{"studies with any \"differs\"", "using 2:3:4:5 with yerrorbars pt 5 ps 1.2", {}, {}};
  double hi = 0;
  for (const auto& n : c.nulls) {
    v.rows.push_back({double(n.replicas) - 0.15, n.verdicts.rate, n.verdicts.low, n.verdicts.high});
    s.rows.push_back({double(n.replicas) + 0.15, n.studies.rate, n.studies.low, n.studies.high});
    hi = std::max(hi, double(n.replicas) + 1);
  }
  ch.extra = "set xrange [0:" + detail::num(hi) + "]\nset yrange [0:*]\n" + detail::hline(c.alpha, "α", "#B2182B");
  ch.lines = {v, s};
  detail::render(ch, dir, run, log);
}

// The null P-values of the config's replica count against the uniform distribution (null_quantiles), drawn on
// −log10 axes where small P-values, the ones that make "differs", are spread out.
const NullRow* config_row(const Calibration& c) {
  for (const auto& n : c.nulls)
    if (n.replicas == c.config_replicas) return &n;
  return nullptr;
}

std::string null_qq_csv(const Calibration& c) {
  std::ostringstream o;
  o << "rank,expected,observed,band_low,band_high\n";
  const NullRow* row = config_row(c);
  if (!row || row->p_values.empty()) return o.str();
  const auto [p, eps] = null_quantiles(*row);
  const double n = double(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double e = (double(i) + 0.5) / n;
    o << i + 1 << ',' << detail::num(e) << ',' << detail::num(p[i]) << ',' << detail::num(std::max(0.0, e - eps))
      << ',' << detail::num(std::min(1.0, e + eps)) << '\n';
  }
  return o.str();
}

void null_qq_chart(const Calibration& c, const fs::path& dir, bool run, std::ostream* log) {
  const NullRow* row = config_row(c);
  if (!row || row->p_values.empty()) return;
  const auto [p, eps] = null_quantiles(*row);
  const double n = double(p.size());
  const auto lg = [](double x) { return -std::log10(std::max(x, 1e-300)); };
  detail::Chart ch;
  ch.name = "null_p_qq";
  ch.title = "Null P-values against uniform (" + c.config_name + ", " + std::to_string(c.config_replicas) +
             " replicas, " + std::to_string(p.size()) + " tests), 95 % simultaneous band";
  ch.x = detail::Axis{"expected −log₁₀ p", "1"};
  ch.y = detail::Axis{"observed −log₁₀ p", "1"};
  ch.columns = {"expected", "observed"};
  ch.key = "inside top left";
  detail::Line obs{"null tests", "using 2:3 with points pt 7 ps 0.4", {}, {}};
  detail::Line lo{"95 % band", "using 2:3 with lines dt 2 lc rgb '#555555'", {}, {}};
  detail::Line hi{"", "using 2:3 with lines dt 2 lc rgb '#555555'", {}, {}};
  // Every test in the tail (expected p < 0.01), where a false alarm would show; a thinned bulk, so that a chart of
  // tens of thousands of tests stays small (null_p_qq.csv holds them all).
  const std::size_t stride = std::max<std::size_t>(1, p.size() / 2000);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double e = (double(i) + 0.5) / n;
    if (e >= 0.01 && i % stride != 0) continue;
    obs.rows.push_back({lg(e), lg(p[i])});
    if (e + eps < 1) lo.rows.push_back({lg(e), lg(e + eps)});
    if (e - eps > 0) hi.rows.push_back({lg(e), lg(e - eps)});
  }
  const double top = lg(0.5 / n);
  ch.lines = {obs, lo, hi, {"uniform", "using 2:3 with lines lc rgb '#B2182B'", {{0, 0}, {top, top}}, {}}};
  detail::render(ch, dir, run, log);
}

std::vector<fs::path> calibration_files(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (fs::is_regular_file(dir, ec)) return {dir};
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file() && e.path().filename() == "calibration.json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

nlohmann::json to_json(const Calibration& c) {
  nlohmann::json nulls = nlohmann::json::array(), power = nlohmann::json::array(), th = nlohmann::json::array();
  for (const auto& n : c.nulls)
    nulls.push_back({{"replicas", n.replicas},
                     {"verdicts", rate_json(n.verdicts)},
                     {"studies", rate_json(n.studies)},
                     {"tests_per_study", n.tests_per_study}});
  for (const auto& p : c.power)
    power.push_back({{"kind", p.kind}, {"size", p.size}, {"replicas", p.replicas},
                     {"detected", rate_json(p.detected)}, {"temperature_error", p.temperature_error}});
  nlohmann::json eq = nlohmann::json::array();
  for (const auto& e : c.equivalence)
    eq.push_back({{"replicas", e.replicas}, {"reference_replicas", e.reference_replicas},
                  {"observable", e.observable}, {"margin", e.margin}, {"equivalent", rate_json(e.equivalent)}});
  nlohmann::json dispersion = nlohmann::json::array();
  const auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  for (const auto& d : c.dispersion)
    dispersion.push_back({{"observable", d.observable}, {"comparisons", d.scores.k}, {"ratio", number(d.scores.ratio)},
                          {"ci95_low", number(d.scores.low)}, {"ci95_high", number(d.scores.high)}});
  for (const auto& t : c.thresholds)
    th.push_back({{"kind", t.kind}, {"replicas", t.replicas}, {"power", t.power},
                  {"size", std::isfinite(t.size) ? nlohmann::json(t.size) : nlohmann::json()},
                  {"below_smallest", t.below}, {"above_largest", t.above}});
  return {{"config", c.config_name},     {"key", c.scene},
          {"alpha", c.alpha},            {"error_control", c.error_control},
          {"steps", c.steps},            {"production_steps", c.production},
          {"config_replicas", c.config_replicas},
          {"pool_replicas", c.pool_replicas}, {"defect_replicas", c.defect_replicas},
          {"at_size", c.at_size},        {"reference_replicas", c.reference_replicas},
          {"null_studies_planned", c.null_studies_planned},
          {"false_alarms", nulls},       {"power", power},              {"equivalence", eq},
          {"score_dispersion", {{"studies", c.scored_studies}, {"rows", dispersion}}},
          {"thresholds", th},            {"cells", c.cells},
          {"computed", c.computed},      {"resumed", c.resumed},
          {"failed", c.failed},          {"wall_seconds", c.seconds}, {"wall_seconds_total", c.wall_total},
          {"cell_seconds", c.cell_seconds}, {"machine", c.machine}};
}

void write_calibration(const Calibration& c, const fs::path& dir, bool charts, std::ostream* log) {
  fs::create_directories(dir);
  write_text_file(dir / "calibration.json", to_json(c).dump(2) + "\n");
  write_text_file(dir / "false_alarms.csv", false_alarms_csv(c));
  if (c.at_size) {
    write_text_file(dir / "equivalence.csv", equivalence_csv(c));
    write_text_file(dir / "score_dispersion.csv", score_dispersion_csv(c));
  } else {
    write_text_file(dir / "power.csv", power_csv(c));
  }
  write_text_file(dir / "null_p_qq.csv", null_qq_csv(c));
  write_text_file(dir / "summary.md", summary_markdown(c));
  if (!charts) return;
  const bool run = detail::has_gnuplot();
  if (!run && log) *log << "[calibrate] gnuplot not found: chart scripts written, not rendered\n";
  write_calibration_charts(c, dir, run, log);
}

void write_calibration_charts(const Calibration& c, const fs::path& dir, bool run, std::ostream* log) {
  detail::fresh_chart_directory(dir / "charts");
  power_chart(c, dir / "charts", run, log);
  false_alarm_chart(c, dir / "charts", run, log);
  null_qq_chart(c, dir / "charts", run, log);
}

Calibration read_calibration_tables(const fs::path& dir) {
  std::ifstream in(dir / "calibration.json");
  if (!in) throw InputError("chart: " + (dir / "calibration.json").string() + " cannot be read");
  Calibration c;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    c.config_name = j.at("config").get<std::string>();
    c.alpha = j.at("alpha").get<double>();
    c.config_replicas = j.at("config_replicas").get<int>();
    c.at_size = j.value("at_size", false);
    for (const auto& n : j.at("false_alarms"))
      c.nulls.push_back({n.at("replicas").get<int>(), rate_from(n.at("verdicts")), rate_from(n.at("studies")), {},
                         n.value("tests_per_study", std::size_t(0))});
    for (const auto& p : j.at("power"))
      c.power.push_back({p.at("kind").get<std::string>(), p.at("size").get<double>(), p.at("replicas").get<int>(),
                         rate_from(p.at("detected")),
                         p.at("temperature_error").is_number() ? p.at("temperature_error").get<double>() : NAN});
  } catch (const nlohmann::json::exception& e) {
    throw InputError("chart: " + (dir / "calibration.json").string() + ": " + e.what());
  }
  // The QQ plot's P-values: the observed column of null_p_qq.csv, which holds the config's replica count's.
  std::ifstream qq(dir / "null_p_qq.csv");
  std::string line;
  std::getline(qq, line);
  for (auto& n : c.nulls)
    if (n.replicas == c.config_replicas)
      while (std::getline(qq, line)) {
        std::istringstream fields(line);
        std::string rank, expected, observed;
        std::getline(fields, rank, ',');
        std::getline(fields, expected, ',');
        std::getline(fields, observed, ',');
        char* end = nullptr;
        const double p = std::strtod(observed.c_str(), &end);
        if (observed.empty() || *end != '\0')
          throw InputError("chart: " + (dir / "null_p_qq.csv").string() + ": not a P-value: '" + observed + "'");
        n.p_values.push_back(p);
      }
  return c;
}

namespace {

// The key of a calibration without its run length and raw-number test sizes: a calibration of the same scene,
// noise, α and error control at another length says how large a defect that scene's verdicts see, though not at
// this config's length.
nlohmann::json without_length(nlohmann::json key) {
  key["scene"].erase("steps");
  key["scene"].erase("equilibrate");
  key.erase("chi2_steps");
  key.erase("ttest_pairs");
  return key;
}

// "a ⟨ζ²⟩ error of X (temperature error ≈ Y) is detected 90 % of the time; false alarms per study ≤ Z (…)" for
// `replicas`, or "" when the file has no 90 % threshold or null row for that count.
std::string limit_clause(const nlohmann::json& j, int replicas) {
  const auto number = [](const nlohmann::json& x) { return x.is_number() ? x.get<double>() : NAN; };
  std::vector<Threshold> ts;
  for (const auto& t : j.at("thresholds"))
    ts.push_back({t.at("kind").get<std::string>(), t.at("replicas").get<int>(), t.at("power").get<double>(),
                  number(t.at("size")), t.at("below_smallest").get<bool>(), t.at("above_largest").get<bool>()});
  const Threshold* t90 = nullptr;
  for (const auto& t : ts)
    if (t.kind == "variance" && t.replicas == replicas && t.power == 0.9) t90 = &t;
  std::vector<NullRow> nulls;
  for (const auto& n : j.at("false_alarms"))
    nulls.push_back({n.at("replicas").get<int>(), rate_from(n.at("verdicts")), rate_from(n.at("studies")), {}, 0});
  const NullRow* null = nullptr;
  for (const auto& n : nulls)
    if (n.replicas == replicas) null = &n;
  if (!t90 || !null) return "";
  std::vector<PowerRow> rows;
  for (const auto& p : j.at("power"))
    rows.push_back({p.at("kind").get<std::string>(), p.at("size").get<double>(), p.at("replicas").get<int>(),
                    rate_from(p.at("detected")), number(p.at("temperature_error"))});
  const double t_per_eps = temperature_per_epsilon(rows);
  std::ostringstream s;
  if (t90->above)
    s << "no ⟨ζ²⟩ error up to the largest calibrated is detected 90 % of the time";
  else
    s << "a ⟨ζ²⟩ error of " << (t90->below ? "≤ " : "") << pct(t90->size, "%.2g") << " (temperature error ≈ "
      << pct(t90->size * t_per_eps, "%.2g") << ") is detected 90 % of the time";
  s << "; false alarms per study ≤ " << pct(null->studies.high, "%.2g") << " (95 % upper bound; "
    << null->studies.events << " of " << null->studies.trials << " null studies had one)";
  return s.str();
}

std::string ratio(double r) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2g×", r);
  return b;
}

std::string where(const fs::path& file) {
  return file.filename().string() + " in " + file.parent_path().filename().string();
}

// "False alarms at this study's own size (…): …" from a calibration that ran null studies of this very config
// (`study calibrate --at-size`), or "" when `j` is not one with a null row for `replicas`. Such a calibration
// injects no defects, so it bounds false alarms, not the detection limit.
std::string at_size_clause(const nlohmann::json& j, int replicas, const fs::path& file) {
  if (!j.value("at_size", false)) return "";
  for (const auto& n : j.at("false_alarms")) {
    if (n.at("replicas").get<int>() != replicas) continue;
    const Rate studies = rate_from(n.at("studies")), verdicts = rate_from(n.at("verdicts"));
    std::ostringstream s;
    s << "False alarms at this study's own size (from " << where(file) << "): ≤ " << pct(studies.high, "%.2g")
      << " per study (95 % upper bound; " << studies.events << " of " << studies.trials
      << " null studies of these variants, tests and error control, with keyed Philox in place of the tested "
         "generators, had one); "
      << verdicts.events << " of " << verdicts.trials << " null variant verdicts were `differs` (≤ "
      << pct(verdicts.high, "%.2g") << ").";
    return s.str();
  }
  return "";
}

}  // namespace

std::vector<CalibrationRecord> read_calibrations(const std::vector<fs::path>& places) {
  std::vector<CalibrationRecord> out;
  for (const auto& place : places)
    for (auto& file : calibration_files(place)) {
      std::ifstream in(file);
      nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
      if (!j.is_discarded()) out.push_back({std::move(file), std::move(j)});
    }
  return out;
}

std::string detection_limit_sentence(const StudyConfig& config, const std::vector<CalibrationRecord>& records) {
  const std::string none = "Detection limit: not calibrated for this config (no `dpdrng study calibrate` result "
                           "with its scene, run length, tests and replica count).";
  if (config.scene.is_bilayer())
    return "Detection limit: not calibrated (`dpdrng study calibrate` runs the water scene only; a membrane "
           "cell costs minutes, a calibration thousands of cells).";
  const nlohmann::json key = calibration_key(config);
  std::string limit, other_length, at_size;
  for (const auto& [file, j] : records) {
    try {
      if (at_size.empty() && j.at("key") == key) at_size = at_size_clause(j, config.replicas, file);
      const std::string clause = limit_clause(j, config.replicas);
      if (clause.empty()) continue;
      if (limit.empty() && j.at("key") == key)
        limit = "Detection limit (from " + where(file) + "): with " + std::to_string(config.replicas) +
                " replicas of " + std::to_string(config.scene.steps) + " steps, " + clause + ".";
      if (other_length.empty() && without_length(j.at("key")) == without_length(key)) {
        const int steps = j.at("steps").get<int>();
        other_length = "Detection limit: not calibrated at this run length (" + std::to_string(config.scene.steps) +
                       " steps). The same scene, noise, α and error control calibrated at " + std::to_string(steps) +
                       " steps (" + where(file) + "), with " + std::to_string(config.replicas) + " replicas: " +
                       clause + ". Runs " + ratio(double(config.scene.steps) / steps) +
                       " as long narrow every error bar, so this config's own limit is expected lower (a larger "
                       "family of tests under the error control pulls the other way), but it has not been measured.";
      }
    } catch (const std::exception&) {
      continue;  // not a calibration file of this layout: another may match
    }
  }
  if (!limit.empty()) return at_size.empty() ? limit : at_size + " " + limit;
  if (!other_length.empty()) return at_size.empty() ? other_length : at_size + " " + other_length;
  if (!at_size.empty())
    return at_size + " Detection limit: not calibrated at this size (defects are injected by `dpdrng study "
                     "calibrate` without `--at-size`, at a smaller scene and its own replica count).";
  return none;
}

std::string detection_limit_sentence(const StudyConfig& config, const fs::path& place) {
  return detection_limit_sentence(config, read_calibrations({place}));
}

std::map<std::string, Rate> calibrated_equivalence(const StudyConfig& config,
                                                   const std::vector<CalibrationRecord>& records) {
  const nlohmann::json key = calibration_key(config);
  for (const auto& [file, j] : records) {
    try {
      if (!j.value("at_size", false) || j.at("key") != key) continue;
      std::map<std::string, Rate> out;
      for (const auto& e : j.at("equivalence"))
        if (e.at("replicas").get<int>() == config.replicas)
          out[e.at("observable").get<std::string>()] = rate_from(e.at("equivalent"));
      if (!out.empty()) return out;
    } catch (const std::exception&) {
      continue;  // not a calibration file of this layout: another may match
    }
  }
  return {};
}

}  // namespace dpdrng::study
