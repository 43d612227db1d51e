// study calibrate through a fake measure: the pool it computes, the counts behind the false-alarm and power
// rows, that it resumes, and that a report finds the detection limit of a matching calibration only.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/stats/binomial.hpp"
#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/calibrate.hpp"
#include "dpdrng/study/report.hpp"
#include "fake_measure.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::study_test_calibrate {

using namespace dpdrng;
using namespace dpdrng::study;
namespace fs = std::filesystem;

namespace {

// The fake engine with the physics of a variance defect: the thermostat's kT scales with σ², so T with 1 + ε.
struct DefectAwareFake {
  fake::FakeMeasure m;
  int calls = 0;
  CellResult operator()(const Cell& c, const StudyConfig& cfg, int t) {
    ++calls;
    CellResult r = m(c, cfg, t);
    if (rng::is_defect(c.generator)) r.scalars["temperature_mean"] *= 1 + rng::parse_defect(c.generator).variance;
    return r;
  }
};

CalibrationPlan small_plan() {
  CalibrationPlan p;
  p.null_studies = 20;
  p.power_studies = 3;
  p.replicas = {4};
  p.variance = {0.0001, 0.003, 0.05};
  return p;
}

}  // namespace

TEST(Calibrate, PoolCountsAndRates) {
  TempDir tmp;
  const StudyConfig cfg = parse_config(fake::small_config_toml("calib-test", 3), "c.toml");
  const CalibrationPlan plan = small_plan();
  DefectAwareFake fake;
  MeasureFn fn = [&](const Cell& c, const StudyConfig& s, int t) { return fake(c, s, t); };
  Store store(tmp.path / "pool");
  const Calibration c = calibrate(cfg, plan, store, fn, 1, nullptr);

  // Pool: 20 null studies of 3 replicas = 60 replicas of reference + 3 good generators; defects on 3 × 4 = 12.
  EXPECT_EQ(c.pool_replicas, 60);
  EXPECT_EQ(c.defect_replicas, 12);
  EXPECT_EQ(fake.calls, 60 * 4 + 12 * 3);
  EXPECT_EQ(c.computed, std::size_t(fake.calls));

  // Null rows for 3 (the config's) and 4 replicas: 60 / R disjoint studies of 3 verdicts each.
  ASSERT_EQ(c.nulls.size(), 2u);
  EXPECT_EQ(c.nulls[0].replicas, 3);
  EXPECT_EQ(c.nulls[0].studies.trials, 20u);
  EXPECT_EQ(c.nulls[0].verdicts.trials, 60u);
  EXPECT_EQ(c.nulls[1].studies.trials, 15u);
  EXPECT_LE(c.nulls[0].verdicts.events, c.nulls[0].verdicts.trials);
  const auto [lo, hi] = stats::clopper_pearson(c.nulls[0].verdicts.events, 60, 0.95);
  EXPECT_EQ(c.nulls[0].verdicts.low, lo);
  EXPECT_EQ(c.nulls[0].verdicts.high, hi);

  // Power rows: 3 sizes × {3, 4} replicas, 12 / R studies each. A 5 % temperature shift is 60 times the fake's
  // replica spread (0.003 / √12 ≈ 0.0009 on 1.03): every study sees it, even through Holm's threshold over the
  // study's ~45 tests with the t-test's 4 degrees of freedom; a 0.01 % shift is a tenth of the spread.
  ASSERT_EQ(c.power.size(), 6u);
  for (const auto& p : c.power) {
    EXPECT_EQ(p.detected.trials, std::size_t(12 / p.replicas)) << p.size;
    if (p.size == 0.05) {
      EXPECT_EQ(p.detected.events, p.detected.trials);
    }
    if (p.size == 0.0001) {
      EXPECT_LT(p.detected.events, p.detected.trials);
    }
    // The measured T error is ε plus the difference of two replica noises (spread ≈ 0.0009 / 1.03 each).
    EXPECT_NEAR(p.temperature_error, p.size, 0.0015) << p.size;
  }
  // The 90 % size of every replica count lies within the sizes tested, or at the smallest.
  for (const auto& t : c.thresholds) {
    EXPECT_FALSE(t.above) << t.replicas;
    EXPECT_LE(t.size, 0.05);
  }
}

