// Verdicts: a planted difference is found, identical generators are never called different and are called
// equivalent where the margins allow, and the statistics under them agree with hand computations.
#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/stats/mean_tests.hpp"
#include "dpdrng/stats/multiple.hpp"
#include "dpdrng/stats/summary.hpp"
#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/report.hpp"
#include "config_text.hpp"
#include "fake_measure.hpp"

namespace dpdrng_test::study_test_analysis {

using namespace dpdrng::study;
namespace rng = dpdrng::rng;

namespace {

const std::string kConfig = fake::small_config_toml("analysis-test", 6);

std::vector<CellResult> fake_cells(const StudyConfig& cfg, double shift) {
  fake::FakeMeasure m;
  m.temperature_shift_tea32_r1 = shift;
  std::vector<CellResult> out;
  for (const auto& c : enumerate_cells(cfg)) out.push_back(m(c, cfg, 1));
  return out;
}

const VariantReport& find(const Analysis& a, const std::string& gen, int rounds) {
  for (const auto& v : a.variants)
    if (v.key.generator == gen && v.key.rounds == rounds) return v;
  throw std::runtime_error("no variant " + gen);
}

const Comparison& comparison(const VariantReport& v, const std::string& name) {
  for (const auto& o : v.observables)
    if (o.observable == name) return o;
  throw std::runtime_error("no comparison " + name);
}

// Every decided test of the analysis, in variant order.
std::vector<const Decision*> decisions(const Analysis& a) {
  std::vector<const Decision*> d;
  for (const auto& v : a.variants) {
    for (const auto& o : v.observables)
      if (o.decision.tested()) d.push_back(&o.decision);
    for (const auto& p : v.passes)
      if (p.decision.tested()) d.push_back(&p.decision);
    for (const auto& c : v.correlations)
      if (c.decision.tested()) d.push_back(&c.decision);
    if (v.zeta_decision.tested()) d.push_back(&v.zeta_decision);
  }
  return d;
}

// Margins wide enough for the fake cells' spread (T 0.08 %, its fluctuation 0.6 %, D 2 %, curves 1 % per bin).
const std::string kWideMargins =
    "[tests.margins]\ntemperature_std = 0.2\ndiffusion = 0.3\nvpdf = 0.5\nrdf = 0.5\nmsd = 0.5\n";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace

TEST(StudyAnalysis, CurveErrorSkipsBinsBelowTheThreshold) {
  EXPECT_NEAR(curve_error({1.1, 2.0, 50}, {1.0, 2.0, 0.01}, 0.5), 0.05, 1e-12);
  EXPECT_TRUE(std::isnan(curve_error({1, 2}, {1, 2, 3}, 0)));
}

// Identical generators never differ; with the default margins the temperature (spread 0.08 %, margin 0.5 %) is
// shown equivalent while D (spread 2 %, margin 3 %) is not, so the variant is inconclusive.
TEST(StudyAnalysis, IdenticalGeneratorsDoNotDiffer) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  const auto& v = find(a, "tea32", 8);
  EXPECT_EQ(v.cells.size(), 6u);
  EXPECT_EQ(v.outcome, Outcome::inconclusive);
  EXPECT_EQ(v.verdict.rfind("inconclusive", 0), 0u) << v.verdict;
  for (const auto& o : v.observables) {
    EXPECT_TRUE(o.available) << o.observable;
    EXPECT_TRUE(o.decision.tested()) << o.observable;
    EXPECT_FALSE(o.decision.differs) << o.observable;
    EXPECT_TRUE(o.ci_low <= o.shift && o.shift <= o.ci_high) << o.observable;
  }
  EXPECT_EQ(comparison(v, "temperature_mean").outcome, Outcome::equivalent);
  EXPECT_EQ(comparison(v, "diffusion_coefficient").outcome, Outcome::inconclusive);
}

// With margins the data can meet, every observable of a generator identical to MT is equivalent, and so is the
// variant; verdicts.csv says so in its "all" row.
TEST(StudyAnalysis, AVariantIsEquivalentWhenEveryObservableIs) {
  const StudyConfig cfg = parse_config(kConfig + kWideMargins, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  const auto& v = find(a, "tea32", 8);
  for (const auto& o : v.observables) EXPECT_EQ(o.outcome, Outcome::equivalent) << o.observable;
  EXPECT_EQ(v.outcome, Outcome::equivalent);
  EXPECT_EQ(v.verdict, "equivalent within the margins");
  const std::string csv = verdicts_csv(a);
  EXPECT_EQ(csv.rfind("variant,seeding,distribution,feed,integrator,dt,replicas,observable,shift,ci_low,ci_high,"
                      "margin,p_adjusted,",
                      0),
            0u)
      << csv;
  EXPECT_NE(csv.find("\ntea32(8),distance,gauss,halves,,0.04,6,all,,,,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",equivalent\n"), std::string::npos) << csv;
}

// The equivalence tests of the whole study form one Holm family (a false "equivalent" is what a user pays for),
// and each is Schuirmann's test of the relative shift at its observable's margin.
TEST(StudyAnalysis, EquivalenceIsHolmOverTheStudysEquivalenceTests) {
  const StudyConfig cfg = parse_config(kConfig + kWideMargins, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  std::vector<const Comparison*> family;
  std::vector<double> p;
  for (const auto& v : a.variants)
    for (const auto& o : v.observables)
      if (o.equivalence.tested()) family.push_back(&o), p.push_back(o.equivalence.p);
  ASSERT_EQ(a.equivalence_tests, family.size());
  ASSERT_GT(family.size(), 10u);
  const auto adjusted = dpdrng::stats::holm_adjust(p);
  for (std::size_t k = 0; k < family.size(); ++k) {
    EXPECT_EQ(family[k]->equivalence.p_adjusted, adjusted[k]);
    EXPECT_EQ(family[k]->equivalence.equivalent, adjusted[k] < a.alpha);
  }
  const Comparison& t = comparison(find(a, "tea32", 8), "temperature_mean");
  EXPECT_EQ(t.margin, 0.005);
  EXPECT_EQ(t.equivalence.p, dpdrng::stats::equivalence_p(t.shift, t.sigma, t.dof, 0.005));
}

TEST(StudyAnalysis, APlantedTemperatureShiftIsCalledADifference) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  // 1 % against a replica spread of ~0.1 %: far beyond the noise.
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0103));
  const auto& v = find(a, "tea32", 1);
  EXPECT_EQ(v.outcome, Outcome::differs);
  EXPECT_EQ(v.verdict.rfind("differs: T +1.", 0), 0u) << v.verdict;
  EXPECT_EQ(v.min_p_what, "temperature_mean");
  const Comparison& t = comparison(v, "temperature_mean");
  EXPECT_TRUE(t.decision.differs);
  EXPECT_EQ(t.outcome, Outcome::differs);
  EXPECT_GT(t.error_rate / t.sigma, 5);
  EXPECT_GT(t.ci_low, 0.005);  // the whole CI beyond the margin
  EXPECT_GE(t.decision.p_adjusted, t.decision.p);
  EXPECT_NE(find(a, "tea32", 8).outcome, Outcome::differs);
}

// The error model is the replicas' spread: Student's two-sample t on the replicas' values, n + m − 2 degrees of
// freedom when the study has one reference, whatever block errors the runs report (here runs that claim a 100
// times smaller error change nothing).
TEST(StudyAnalysis, TheErrorModelIsTheReplicasSpread) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  const Analysis plain = analyse(cfg, cells);
  for (auto& c : cells) {
    c.scalars["temperature_sem"] = 1e-5;
    c.scalars["temperature_sem_dof"] = 1000;
  }
  const Analysis a = analyse(cfg, cells);
  const auto& v = find(a, "tea32", 8);
  const Comparison& t = comparison(v, "temperature_mean");
  std::vector<double> x, y;
  for (const auto* c : v.cells) x.push_back(c->scalar("temperature_mean", NAN));
  for (const auto* c : a.reference_for(v.key)->cells) y.push_back(c->scalar("temperature_mean", NAN));
  const auto ref = dpdrng::stats::pooled_t(x, y);
  EXPECT_EQ(t.dof, 10.0);
  EXPECT_NEAR(t.sigma, ref.se / std::abs(dpdrng::stats::mean(y)), 1e-15);
  EXPECT_EQ(t.decision.p, ref.p_value);
  EXPECT_EQ(t.sigma, comparison(find(plain, "tea32", 8), "temperature_mean").sigma);
  // The runs' block errors still give their own score, for the error-model check.
  EXPECT_GT(std::abs(t.score_runs), 10 * std::abs(t.score));
}

// With the reference under three noises (two feeds and the uniform distribution) and more reference replicas
// than variant ones, a variant's comparison pools one replica's variance from its own replicas, its reference's
// and the two other references' (R's t.test(var.equal = TRUE) generalised: the pooled variance is
// Σ (n_g − 1) s_g² / Σ (n_g − 1), Student t on Σ (n_g − 1) degrees of freedom, the standard error
// s √(1/n + 1/m)); a variant whose replicas vary far more than the references gets its own spread alone.
TEST(StudyAnalysis, TheErrorModelPoolsTheReferencesUnderEveryNoise) {
  const std::string text = config_text::StudyText{.name = "pool",
                                                  .replicas = 4,
                                                  .study_extra = "reference_replicas = 7\n",
                                                  .distributions = R"(["gauss", "uniform"])",
                                                  .sweep_extra = "feeds = [\"halves\", \"blocks\"]\n",
                                                  .generators = {{.name = "tea32", .rounds = "[8]"}},
                                                  .scene = "particles = 16\nsteps = 20\nequilibrate = 2\n",
                                                  .tests = "ttest_pairs = 2\n"}
                               .text();
  const StudyConfig cfg = parse_config(text, "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  const Analysis a = analyse(cfg, cells);
  std::size_t compared = 0;
  for (const auto& v : a.variants) {
    if (v.key.reference) {
      EXPECT_EQ(v.cells.size(), 7u);
      continue;
    }
    ++compared;
    ASSERT_EQ(v.cells.size(), 4u);
    std::vector<double> x, y;
    for (const auto* c : v.cells) x.push_back(c->scalar("temperature_mean", NAN));
    double ss = 0, dof = 0;
    for (const auto& r : a.variants) {
      if (!r.key.reference) continue;
      std::vector<double> g;
      for (const auto* c : r.cells) g.push_back(c->scalar("temperature_mean", NAN));
      if (&r == a.reference_for(v.key)) y = g;
      ss += (double(g.size()) - 1) * std::pow(dpdrng::stats::sample_sd(g), 2), dof += double(g.size()) - 1;
    }
    ss += 3 * std::pow(dpdrng::stats::sample_sd(x), 2), dof += 3;
    const Comparison& t = comparison(v, "temperature_mean");
    EXPECT_EQ(t.dof, 21.0);  // 3 + 3 × 6
    EXPECT_EQ(dof, 21.0);
    const double se = std::sqrt(ss / dof) * std::sqrt(1.0 / 4 + 1.0 / 7);
    EXPECT_NEAR(t.sigma, se / std::abs(dpdrng::stats::mean(y)), 1e-12);
    EXPECT_NEAR(t.decision.p, 2 * gsl_cdf_tdist_Q(std::abs(t.statistic), 21), 1e-12);
  }
  EXPECT_EQ(compared, 3u);
  // One variant's replicas spread 30 times wider than the references': the pool stays out of its comparison.
  for (auto& c : cells)
    if (!c.cell.reference && c.cell.feed == rng::Feed::blocks)
      c.scalars["temperature_mean"] = 1.03 + 30 * (c.scalars["temperature_mean"] - 1.03);
  const Analysis wide = analyse(cfg, cells);
  for (const auto& v : wide.variants) {
    if (!v.key.reference && v.key.feed == rng::Feed::blocks) {
      EXPECT_EQ(comparison(v, "temperature_mean").dof, 9.0);  // 4 + 7 − 2
    }
  }
}

TEST(StudyAnalysis, PassFractionsPoolReplicasAndKeepTea64OutputsApart) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  const auto& v = find(a, "tea64", 1);
  ASSERT_EQ(v.passes.size(), 4u);  // chi2 a, chi2 b, ttest a, ttest b
  for (const auto& p : v.passes) {
    EXPECT_TRUE(p.stream == "a" || p.stream == "b");
    if (p.test == "chi2") {
      EXPECT_EQ(p.trials, 600u);
      EXPECT_EQ(p.passed, 594u);
      EXPECT_LT(p.ci_low, 0.99);
      EXPECT_GT(p.ci_high, 0.99);
      EXPECT_GT(p.decision.p, 0.5);  // exactly the expected 1 % failing
    }
  }
  const std::string table = pass_table_markdown(a, "gauss");
  EXPECT_NE(table.find("| tea64(1) distance | a |"), std::string::npos) << table;
  EXPECT_NE(table.find("| tea64(1) distance | b |"), std::string::npos) << table;
  EXPECT_NE(table.find("[99 % CI]"), std::string::npos) << table;
}

// The pass fraction's interval and bold mark follow the config's α, not a fixed 1 %: 98 of 100 per replica is
// consistent with 0.99 (p = 0.52 over 600) but not with 0.999 at α = 0.001.
TEST(StudyAnalysis, PassFractionsUseTheConfigsAlpha) {
  const StudyConfig cfg = parse_config(kConfig + "alpha = 0.001\n", "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  for (auto& c : cells) c.scalars["chi2.x.passed"] = 98;
  const Analysis a = analyse(cfg, cells);
  for (const auto& p : find(a, "tea32", 8).passes)
    if (p.test == "chi2") {
      EXPECT_TRUE(p.decision.differs);
      EXPECT_LT(p.ci_high, 0.999);
    }
  const std::string table = pass_table_markdown(a, "gauss");
  EXPECT_NE(table.find("[99.9 % CI]"), std::string::npos) << table;
  EXPECT_NE(table.find("**0.980**"), std::string::npos) << table;
}

TEST(StudyAnalysis, BrokenCellsAreCountedNotAveraged) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  for (auto& c : cells)
    if (c.cell.generator == "tea64") {
      c.status = CellStatus::unstable;
      c.unstable_step = 12;
      c.reason = "unstable at step 12: temperature runaway";
      c.scalars["temperature_mean"] = 1e9;
    }
  const Analysis a = analyse(cfg, cells);
  const auto& v = find(a, "tea64", 1);
  EXPECT_TRUE(v.cells.empty());
  EXPECT_EQ(v.broken.size(), 6u);
  EXPECT_NE(v.verdict.find("unstable"), std::string::npos);
}

// Study-wide control is Holm over every decided test of every variant; per-variant control is Holm within each
// variant. Both are checked against holm_adjust on the collected raw P-values.
TEST(StudyAnalysis, ErrorControlIsHolmOverTheChosenFamily) {
  for (const char* mode : {"study", "variant"}) {
    const StudyConfig cfg =
        parse_config(kConfig + "error_control = \"" + mode + "\"\n", "c.toml");
    const Analysis a = analyse(cfg, fake_cells(cfg, 0.004));
    EXPECT_EQ(a.error_control, std::string(mode) == "study" ? ErrorControl::study : ErrorControl::variant);
    const auto all = decisions(a);
    EXPECT_EQ(a.family_size, all.size());
    if (a.error_control == ErrorControl::study) {
      EXPECT_EQ(a.families, 1u);
      std::vector<double> p;
      for (const auto* d : all) p.push_back(d->p);
      const auto adjusted = dpdrng::stats::holm_adjust(p);
      for (std::size_t k = 0; k < all.size(); ++k) {
        EXPECT_EQ(all[k]->p_adjusted, adjusted[k]);
        EXPECT_EQ(all[k]->differs, adjusted[k] < a.alpha);
      }
      EXPECT_NE(a.error_control_sentence().find("one family per study"), std::string::npos);
    } else {
      EXPECT_EQ(a.families, a.variants.size());  // every variant here has tests
      for (const auto& v : a.variants) {
        Analysis one;
        one.variants.push_back(v);
        std::vector<double> p;
        for (const auto* d : decisions(one)) p.push_back(d->p);
        const auto adjusted = dpdrng::stats::holm_adjust(p);
        const auto mine = decisions(one);
        for (std::size_t k = 0; k < mine.size(); ++k) EXPECT_EQ(mine[k]->p_adjusted, adjusted[k]);
      }
      EXPECT_NE(a.error_control_sentence().find("within each variant"), std::string::npos);
    }
  }
}

// The study-wide family is the larger one, so it never calls "differs" what per-variant control does not, and
// some shifts are called a difference per variant but not study-wide.
TEST(StudyAnalysis, StudyWideControlIsTheStricter) {
  const StudyConfig study = parse_config(kConfig, "c.toml");
  const StudyConfig variant = parse_config(kConfig + "error_control = \"variant\"\n", "c.toml");
  bool split = false;
  for (double shift = 0.0; shift <= 0.003; shift += 0.0001) {
    const bool s = find(analyse(study, fake_cells(study, shift)), "tea32", 1).min_p < study.tests.alpha;
    const bool v = find(analyse(variant, fake_cells(variant, shift)), "tea32", 1).min_p < variant.tests.alpha;
    EXPECT_TRUE(!s || v) << "shift " << shift;
    split |= v && !s;
  }
  EXPECT_TRUE(split);
}

// Bold marks and verdicts read one set of decisions: every bold cell of the observable, pass-fraction and
// correlation tables is a "differs" decision and every such decision is bold.
TEST(StudyReport, BoldMarksAreTheDecisions) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  auto cells = fake_cells(cfg, 0.0103);
  for (auto& c : cells)
    if (c.cell.generator == "tea64") c.scalars["chi2.a.passed"] = 90;
  const Analysis a = analyse(cfg, cells);
  std::size_t observables = 0, passes = 0;
  for (const auto& v : a.variants) {
    for (const auto& o : v.observables) observables += o.decision.differs;
    for (const auto& p : v.passes) passes += p.decision.differs;
  }
  EXPECT_GT(observables, 0u);
  EXPECT_GT(passes, 0u);
  EXPECT_EQ(count(observables_markdown(a, "gauss"), "**") / 2, observables);
  EXPECT_EQ(count(pass_table_markdown(a, "gauss"), "**") / 2, passes);
  for (const auto& v : a.variants)
    if (!v.key.reference) {
      EXPECT_EQ(v.verdict.rfind("differs", 0) == 0, v.min_p < a.alpha) << v.verdict;
    }
}

