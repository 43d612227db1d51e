// The study driver on the membrane scene: its config rules, the paired comparison against MT, and a tiny real
// study through run → resume (nothing recomputed) → report.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/report.hpp"
#include "dpdrng/study/store.hpp"
#include "config_text.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::study_test_bilayer_study {

using namespace dpdrng::study;
namespace rng = dpdrng::rng;
namespace dpd = dpdrng::dpd;
namespace fs = std::filesystem;

namespace {

// Seconds, not minutes: the scene's box is fixed (5 400 beads), so the run is short instead: 100 warm-up steps
// at dt 0.005, 200 production steps.
const std::string kTinyBilayer =
    config_text::StudyText{.name = "tiny-bilayer",
                           .replicas = 1,
                           .study_extra = "seed = 7\n",
                           .generators = {{.rounds = "[1]"}},
                           .scene = "name = \"bilayer\"\nparticles = 5400\ndensity = 3.0\n"
                                    "steps = 300\nequilibrate = 100\n",
                           .tests = ""}
        .text();

using config_text::error_of;
using config_text::with;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Built piecewise: GCC 12 warns (-Wrestrict, a false positive) on "'" + path.string().
std::string quote(const fs::path& p) {
  std::string s = "'";
  s += p.string();
  s += "'";
  return s;
}

int run_cli(const std::string& args, std::string* err = nullptr) {
  const fs::path e = fs::temp_directory_path() / ("dpdrng-bilayer-err-" + std::to_string(getpid()));
  const int rc = std::system((std::string(DPDRNG_CLI_PATH) + " " + args + " >/dev/null 2>'" + e.string() + "'").c_str());
  if (err) *err = read(e);
  fs::remove(e);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// A cell with the bilayer's scalars, as measure_cell records them.
CellResult bilayer_cell(const Cell& c, double temperature, double tension) {
  CellResult r;
  r.cell = c;
  const auto put = [&](const std::string& n, double mean) {
    r.scalars[n + "_mean"] = mean;
    r.scalars[n + "_sem"] = 0.01;
  };
  put("temperature", temperature);
  put("pressure_xx", 23.1), put("pressure_yy", 23.2), put("pressure_zz", 23.3);
  put("tension", tension);
  put("thickness", 4.1), put("tail_order", 0.45);
  return r;
}

}  // namespace

TEST(BilayerStudyConfig, ShippedConfigSweepsTheMembrane) {
  const StudyConfig c = load_config(std::string(DPDRNG_SOURCE_DIR) + "/study/bilayer.toml");
  EXPECT_TRUE(c.scene.is_bilayer());
  EXPECT_EQ(c.scene.particles, 5400);
  EXPECT_EQ(c.scene.steps, 61000);
  EXPECT_EQ(c.tests.chi2_steps, 0);
  EXPECT_EQ(c.tests.ttest_pairs, 0);
  const auto cells = enumerate_cells(c);
  // 4 replicas × 2 feeds (halves, blocks) × (mt19937, tea32(1), tea32(32))
  EXPECT_EQ(cells.size(), 24u);
  std::size_t blocks = 0;
  for (const auto& cell : cells) {
    EXPECT_FALSE(cell.nist) << cell.id();
    blocks += cell.feed == rng::Feed::blocks;
  }
  EXPECT_EQ(blocks, 12u);
  EXPECT_FALSE(c.canonical()["scene"].contains("a"));
}

TEST(BilayerStudyConfig, SceneDefaultsAreTheBilayers) {
  const StudyConfig c = parse_config(
      "[study]\nname = \"b\"\n[[sweep.generator]]\nname = \"tea32\"\n[scene]\nname = \"bilayer\"\n", "b.toml");
  EXPECT_EQ(c.scene.particles, 5400);
  EXPECT_DOUBLE_EQ(c.scene.density, 3.0);
  EXPECT_DOUBLE_EQ(c.scene.gamma, 4.5);
  EXPECT_EQ(c.scene.dt, std::vector<double>{0.01});
  EXPECT_EQ(c.scene.pairs, dpd::PairMode::cells);
  EXPECT_EQ(c.tests.ttest_pairs, 0);  // the water default (100) would ask for taps the bilayer does not make
}

TEST(BilayerStudyConfig, ErrorsNameTheKey) {
  EXPECT_NE(error_of(with(kTinyBilayer, "density = 3.0", "density = 3.0\na = 25")).find("scene.a: not used by the bilayer"),
            std::string::npos);
  EXPECT_NE(error_of(with(kTinyBilayer, "particles = 5400", "particles = 5000")).find("scene.particles"),
            std::string::npos);
  EXPECT_NE(error_of(with(kTinyBilayer, "density = 3.0", "density = 2.0")).find("10 x 10 x 18"), std::string::npos);
  // A consistent pair is fine (ρ = 2 in the same box), but not fewer beads than the lipids hold.
  EXPECT_EQ(error_of(with(with(kTinyBilayer, "particles = 5400", "particles = 3600"), "density = 3.0", "density = 2.0")),
            "");
  EXPECT_NE(error_of(with(with(kTinyBilayer, "particles = 5400", "particles = 1800"), "density = 3.0", "density = 1.0"))
                .find("lipids"),
            std::string::npos);
  EXPECT_NE(error_of(with(kTinyBilayer, "density = 3.0", "density = nan")).find("scene.density: must be finite"),
            std::string::npos);
  EXPECT_NE(error_of(with(kTinyBilayer, "steps = 300", "steps = 300\ngamma = inf")).find("scene.gamma"),
            std::string::npos);
  EXPECT_NE(error_of(kTinyBilayer + "[tests]\nchi2_steps = 5\n").find("tests.chi2_steps: must be 0 for the bilayer"),
            std::string::npos);
  EXPECT_NE(error_of(kTinyBilayer + "[tests]\nttest_pairs = 2\n").find("tests.ttest_pairs"), std::string::npos);
  EXPECT_NE(error_of(kTinyBilayer + "[tests]\nnist_generators = [\"tea32\"]\n").find("tests.nist_generators"),
            std::string::npos);
  EXPECT_NE(error_of(with(kTinyBilayer, "\"bilayer\"", "\"vesicle\"")).find("known: water, bilayer"),
            std::string::npos);
}

// Existing result directories are keyed by the canonical form's hash: the bilayer's keys must not have changed
// it for water configs, or results/okada2021 could not be reported or resumed.
TEST(BilayerStudyConfig, WaterConfigHashUnchanged) {
  const fs::path stored = fs::path(DPDRNG_SOURCE_DIR) / "results" / "okada2021" / "config.hash";
  if (!fs::exists(stored)) GTEST_SKIP() << stored << " not present";
  std::string h = read(stored);
  while (!h.empty() && (h.back() == '\n' || h.back() == ' ')) h.pop_back();
  EXPECT_EQ(load_config((fs::path(DPDRNG_SOURCE_DIR) / "results" / "okada2021" / "study.toml").string()).hash, h);
}

TEST(BilayerStudyAnalysis, OneReplicaGetsTheRunsOwnInterval) {
  const StudyConfig cfg = parse_config(kTinyBilayer, "b.toml");
  const CellResult c = bilayer_cell(enumerate_cells(cfg).front(), 1.01, 0.3);
  const ReplicaMean m = replica_mean({&c}, "temperature_mean", "temperature_sem");
  EXPECT_EQ(m.n, 1u);
  EXPECT_DOUBLE_EQ(m.mean, 1.01);
  EXPECT_TRUE(m.from_run_sem);
  EXPECT_NEAR(m.ci95, 1.96 * 0.01, 1e-4);
}

// A temperature shift planted in one generator is found by the paired test and only there; the tension, whose
// replicas scatter as much as MT's own, is left alone.
TEST(BilayerStudyAnalysis, PlantedShiftIsFoundAndNothingElse) {
  const StudyConfig cfg = parse_config(
      with(with(kTinyBilayer, "replicas = 1", "replicas = 6"), "rounds = [1]", "rounds = [1, 32]"), "b.toml");
  std::vector<CellResult> cells;
  for (const auto& c : enumerate_cells(cfg)) {
    // Replica state shared by every generator, plus a small per-cell scatter.
    const double state = double(dpdrng::rng::splitmix64_mix(c.seed) >> 11) * 0x1p-53 - 0.5;
    const std::uint64_t who = (std::uint64_t(c.rounds) << 8) | (c.reference ? 1u : 2u);
    const double own = double(dpdrng::rng::splitmix64_mix(c.seed ^ who) >> 11) * 0x1p-53 - 0.5;
    const double shift = !c.reference && c.rounds == 1 ? -0.03 : 0.0;
    cells.push_back(bilayer_cell(c, 1.0 + 0.01 * state + 0.002 * own + shift, 0.5 * state + 0.3 * own));
  }
  const Analysis a = analyse(cfg, cells);
  ASSERT_TRUE(a.bilayer);
  for (const auto& v : a.variants) {
    if (v.key.reference) continue;
    const Comparison* temperature = nullptr;
    for (const auto& o : v.observables)
      if (o.observable == "temperature") temperature = &o;
    ASSERT_NE(temperature, nullptr);
    EXPECT_TRUE(temperature->paired);
    EXPECT_EQ(temperature->n_pairs, 6u);
    if (v.key.rounds == 1) {
      EXPECT_NEAR(temperature->diff, -0.03, 0.003);
      EXPECT_LT(temperature->decision.p, 1e-4);
      EXPECT_TRUE(temperature->decision.differs);
      EXPECT_NE(v.verdict.find("differs"), std::string::npos) << v.verdict;
    } else {
      // The membrane's observables have no margins: not differing is not shown equivalent.
      EXPECT_EQ(v.outcome, Outcome::inconclusive) << v.verdict;
    }
  }
  const std::string table = bilayer_differences_markdown(a, "gauss");
  EXPECT_NE(table.find("| tea32(1) distance | T |"), std::string::npos) << table;
}

namespace {

const Comparison* find_comparison(const VariantReport& v, const std::string& name) {
  for (const auto& o : v.observables)
    if (o.observable == name) return &o;
  return nullptr;
}

// Six replicas of MT, tea32(1) and tea32(32) whose cells hold the components: a state shared by the replica's
// generators plus a small scatter of each cell's own, and per generator a planted shift of T (`dT`) and of
// P_xx − P_yy (`dA`).
std::vector<CellResult> component_cells(const StudyConfig& cfg, double ref_T, double dT_r1, double dA_r1) {
  std::vector<CellResult> cells;
  for (const auto& c : enumerate_cells(cfg)) {
    const double state = double(dpdrng::rng::splitmix64_mix(c.seed) >> 11) * 0x1p-53 - 0.5;
    const std::uint64_t who = (std::uint64_t(c.rounds) << 8) | (c.reference ? 1u : 2u);
    const auto own = [&](int k) {
      return double(dpdrng::rng::splitmix64_mix(c.seed ^ who ^ (std::uint64_t(k) << 32)) >> 11) * 0x1p-53 - 0.5;
    };
    const bool r1 = !c.reference && c.rounds == 1;
    const double T = ref_T + 0.01 * state + 0.002 * own(0) + (r1 ? dT_r1 : 0.0);
    CellResult r = bilayer_cell(c, T, 0.5 * state + 0.3 * own(1));
    const auto put = [&](const std::string& n, double mean) {
      r.scalars[n + "_mean"] = mean;
      r.scalars[n + "_sem"] = 0.01;
    };
    put("temperature_x", T + 0.002 * own(2)), put("temperature_y", T + 0.002 * own(3));
    put("temperature_z", T + 0.002 * own(4));
    put("pressure_xx_minus_yy", 0.05 * state + 0.02 * own(5) + (r1 ? dA_r1 : 0.0));
    cells.push_back(std::move(r));
  }
  return cells;
}

const std::string kSixReplicas =
    with(with(kTinyBilayer, "replicas = 1", "replicas = 6"), "rounds = [1]", "rounds = [1, 32]");

}  // namespace

// Isotropy in the membrane's verdicts: an in-plane anisotropy P_xx − P_yy planted in one generator (the halves
// feed's direction-dependent defect) is found by its paired test inside the study's one Holm family, and the
// per-component temperatures are tested beside it.
TEST(BilayerStudyAnalysis, InPlaneAnisotropyAndTemperatureComponentsAreVerdictMembers) {
  const StudyConfig cfg = parse_config(kSixReplicas, "b.toml");
  const std::vector<CellResult> cells = component_cells(cfg, 1.0, 0.0, 0.3);
  const Analysis a = analyse(cfg, cells);
  std::size_t tested = 0;
  for (const auto& v : a.variants) {
    if (v.key.reference) continue;
    for (const char* name : {"temperature_x", "temperature_y", "temperature_z", "pressure_xx_minus_yy"}) {
      const Comparison* c = find_comparison(v, name);
      ASSERT_NE(c, nullptr) << name;
      EXPECT_TRUE(c->available && c->paired && c->decision.tested()) << name;
      EXPECT_EQ(c->n_pairs, 6u) << name;
      tested += c->decision.tested();
    }
    const Comparison* aniso = find_comparison(v, "pressure_xx_minus_yy");
    if (v.key.rounds == 1) {
      EXPECT_NEAR(aniso->diff, 0.3, 0.03);
      EXPECT_TRUE(aniso->decision.differs);
      EXPECT_NE(v.verdict.find("differs"), std::string::npos) << v.verdict;
      EXPECT_FALSE(find_comparison(v, "temperature")->decision.differs);
    } else {
      EXPECT_FALSE(aniso->decision.differs);
    }
  }
  EXPECT_EQ(tested, 8u);
  // One family: every variant's tests, the components included.
  std::size_t members = 0;
  for (const auto& v : a.variants) members += v.tests;
  EXPECT_EQ(a.family_size, members);
  EXPECT_EQ(a.families, 1u);
  EXPECT_EQ(a.family_size, 2u * bilayer_observables().size());  // every scalar of both variants, no profiles stored
  const std::string table = bilayer_differences_markdown(a, "gauss");
  EXPECT_NE(table.find("| tea32(1) distance | P_xx − P_yy | "), std::string::npos) << table;
}

// Cells stored before the components were measured: those rows say "not measured", are not tested, and the
// verdict rests on the rest as before.
TEST(BilayerStudyAnalysis, CellsWithoutComponentsSayNotMeasured) {
  const StudyConfig cfg = parse_config(kSixReplicas, "b.toml");
  std::vector<CellResult> cells = component_cells(cfg, 1.0, -0.03, 0.0);
  for (auto& c : cells)
    for (const char* n : {"temperature_x", "temperature_y", "temperature_z", "pressure_xx_minus_yy"})
      for (const char* suffix : {"_mean", "_sem"}) c.scalars.erase(std::string(n) + suffix);
  const Analysis a = analyse(cfg, cells);
  for (const auto& v : a.variants) {
    if (v.key.reference) continue;
    for (const char* name : {"temperature_x", "pressure_xx_minus_yy"}) {
      const Comparison* c = find_comparison(v, name);
      ASSERT_NE(c, nullptr) << name;
      EXPECT_FALSE(c->available);
      EXPECT_FALSE(c->decision.tested());
      EXPECT_EQ(c->note, "not measured");
    }
    if (v.key.rounds == 1) {
      EXPECT_TRUE(find_comparison(v, "temperature")->decision.differs);
    }
  }
  const std::string table = bilayer_differences_markdown(a, "gauss");
  EXPECT_NE(table.find("| tea32(1) distance | P_xx − P_yy | – | – | – | – | – | not measured |"), std::string::npos)
      << table;
  EXPECT_TRUE(error_budget_csv(error_budget(a, 1.0)).find("pressure_xx_minus_yy") == std::string::npos);
}

// The membrane's reference runs the mt19937 stream in cells mode and stores no ζ: its effective power is the
// ideal 1 (independent unit-variance numbers), so the variants' weighted ⟨ζ²⟩ still predicts their shift.
TEST(BilayerStudyAnalysis, AReferenceWithoutZetaHasTheIdealPower) {
  const StudyConfig cfg = parse_config(kSixReplicas, "b.toml");
  std::vector<CellResult> cells = component_cells(cfg, 1.0, -0.03, 0.0);
  for (auto& c : cells)
    if (!c.cell.reference) {
      c.scalars["zeta_weighted_second_moment_mean"] = c.cell.rounds == 1 ? 0.96 : 1.0;
      c.scalars["zeta_weighted_second_moment_sem"] = 0.001;
    }
  const Analysis a = analyse(cfg, cells);
  for (const auto& v : a.variants) {
    if (v.key.reference) {
      EXPECT_FALSE(std::isfinite(v.power_predicted_shift.value));
      continue;
    }
    EXPECT_NEAR(v.power_predicted_shift.value, v.key.rounds == 1 ? -0.04 : 0.0, 1e-12);
    EXPECT_NEAR(v.power_predicted_shift.se, 0.001 / std::sqrt(6.0), 1e-9);
  }
  EXPECT_NE(zeta_csv(a).find("tea32,1,gauss,halves,distance,0.01,6,0,"), std::string::npos) << zeta_csv(a);
}

// The error budget separates what cancels: the integrator heats the reference by 3 % and the generator's noise
// cools by 3 %, so the variant reads k_BT = 1 while both parts of its error are far from 0.
TEST(ErrorBudget, CancellingErrorsAreShownApart) {
  const StudyConfig cfg = parse_config(kSixReplicas, "b.toml");
  const std::vector<CellResult> cells = component_cells(cfg, 1.03, -0.03, 0.0);
  const Analysis a = analyse(cfg, cells);
  const std::vector<BudgetRow> rows = error_budget(a, 1.0);
  const BudgetRow* t = nullptr;
  for (const auto& r : rows)
    if (r.variant->key.rounds == 1 && r.observable == "temperature") t = &r;
  ASSERT_NE(t, nullptr);
  EXPECT_NEAR(t->noise.value, -0.03, 0.003);
  EXPECT_LT(t->noise.ci_high, 0.0);
  EXPECT_NEAR(t->integrator.value, 0.03, 0.006);
  EXPECT_GT(t->integrator.ci_low, 0.0);
  EXPECT_LT(t->total.ci_low, 0.0);
  EXPECT_GT(t->total.ci_high, 0.0);
  EXPECT_NEAR(t->noise.value + t->integrator.value, t->total.value, 1e-12);
  const std::string csv = error_budget_csv(rows);
  EXPECT_EQ(csv.rfind("variant,seeding,distribution,feed,integrator,dt,replicas,observable,target,scale,noise_error,", 0),
            0u);
  EXPECT_NE(csv.find("tea32(1),distance,gauss,halves,,0.01,6,temperature,1,fraction of target,"), std::string::npos)
      << csv;
  EXPECT_NE(error_budget_markdown(rows).find("| tea32(1) | gauss | distance | T | -3."), std::string::npos);
}

// The membrane study's driver end to end on the real engine: 2 cells of 300 steps.
TEST(BilayerStudyCli, RunResumeReport) {
  TempDir tmp;
  std::ofstream(tmp.path / "b.toml") << kTinyBilayer;
  const std::string cfg = quote(tmp.path / "b.toml");
  const fs::path out = tmp.path / "out";
  std::string err;
  ASSERT_EQ(run_cli("study run " + cfg + " --threads 2 --out " + quote(out), &err), 0) << err;
  const auto cells = Store(out).load_all();
  ASSERT_EQ(cells.size(), 2u);  // mt19937 and tea32(1), one replica
  std::map<std::string, const CellResult*> by_label;
  for (const auto& c : cells) {
    ASSERT_EQ(c.status, CellStatus::ok) << c.cell.id() << ": " << c.reason;
    by_label[c.cell.label()] = &c;
    for (const char* n : {"temperature_mean", "pressure_xx_mean", "pressure_yy_mean", "pressure_zz_mean",
                          "tension_mean", "thickness_mean", "tail_order_mean", "temperature_sem", "tension_sem"})
      EXPECT_TRUE(std::isfinite(c.scalar(n, NAN))) << c.cell.id() << " " << n;
    EXPECT_EQ(c.scalar("steps_done", 0), 300);
    const auto* z = c.find_series("profile/z");
    ASSERT_NE(z, nullptr);
    for (const char* p : {"profile/head", "profile/tail", "profile/water"}) {
      ASSERT_NE(c.find_series(p), nullptr) << p;
      EXPECT_EQ(c.find_series(p)->size(), z->size()) << p;
    }
    EXPECT_FALSE(c.has("chi2.x.trials"));
  }
  ASSERT_TRUE(by_label.count("mt19937") && by_label.count("tea32(1)"));
  // Paired replicas start from one state, but the noise differs: the runs are not copies of each other.
  EXPECT_NE(by_label["mt19937"]->scalar("temperature_mean", 0), by_label["tea32(1)"]->scalar("temperature_mean", 0));

  std::map<fs::path, std::pair<ino_t, long>> before;
  for (const auto& e : fs::directory_iterator(out / "cells")) {
    struct stat st {};
    ASSERT_EQ(stat(e.path().c_str(), &st), 0);
    before[e.path()] = {st.st_ino, st.st_mtim.tv_nsec};
  }
  ASSERT_EQ(run_cli("study run " + cfg + " --out " + quote(out), &err), 0) << err;
  EXPECT_NE(err.find("2 of 2 cells already stored"), std::string::npos) << err;
  EXPECT_NE(err.find("0 computed"), std::string::npos) << err;
  for (const auto& [f, id] : before) {
    struct stat st {};
    ASSERT_EQ(stat(f.c_str(), &st), 0) << f;
    EXPECT_EQ(st.st_ino, id.first) << f << " was recomputed";
    EXPECT_EQ(st.st_mtim.tv_nsec, id.second) << f << " was rewritten";
  }

  ASSERT_EQ(run_cli("study report " + quote(out), &err), 0) << err;
  const std::string md = read(out / "report" / "report.md");
  EXPECT_NE(md.find("cells stored: **2 of 2**"), std::string::npos);
  EXPECT_NE(md.find("| mt19937 | 1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| tea32(1) distance | 1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| tea32(1) distance | Σ |"), std::string::npos) << md;
  EXPECT_EQ(md.find("Pass fractions"), std::string::npos);  // no taps, no pass tables
  EXPECT_TRUE(fs::exists(out / "report" / "charts" / "bilayer_profiles_gauss.gp"));
  EXPECT_TRUE(fs::exists(out / "report" / "charts" / "bilayer_tension_gauss.gp"));
  EXPECT_NE(md.find("## Error budget"), std::string::npos);
  EXPECT_NE(read(out / "report" / "error_budget.csv").find(",pressure_xx_minus_yy,0,absolute,"), std::string::npos);

  // The CSV table holds each cell's own values (one replica: the mean is the cell's value).
  std::istringstream csv(read(out / "report" / "bilayer_table.csv"));
  std::string line;
  std::getline(csv, line);
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 10u) << line;
    const CellResult* c = by_label[f[0] == "mt19937" ? "mt19937" : "tea32(" + f[1] + ")"];
    ASSERT_NE(c, nullptr) << line;
    const double mean = std::stod(f[7]), ci = std::stod(f[8]);
    EXPECT_TRUE(std::isfinite(mean) && std::isfinite(ci) && ci > 0) << line;
    EXPECT_NEAR(mean, c->scalar(f[5] + "_mean", NAN), 1e-5 * (1 + std::abs(mean))) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 2u * bilayer_observables().size());
}

TEST(BilayerStudyCli, BadBilayerConfigExitsTwoAndWritesNothing) {
  TempDir tmp;
  const fs::path out = tmp.path / "out";
  std::string err;
  for (const auto& [text, key] : {std::pair{with(kTinyBilayer, "density = 3.0", "density = 3.0\na = 25"), "scene.a"},
                                  std::pair{kTinyBilayer + "[tests]\nchi2_steps = 4\n", "tests.chi2_steps"},
                                  std::pair{with(kTinyBilayer, "particles = 5400", "particles = 5401"), "scene.particles"},
                                  std::pair{with(kTinyBilayer, "steps = 300", "steps = 300\nkT = nan"), "scene.kT"}}) {
    std::ofstream(tmp.path / "bad.toml") << text;
    EXPECT_EQ(run_cli("study run " + quote(tmp.path / "bad.toml") + " --out " + quote(out), &err), 2)
        << key;
    EXPECT_NE(err.find(key), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace dpdrng_test::study_test_bilayer_study