// Two shards into one pool compute disjoint halves; the first to finish analyses nothing, the second finds every
// cell and gives the calibration of an unsharded run.
TEST(Calibrate, ShardsShareOnePool) {
  TempDir tmp;
  const StudyConfig cfg = parse_config(fake::small_config_toml("calib-shards", 3), "c.toml");
  CalibrationPlan plan = small_plan();
  plan.null_studies = 4;
  DefectAwareFake one, two, whole;
  const auto with = [](DefectAwareFake& f) {
    return MeasureFn([&f](const Cell& c, const StudyConfig& s, int t) { return f(c, s, t); });
  };
  Store store(tmp.path / "sharded");
  plan.shard = {1, 2};
  const Calibration a = calibrate(cfg, plan, store, with(one), 1, nullptr);
  EXPECT_GT(a.missing, 0u);
  EXPECT_TRUE(a.nulls.empty());
  EXPECT_EQ(std::size_t(one.calls) + a.missing, a.cells);
  plan.shard = {2, 2};
  const Calibration b = calibrate(cfg, plan, store, with(two), 1, nullptr);
  EXPECT_EQ(b.missing, 0u);
  EXPECT_EQ(std::size_t(one.calls + two.calls), b.cells);
  EXPECT_LE(std::abs(one.calls - two.calls), 1);

  Store unsharded(tmp.path / "whole");
  plan.shard = {1, 1};
  const Calibration c = calibrate(cfg, plan, unsharded, with(whole), 1, nullptr);
  nlohmann::json jb = to_json(b), jc = to_json(c);
  for (const char* k : {"computed", "resumed", "wall_seconds", "wall_seconds_total", "cell_seconds"})
    jb.erase(k), jc.erase(k);
  EXPECT_EQ(jb, jc);
}

TEST(Calibrate, ResumesWithoutRecomputing) {
  TempDir tmp;
  const StudyConfig cfg = parse_config(fake::small_config_toml("calib-resume", 3), "c.toml");
  CalibrationPlan plan = small_plan();
  plan.null_studies = 4;
  DefectAwareFake first, second;
  Store store(tmp.path / "pool");
  const Calibration a = calibrate(cfg, plan, store, [&](const Cell& c, const StudyConfig& s, int t) { return first(c, s, t); }, 1, nullptr);
  const Calibration b = calibrate(cfg, plan, store, [&](const Cell& c, const StudyConfig& s, int t) { return second(c, s, t); }, 1, nullptr);
  EXPECT_GT(first.calls, 0);
  EXPECT_EQ(second.calls, 0);
  EXPECT_EQ(b.resumed, b.cells);
  nlohmann::json ja = to_json(a), jb = to_json(b);
  for (const char* k : {"computed", "resumed", "wall_seconds", "wall_seconds_total"}) ja.erase(k), jb.erase(k);
  EXPECT_EQ(ja, jb);
  // Another plan is another pool: the store refuses it rather than mixing cells.
  plan.variance = {0.5};
  EXPECT_THROW(calibrate(cfg, plan, store, [&](const Cell& c, const StudyConfig& s, int t) { return second(c, s, t); }, 1, nullptr),
               InputError);
}