// A missing or unreadable reference replica leaves no verdict against it, and no decision that would mark a
// table; the reference itself is still judged on its own tests.
TEST(StudyAnalysis, MissingReferenceGivesNoVerdict) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  for (const char* how : {"missing", "failed"}) {
    auto cells = fake_cells(cfg, 0.0103);
    for (auto it = cells.begin(); it != cells.end(); ++it)
      if (it->cell.reference && it->cell.replica == 2) {
        if (std::string(how) == "missing") {
          cells.erase(it);
        } else {
          it->status = CellStatus::failed;
          it->reason = "cannot read cells/mt19937-rep02.h5";
        }
        break;
      }
    const Analysis a = analyse(cfg, cells);
    for (const auto& v : a.variants) {
      if (v.key.reference) {
        EXPECT_EQ(v.verdict.rfind("reference", 0), 0u) << v.verdict;
        continue;
      }
      EXPECT_EQ(v.verdict, "no reference data (mt19937: 1 of 6 replicas missing, unreadable or failed)") << how;
      EXPECT_TRUE(std::isnan(v.min_p));
      EXPECT_TRUE(v.observables.empty());
      for (const auto& p : v.passes) EXPECT_FALSE(p.decision.tested() && p.decision.differs);
    }
    EXPECT_EQ(count(observables_markdown(a, "gauss"), "**"), 0u);
    EXPECT_EQ(count(pass_table_markdown(a, "gauss"), "**"), 0u);
    EXPECT_EQ(count(summary_markdown(a), "differs"), 0u);
  }
}

