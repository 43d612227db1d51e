// Verdicts: a planted difference is found, identical generators are called indistinguishable, and the
// statistics under them agree with hand computations.
#include <gtest/gtest.h>

#include <cmath>

#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/report.hpp"
#include "fake_measure.hpp"

using namespace dpdrng::study;

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

}  // namespace

TEST(StudyAnalysis, WelchMatchesAHandComputation) {
  // x = {1,2,3,4}, y = {2,4,6,8}: t = -1.7321, Welch dof = 4.4118, two-sided p = 0.1516 (R: t.test(x, y);
  // the P-value also checked by integrating the t density numerically).
  EXPECT_NEAR(welch_p({1, 2, 3, 4}, {2, 4, 6, 8}), 0.15158, 5e-5);
  EXPECT_TRUE(std::isnan(welch_p({1}, {2, 3})));
  EXPECT_DOUBLE_EQ(welch_p({1, 1}, {1, 1}), 1.0);
}

TEST(StudyAnalysis, CurveErrorSkipsBinsBelowTheThreshold) {
  EXPECT_NEAR(curve_error({1.1, 2.0, 50}, {1.0, 2.0, 0.01}, 0.5), 0.05, 1e-12);
  EXPECT_TRUE(std::isnan(curve_error({1, 2}, {1, 2, 3}, 0)));
}

TEST(StudyAnalysis, IdenticalGeneratorsAreIndistinguishable) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0));
  const auto& v = find(a, "tea32", 8);
  EXPECT_EQ(v.cells.size(), 6u);
  EXPECT_EQ(v.verdict, "indistinguishable from MT at this sample size");
  for (const auto& o : v.observables) {
    EXPECT_TRUE(o.available) << o.observable;
    EXPECT_GT(o.noise_floor, 0) << o.observable;
  }
}

TEST(StudyAnalysis, APlantedTemperatureShiftIsCalledADifference) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  // 1 % against a replica spread of ~0.1 %: far beyond the noise floor.
  const Analysis a = analyse(cfg, fake_cells(cfg, 0.0103));
  const auto& v = find(a, "tea32", 1);
  EXPECT_EQ(v.verdict.rfind("differs (p = ", 0), 0u) << v.verdict;
  EXPECT_EQ(v.min_p_what, "temperature_mean");
  EXPECT_GT(v.worst_error_over_floor, 5);
  EXPECT_EQ(find(a, "tea32", 8).verdict, "indistinguishable from MT at this sample size");
}

// Four replicas can agree by chance far more closely than their runs' own errors allow; the floor then falls
// back on those errors. Here MT's temperatures are identical (spread 0) and every run claims a block SEM of
// 0.002: the floor must be 0.002·√(1/6 + 1/6) / 1.03, not 0 (which would make every ratio infinite).
TEST(StudyAnalysis, NoiseFloorFallsBackOnTheRunsOwnErrors) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  for (auto& c : cells) {
    c.scalars["temperature_sem"] = 0.002;
    if (c.cell.reference) c.scalars["temperature_mean"] = 1.03;
  }
  const Analysis a = analyse(cfg, cells);
  for (const auto& o : find(a, "tea32", 8).observables)
    if (o.observable == "temperature_mean") {
      EXPECT_NEAR(o.noise_floor, 0.002 * std::sqrt(2.0 / 6) / 1.03, 1e-12);
      return;
    }
  ADD_FAILURE() << "no temperature comparison";
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
      EXPECT_GT(p.binomial_p, 0.5);  // exactly the expected 1 % failing
    }
  }
  const std::string table = pass_table_markdown(a, "gauss");
  EXPECT_NE(table.find("| tea64(1) distance | a |"), std::string::npos) << table;
  EXPECT_NE(table.find("| tea64(1) distance | b |"), std::string::npos) << table;
}

TEST(StudyAnalysis, ClopperPearsonIntervalIsFiniteWhereGslPinvIsNot) {
  // 792 of 800 passed: the case where gsl_cdf_beta_Pinv returned NaN for the lower bound. The exact 99 %
  // interval lies below the normal approximation's 0.981 and must still contain 0.99.
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  for (auto& c : cells) c.scalars["ttest.x.passed"] = c.cell.replica < 2 ? 396 : 0, c.scalars["ttest.x.trials"] =
                                                          c.cell.replica < 2 ? 400 : 0;
  const Analysis a = analyse(cfg, cells);
  for (const auto& p : find(a, "tea32", 8).passes)
    if (p.test == "ttest") {
      EXPECT_EQ(p.passed, 792u);
      EXPECT_TRUE(std::isfinite(p.ci_low));
      EXPECT_NEAR(p.ci_high, 0.99678, 2e-4);
      EXPECT_GT(p.ci_low, 0.97);
      EXPECT_LT(p.ci_low, 0.98);
    }
}

TEST(StudyAnalysis, BrokenCellsAreCountedNotAveraged) {
  const StudyConfig cfg = parse_config(kConfig, "c.toml");
  auto cells = fake_cells(cfg, 0.0);
  for (auto& c : cells)
    if (c.cell.generator == "tea64") {
      c.status = "unstable";
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

TEST(StudyReport, NistLayoutFollowsTheReference) {
  VariantReport v;
  v.key = VariantKey{"tea32", 1, "gauss", "distance", 0.04, false};
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