TEST(Calibrate, ReportReadsAMatchingCalibrationOnly) {
  TempDir tmp;
  const StudyConfig cfg = parse_config(fake::small_config_toml("calib-report", 3), "c.toml");
  CalibrationPlan plan = small_plan();
  plan.null_studies = 4;
  DefectAwareFake fake;
  Store store(tmp.path / "pool");
  const Calibration c = calibrate(cfg, plan, store, [&](const Cell& x, const StudyConfig& s, int t) { return fake(x, s, t); }, 1, nullptr);
  write_calibration(c, tmp.path, false, nullptr);
  for (const char* f : {"summary.md", "calibration.json", "power.csv", "false_alarms.csv", "null_p_qq.csv"})
    EXPECT_TRUE(fs::exists(tmp.path / f)) << f;
  // The QQ table: every raw null P-value of the config's replica count, sorted, against (i − ½)/n, inside the
  // Dvoretzky–Kiefer–Wolfowitz band ε = √(ln 40 / 2n) around the uniform quantile.
  {
    const auto& row = c.nulls[0];
    ASSERT_EQ(row.replicas, 3);
    ASSERT_FALSE(row.p_values.empty());
    std::ifstream in(tmp.path / "null_p_qq.csv");
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "rank,expected,observed,band_low,band_high");
    const double n = double(row.p_values.size()), eps = std::sqrt(std::log(40.0) / (2 * n));
    std::size_t rows = 0;
    double last = 0;
    while (std::getline(in, line)) {
      double rank, e, o, lo, hi;
      ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf", &rank, &e, &o, &lo, &hi), 5) << line;
      EXPECT_NEAR(e, (rank - 0.5) / n, 1e-6);
      EXPECT_NEAR(hi - e, std::min(eps, 1 - e), 1e-6);
      EXPECT_GE(o, last);
      EXPECT_TRUE(o >= 0 && o <= 1) << o;
      last = o;
      ++rows;
    }
    EXPECT_EQ(rows, row.p_values.size());
  }

  const std::string s = detection_limit_sentence(cfg, tmp.path);
  EXPECT_NE(s.find("with 3 replicas of 20 steps"), std::string::npos) << s;
  EXPECT_NE(s.find("detected 90 % of the time"), std::string::npos) << s;
  EXPECT_NE(s.find("false alarms per study ≤"), std::string::npos) << s;
  // Another run length: not calibrated, and the same scene's limit at the calibrated length beside it, named as
  // such. A replica count without a row, or no calibration at all: not calibrated.
  StudyConfig longer = cfg;
  longer.scene.steps = 40;
  const std::string l = detection_limit_sentence(longer, tmp.path);
  EXPECT_NE(l.find("not calibrated at this run length (40 steps)"), std::string::npos) << l;
  EXPECT_NE(l.find("calibrated at 20 steps"), std::string::npos) << l;
  EXPECT_NE(l.find("detected 90 % of the time"), std::string::npos) << l;
  EXPECT_NE(l.find("Runs 2× as long"), std::string::npos) << l;
  StudyConfig more = cfg;
  more.replicas = 5;
  EXPECT_NE(detection_limit_sentence(more, tmp.path).find("not calibrated for this config"), std::string::npos);
  StudyConfig other_scene = longer;
  other_scene.scene.gamma = 4.5;
  EXPECT_NE(detection_limit_sentence(other_scene, tmp.path).find("not calibrated for this config"), std::string::npos);
  EXPECT_NE(detection_limit_sentence(cfg, tmp.path / "nowhere").find("not calibrated"), std::string::npos);

  // The study report carries the sentence in its header.
  std::vector<CellResult> cells;
  for (const auto& cell : enumerate_cells(cfg)) cells.push_back(fake.m(cell, cfg, 1));
  ReportOptions o;
  o.charts = false;
  o.calibration = tmp.path / "calibration.json";
  const fs::path md = write_report(cfg, cells, tmp.path / "study", o);
  std::ifstream in(md);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(s), std::string::npos);
}

TEST(Calibrate, RefusesBadPlans) {
  const StudyConfig cfg = parse_config(fake::small_config_toml("calib-bad", 3), "c.toml");
  CalibrationPlan plan = small_plan();
  plan.replicas = {1};
  EXPECT_THROW(calibration_pool(cfg, plan), InputError);
  plan = small_plan();
  plan.variance = {-1.0};
  EXPECT_THROW(calibration_pool(cfg, plan), InputError);
  plan = small_plan();
  plan.lag1 = {1.0};
  EXPECT_THROW(calibration_pool(cfg, plan), InputError);
  // A lag-1 defect runs in pair-step seeding whatever the config's seeding.
  plan = small_plan();
  plan.lag1 = {0.1};
  const StudyConfig pool = calibration_pool(cfg, plan);
  EXPECT_EQ(pool.generators.back().name, "defect:lag1=0.1");
  EXPECT_EQ(pool.generators.back().seedings, std::vector<rng::Seeding>{rng::Seeding::pair_step});
}