// A shift of 30 % against a spread of 0.08 % has a P-value far below 1e-12, which no error model of the study
// supports: every table prints "< 1e-12", none a smaller number or 0.
TEST(StudyReport, PValuesArePrintedNoSmallerThanTheFloor) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.3));
  ASSERT_LT(comparison(find(a, "tea32", 1), "temperature_mean").decision.p_adjusted, 1e-12);
  const std::regex smaller("e-(1[3-9]|[2-9][0-9]|[1-9][0-9][0-9])|p 0\\)| 0 \\|");
  for (const std::string& table : {observables_markdown(a, "gauss"), summary_markdown(a), zeta_markdown(a)}) {
    EXPECT_FALSE(std::regex_search(table, smaller)) << table;
  }
  EXPECT_NE(observables_markdown(a, "gauss").find("(p < 1e-12)"), std::string::npos);
  EXPECT_NE(summary_markdown(a).find("| < 1e-12 |"), std::string::npos);
  // The CSV tables the charts and the README read floor them too.
  for (const std::string& csv : {verdicts_csv(a), observables_csv(a), summary_csv(a), zeta_csv(a), pass_table_csv(a)})
    EXPECT_FALSE(std::regex_search(csv, std::regex("e-(1[3-9]|[2-9][0-9]|[1-9][0-9][0-9])"))) << csv;
  EXPECT_NE(verdicts_csv(a).find(",<1e-12,"), std::string::npos);
}