TEST(Calibrate, PoolRunsTheFirstFeedOnly) {
  std::string toml = fake::small_config_toml("calib-feeds", 3);
  toml.replace(toml.find("[[sweep.generator]]"), 0, "feeds = [\"blocks\", \"halves\"]\n");
  const StudyConfig cfg = parse_config(toml, "c.toml");
  ASSERT_EQ(cfg.feeds.size(), 2u);
  const StudyConfig pool = calibration_pool(cfg, small_plan());
  EXPECT_EQ(pool.feeds, std::vector<rng::Feed>{rng::Feed::blocks});
  for (const auto& c : enumerate_cells(pool)) EXPECT_EQ(c.feed, rng::Feed::blocks);
}

// At the study's own size: every variant slot of the config (generator × rounds) becomes its own keyed good
// generator, so a null study has the config's variants and Holm family; null study s takes variant replicas
// [sR, sR + R), the same reference replicas and R_ref − R reference replicas of its own.
TEST(Calibrate, AtSizeNullStudiesHaveTheStudysVariants) {
  std::string toml = fake::small_config_toml("calib-at-size", 3);
  toml.replace(toml.find("[[sweep.generator]]"), 0, "feeds = [\"halves\", \"blocks\"]\n");
  StudyConfig cfg = parse_config(toml, "c.toml");
  cfg.reference_replicas = 5;
  std::size_t slots = 0;
  for (const auto& g : cfg.generators) slots += std::max<std::size_t>(g.rounds.size(), 1);
  CalibrationPlan plan;
  plan.at_size = true;
  plan.null_studies = 6;
  plan.variance.clear();
  const StudyConfig pool = at_size_pool(cfg, plan);
  ASSERT_EQ(pool.generators.size(), slots);
  for (std::size_t k = 0; k < slots; ++k) EXPECT_EQ(pool.generators[k].name, "defect:key=" + std::to_string(k));
  EXPECT_EQ(pool.replicas, 18);
  EXPECT_EQ(pool.reference_replicas, 18 + 6 * 2);
  EXPECT_TRUE(pool.tests.nist_generators.empty());
  EXPECT_EQ(pool.feeds, cfg.feeds);  // every noise of the study, unlike the CI-size pool

  // Slot 1 runs 5 % hot (60 times the fake's replica spread): every null study must see it in its own block.
  struct SlotFake {
    fake::FakeMeasure m;
    int calls = 0;
    CellResult operator()(const Cell& c, const StudyConfig& s, int t) {
      ++calls;
      CellResult r = m(c, s, t);
      if (c.generator == "defect:key=1") r.scalars["temperature_mean"] *= 1.05;
      return r;
    }
  } fake;
  TempDir tmp;
  Store store(tmp.path / "pool");
  const Calibration c = calibrate(cfg, plan, store, [&](const Cell& x, const StudyConfig& s, int t) { return fake(x, s, t); }, 1, nullptr);
  const std::size_t noises = 2;  // gauss under halves and blocks
  EXPECT_EQ(std::size_t(fake.calls), slots * noises * 18 + noises * 30);
  EXPECT_TRUE(c.at_size);
  EXPECT_TRUE(c.power.empty());
  ASSERT_EQ(c.nulls.size(), 1u);
  EXPECT_EQ(c.nulls[0].replicas, 3);
  EXPECT_EQ(c.nulls[0].studies.trials, 6u);
  EXPECT_EQ(c.nulls[0].studies.events, 6u);
  EXPECT_EQ(c.nulls[0].verdicts.trials, 6 * slots * noises);
  EXPECT_GE(c.nulls[0].verdicts.events, 6 * noises);  // slot 1 under each noise, in each study
  // A null study's Holm family is the config's own study's (same variants and tests, other generators), except
  // for per-stream tests: the fake gives tea64 two χ² and two lag-1 t streams and a keyed Philox one, so the
  // study holds 2 pass-fraction tests more per noise.
  fake::FakeMeasure real;
  std::vector<CellResult> study_cells;
  for (const auto& cell : enumerate_cells(cfg)) study_cells.push_back(real(cell, cfg, 1));
  EXPECT_EQ(c.nulls[0].tests_per_study + 2 * noises, analyse(cfg, study_cells).family_size);
  bool temperature = false;
  for (const auto& e : c.equivalence) {
    EXPECT_EQ(e.replicas, 3);
    EXPECT_EQ(e.reference_replicas, 5);
    EXPECT_EQ(e.equivalent.trials, 6 * slots * noises) << e.observable;
    temperature = temperature || e.observable == "temperature_mean";
  }
  EXPECT_TRUE(temperature);
  EXPECT_EQ(c.null_studies_planned, 6);

  // The error model's check: every variant's normal score per scalar observable, kept in each record and pooled
  // over the null studies. Slot 1's planted 5 % heating makes its temperature scores far from N(0, 1); pressure
  // stays near 1.
  EXPECT_EQ(c.scored_studies, 6u);
  const auto dispersion = [&](const Calibration& cal, const std::string& name) {
    for (const auto& d : cal.dispersion)
      if (d.observable == name) return d.scores;
    throw std::runtime_error("no dispersion row " + name);
  };
  EXPECT_EQ(dispersion(c, "temperature_mean").k, 6 * slots * noises);
  EXPECT_GT(dispersion(c, "temperature_mean").low, 10.0);
  {
    std::vector<double> z;
    for (int s = 0; s < 6; ++s) {
      char name[32];
      std::snprintf(name, sizeof name, "study-%03d.json", s);
      const auto j = nlohmann::json::parse(read_whole_file(store.dir() / "null-studies" / name));
      for (double x : j.at("scores").at("pressure_mean").get<std::vector<double>>()) z.push_back(x);
    }
    const auto by_hand = dpdrng::stats::score_dispersion(z);
    EXPECT_EQ(dispersion(c, "pressure_mean").k, by_hand.k);
    EXPECT_EQ(dispersion(c, "pressure_mean").ratio, by_hand.ratio);
  }

  // The study's report, with this calibration in a directory beside it, quotes its false-alarm rate and says that
  // the detection limit was not calibrated at this size.
  write_calibration(c, tmp.path / "at-size", false, nullptr);
  const std::string sentence = detection_limit_sentence(cfg, tmp.path / "at-size");
  EXPECT_EQ(sentence.rfind("False alarms at this study's own size (from calibration.json in at-size): ≤ ", 0), 0u)
      << sentence;
  EXPECT_NE(sentence.find("6 of 6 null studies"), std::string::npos) << sentence;
  EXPECT_NE(sentence.find("Detection limit: not calibrated at this size"), std::string::npos) << sentence;
  StudyConfig more = cfg;
  more.replicas = 4;  // no null row for this count
  EXPECT_NE(detection_limit_sentence(more, tmp.path / "at-size").find("not calibrated for this config"),
            std::string::npos);
  {
    ReportOptions o;
    o.charts = false;
    std::ifstream in(write_report(cfg, study_cells, tmp.path / "study", o));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find(sentence), std::string::npos);
  }

  // Each null study's outcome is kept on its own: with the cells gone, a rerun computes nothing and adds up the
  // same numbers; a study whose record is deleted has its cells (and only those) computed again.
  for (int s = 0; s < 6; ++s) {
    char name[32];
    std::snprintf(name, sizeof name, "study-%03d.json", s);
    EXPECT_TRUE(std::filesystem::exists(store.dir() / "null-studies" / name)) << name;
  }
  std::filesystem::remove_all(store.dir() / "cells");
  SlotFake again;
  const auto rerun = [&] {
    return calibrate(cfg, plan, store, [&](const Cell& x, const StudyConfig& s, int t) { return again(x, s, t); }, 1,
                     nullptr);
  };
  const Calibration resumed = rerun();
  EXPECT_EQ(again.calls, 0);
  EXPECT_EQ(resumed.missing, 0u);
  ASSERT_EQ(resumed.nulls.size(), 1u);
  EXPECT_EQ(resumed.nulls[0].p_values, c.nulls[0].p_values);
  EXPECT_EQ(resumed.nulls[0].verdicts.events, c.nulls[0].verdicts.events);
  ASSERT_EQ(resumed.equivalence.size(), c.equivalence.size());
  for (std::size_t k = 0; k < c.equivalence.size(); ++k)
    EXPECT_EQ(resumed.equivalence[k].equivalent.events, c.equivalence[k].equivalent.events);
  std::filesystem::remove(store.dir() / "null-studies" / "study-004.json");
  const Calibration redone = rerun();
  EXPECT_EQ(std::size_t(again.calls), slots * noises * 3 + noises * 5);
  EXPECT_EQ(redone.nulls[0].p_values.size(), c.nulls[0].p_values.size());
  EXPECT_EQ(redone.nulls[0].studies.events, 6u);

  // A record written before scores were kept still counts; the check says how many records it rests on.
  {
    const auto p = store.dir() / "null-studies" / "study-001.json";
    auto j = nlohmann::json::parse(read_whole_file(p));
    j.erase("scores");
    write_file_atomically(p, j.dump() + "\n");
    const Calibration older = rerun();
    EXPECT_EQ(older.nulls[0].studies.trials, 6u);
    EXPECT_EQ(older.scored_studies, 5u);
    EXPECT_EQ(dispersion(older, "temperature_mean").k, 5 * slots * noises);
    write_calibration(older, tmp.path / "older", false, nullptr);
    const std::string md = read_whole_file(tmp.path / "older" / "summary.md");
    EXPECT_NE(md.find("From the 5 of 6 recorded null studies whose records hold scores."), std::string::npos);
    EXPECT_TRUE(fs::exists(tmp.path / "older" / "score_dispersion.csv"));
  }

  // A damaged record is an error that names it, not a silently smaller calibration.
  write_file_atomically(store.dir() / "null-studies" / "study-002.json", "{\"study\": 2");
  EXPECT_THROW(rerun(), OutputError);
  std::filesystem::remove(store.dir() / "null-studies" / "study-002.json");

  // Defects are calibrated at the CI scene's size; configs whose replica blocks vary by Δt are refused.
  plan.variance = {0.01};
  EXPECT_THROW(at_size_pool(cfg, plan), InputError);
  plan.variance.clear();
  plan.replicas = {6};  // null studies have the config's replica count
  EXPECT_THROW(at_size_pool(cfg, plan), InputError);
  plan.replicas.clear();
  cfg.integrators = {"mvv:0.5", "shardlow"};
  EXPECT_THROW(at_size_pool(cfg, plan), InputError);
}

// A time limit stops a long calibration between cells: what is stored stays, nothing is analysed until a null
// study is complete, and the next run goes on from there to the same result as one uninterrupted run.
TEST(Calibrate, TimeLimitStopsBetweenCellsAndTheRerunGoesOn) {
  const StudyConfig cfg = parse_config(fake::small_config_toml("calib-limit", 2), "c.toml");
  CalibrationPlan plan;
  plan.at_size = true;
  plan.null_studies = 2;
  plan.variance.clear();
  plan.max_seconds = 1e-9;  // past before the second cell starts
  TempDir tmp;
  Store store(tmp.path / "pool");
  fake::FakeMeasure m;
  const auto measure = [&](const Cell& x, const StudyConfig& s, int t) { return m(x, s, t); };
  const Calibration first = calibrate(cfg, plan, store, measure, 1, nullptr);
  EXPECT_EQ(first.computed, 1u);
  EXPECT_EQ(first.missing, first.cells - 1);
  EXPECT_TRUE(first.nulls.empty());
  plan.max_seconds = 0;
  const Calibration rest = calibrate(cfg, plan, store, measure, 1, nullptr);
  EXPECT_EQ(rest.computed, first.cells - 1);
  EXPECT_EQ(rest.missing, 0u);
  ASSERT_EQ(rest.nulls.size(), 1u);
  EXPECT_EQ(rest.nulls[0].studies.trials, 2u);

  TempDir whole_dir;
  Store whole_store(whole_dir.path / "pool");
  fake::FakeMeasure m2;
  const Calibration whole =
      calibrate(cfg, plan, whole_store, [&](const Cell& x, const StudyConfig& s, int t) { return m2(x, s, t); }, 1,
                nullptr);
  EXPECT_EQ(whole.nulls[0].p_values, rest.nulls[0].p_values);
}

}  // namespace dpdrng_test::study_test_calibrate