TEST(StudyReport, NistLayoutFollowsTheReference) {
  VariantReport v;
  v.key = VariantKey{"tea32", 1, rng::Distribution::gauss, rng::Feed::halves, rng::Seeding::distance, 0.04,
                     false, ""};
  v.nist_cell = "tea32-r01";
  NistRow r;
  r.test = "Frequency";
  r.variant = "-";
  r.histogram = {10, 9, 11, 10, 10, 10, 10, 10, 10, 10};
  r.p_uniformity = 0.999;
  r.passed = 99;
  r.applicable = 100;
  v.nist.push_back(r);
  r.test = "Runs";
  r.passed = 90;
  r.proportion_ok = false;
  v.nist.push_back(r);
  const std::string text = nist_final_analysis_report(v, 0.01);
  EXPECT_NE(text.find(" C1  C2  C3  C4  C5  C6  C7  C8  C9 C10  P-VALUE  PROPORTION  STATISTICAL TEST"),
            std::string::npos);
  const auto line_with = [&](const std::string& what) {
    const auto at = text.find(what);
    if (at == std::string::npos) return std::string();
    const auto start = text.rfind('\n', at) + 1;
    return text.substr(start, text.find('\n', at) - start);
  };
  EXPECT_NE(line_with("Frequency").find(" 99/100"), std::string::npos) << text;
  EXPECT_EQ(line_with("Frequency").find('*'), std::string::npos) << text;
  EXPECT_NE(line_with("Runs").find(" 90/100"), std::string::npos) << text;
  EXPECT_NE(line_with("Runs").find('*'), std::string::npos) << text;
  EXPECT_NE(text.find("1 of 2 P-value series fail the proportion bound"), std::string::npos) << text;
}

// The own-spread detection limit is stats::detectable_difference of each temperature comparison at α/m, and a
// temperature error of three times that limit, planted in one variant, is declared.
TEST(StudyAnalysis, TemperatureLimitFromTheStudysOwnSpread) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  const TemperatureLimit t = temperature_limit(a);
  std::vector<double> by_hand;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.tests == 0) continue;
    const Comparison& c = comparison(v, "temperature_mean");
    by_hand.push_back(dpdrng::stats::detectable_difference(c.sigma, c.dof, a.alpha / double(a.family_size), 0.9));
  }
  ASSERT_FALSE(by_hand.empty());
  EXPECT_EQ(t.variants, by_hand.size());
  EXPECT_EQ(t.threshold, a.alpha / double(a.family_size));
  EXPECT_EQ(t.low, *std::min_element(by_hand.begin(), by_hand.end()));
  EXPECT_EQ(t.high, *std::max_element(by_hand.begin(), by_hand.end()));
  EXPECT_EQ(t.median, dpdrng::stats::median(by_hand));
  EXPECT_GT(t.low, 0.0);
  EXPECT_NE(temperature_limit_sentence(a).find("own spread"), std::string::npos);

  const Analysis shifted = analyse(cfg, fake_cells(cfg, 3 * t.high));
  EXPECT_TRUE(comparison(find(shifted, "tea32", 1), "temperature_mean").decision.differs);
}

// The replicas a good generator needs for `equivalent`: one replica's spread from each comparison's standard error
// (σ / √(1/n + 1/n_ref), median over the variants), the study's R_ref/R, Holm's strictest threshold over the
// equivalence family; the stats functions behind it are checked against Chow, Shao & Wang (test_equivalence).
TEST(StudyAnalysis, ReplicasForEquivalenceFromTheStudysOwnSpread) {
  const StudyConfig cfg = parse_config(kConfig + kWideMargins, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  const auto rows = equivalence_replicas(a);
  const auto row = [&](const std::string& name) {
    for (const auto& r : rows)
      if (r.observable == name) return r;
    throw std::runtime_error("no row " + name);
  };
  std::vector<double> sd, dof;
  for (const auto& v : a.variants) {
    if (v.key.reference || v.tests == 0) continue;
    const Comparison& c = comparison(v, "temperature_mean");
    sd.push_back(c.sigma / std::sqrt(1.0 / double(c.n) + 1.0 / double(c.n_ref)));
    dof.push_back(c.dof);
  }
  const EquivalenceReplicas t = row("temperature_mean");
  const double threshold = a.alpha / double(a.equivalence_tests);
  EXPECT_EQ(t.comparisons, sd.size());
  EXPECT_EQ(t.sd, dpdrng::stats::median(sd));
  EXPECT_EQ(t.dof, dpdrng::stats::median(dof));
  EXPECT_EQ(t.threshold, threshold);
  EXPECT_EQ(t.replicas, 6);
  EXPECT_EQ(t.reference_replicas, 6);
  EXPECT_EQ(t.margin, 0.005);
  EXPECT_EQ(t.needed, dpdrng::stats::replicas_for_equivalence(t.sd, 1.0, t.dof, threshold, 0.005, 0.9));
  EXPECT_GE(t.needed, 2);
  EXPECT_EQ(t.power_now,
            dpdrng::stats::equivalence_power(t.sd * std::sqrt(2.0 / 6), t.dof, threshold, 0.005));
  // A margin twice as wide needs about a quarter of the replicas (the fewest being 2).
  const StudyConfig wider = parse_config(kConfig + kWideMargins + "temperature = 0.01\n", "c.toml");
  const EquivalenceReplicas w = [&] {
    for (const auto& r : equivalence_replicas(analyse(wider, fake_cells(wider, 0.0))))
      if (r.observable == "temperature_mean") return r;
    throw std::runtime_error("no row");
  }();
  EXPECT_LE(w.needed, std::max(2, (t.needed + 3) / 4 + 1));
  // Curves are not modelled, and say so.
  EXPECT_EQ(row("rdf_vs_mt").needed, -1);
  EXPECT_NE(row("rdf_vs_mt").not_modelled.find("curve"), std::string::npos);

  // The table and its CSV, with a calibrated rate beside the model where one is given.
  std::map<std::string, Rate> calibrated{{"temperature_mean", make_rate(97, 100)}};
  const std::string md = equivalence_replicas_markdown(rows, calibrated);
  EXPECT_NE(md.find("calibrated at the same R"), std::string::npos) << md;
  EXPECT_NE(md.find("97/100 = 97.0 %"), std::string::npos) << md;
  EXPECT_NE(md.find("| " + std::to_string(t.needed) + " (reference " + std::to_string(t.needed) + ") |"),
            std::string::npos)
      << md;
  EXPECT_EQ(equivalence_replicas_markdown(rows, {}).find("calibrated at the same R"), std::string::npos);
  const std::string csv = equivalence_replicas_csv(rows, calibrated);
  EXPECT_EQ(csv.rfind("observable,margin,comparisons,replica_sd,dof,replicas,reference_replicas,threshold,"
                      "predicted_equivalent,replicas_for_90,calibrated_equivalent,",
                      0),
            0u);
  EXPECT_NE(csv.find("\ntemperature_mean,0.005,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("," + std::to_string(t.needed) + ",0.97,100,"), std::string::npos) << csv;
}

}  // namespace dpdrng_test::study_test_analysis

namespace dpdrng_test::study_test_analysis {

// The effective noise power pools the replicas' w_R²-weighted ⟨ζ²⟩ and ρ_k, and predicts T/T_ref as the ratio of
// the variant's power to the reference's (stats::effective_noise_power): with ⟨w²ζ²⟩/⟨w²⟩ = 0.96 and ρ₁ = 0.01
// against the reference's 1.0 and no ρ, the prediction is 0.96·1.02 − 1 = −2.08 %; the lags every replica stores
// count, a lag one replica lacks does not.
TEST(StudyAnalysis, EffectivePowerPredictsTheTemperatureShift) {
  const StudyConfig cfg = parse_config(kConfig, "t.toml");
  auto cells = fake_cells(cfg, 0.0);
  for (auto& c : cells) {
    const bool ref = c.cell.reference;
    c.scalars["zeta_weighted_second_moment_mean"] = ref ? 1.0 : 0.96;
    c.scalars["zeta_weighted_second_moment_sem"] = 0.002;
    if (!ref) {
      c.scalars["zeta_autocorrelation_1"] = 0.01;
      c.scalars["zeta_autocorrelation_1_se"] = 0.001;
      if (c.cell.replica == 0) c.scalars["zeta_autocorrelation_2"] = 0.3, c.scalars["zeta_autocorrelation_2_se"] = 0.001;
    }
  }
  const Analysis a = analyse(cfg, cells);
  const VariantReport& v = find(a, "tea32", 1);
  EXPECT_EQ(v.power_lags, 1u);
  EXPECT_NEAR(v.noise_power.value, 0.96 * 1.02, 1e-12);
  EXPECT_NEAR(v.power_predicted_shift.value, 0.96 * 1.02 - 1, 1e-12);
  // Each side's mean over n replicas has standard error 0.002/√n (the ρ term adds 0.96²·4·0.001²/n).
  const double n = double(v.cells.size()), nr = double(a.reference_for(v.key)->cells.size());
  const double var_v = (1.02 * 1.02 * 0.002 * 0.002 + 0.96 * 0.96 * 4 * 1e-6) / n, var_r = 0.002 * 0.002 / nr;
  EXPECT_NEAR(v.power_predicted_shift.se, 0.96 * 1.02 * std::sqrt(var_v / std::pow(0.96 * 1.02, 2) + var_r), 1e-12);
  EXPECT_NE(zeta_csv(a).find("power_predicted_T_shift"), std::string::npos);
}

}  // namespace dpdrng_test::study_test_analysis
