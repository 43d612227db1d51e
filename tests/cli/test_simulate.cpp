// The CLI contract of `dpdrng simulate` (water and --scene bilayer) and `simulate-bilayer`, run as the built
// binary: bad parameters exit 2 with one line naming the parameter; a run exits 0 with its fixed set of JSON keys,
// a run that blows up included (its status says where and why: data, not an error).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "run_cli.hpp"

namespace dpdrng_test::cli_test_simulate {

using namespace dpdrng::cli_test;
using nlohmann::json;

namespace {

// 64 beads (box 2.77 > 2 r_c), 20 steps: a few milliseconds.
const std::string kTiny = "simulate -n 64 --steps 20 --equilibrate 10 -q ";
// The bilayer scene is 5400 beads; 20 steps (10 warm-up) take well under a second.
const std::string kTinyBilayer = "simulate --scene bilayer --steps 20 --equilibrate 10 -q ";

struct BadCase {
  std::string args;
  std::string names;  // what the one-line reason must mention
};

void expect_refused(const BadCase& c) {
  const Result r = run(c.args);
  EXPECT_EQ(r.code, 2) << c.args;
  EXPECT_TRUE(r.out.empty()) << c.args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
  EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << ": " << r.err;
}

json run_json(const std::string& args) {
  const Result r = run(args + " --json");
  EXPECT_EQ(r.code, 0) << args << ": " << r.err;
  return json::parse(r.out);
}

std::set<std::string> keys(const json& j) {
  std::set<std::string> k;
  for (auto it = j.begin(); it != j.end(); ++it) k.insert(it.key());
  return k;
}

TEST(CliSimulate, BadWaterParametersExitTwoNamingTheParameter) {
  const std::vector<BadCase> cases = {
      {kTiny + "--density 0", "density"},        {kTiny + "--density -3", "density"},
      {kTiny + "--dt 0", "dt"},                  {kTiny + "--dt -0.01", "dt"},
      {kTiny + "--dt 1e-400", "dt"},             {kTiny + "--density nan", "density"},
      {kTiny + "--a nan", "--a"},                {kTiny + "--a inf", "--a"},
      {kTiny + "--a -inf", "--a"},               {kTiny + "--rc nan", "rc"},
      {kTiny + "--gamma nan", "gamma"},          {kTiny + "--gamma -1", "gamma"},
      {kTiny + "--kT inf", "kT"},                {kTiny + "--kT 0", "kT"},
      {kTiny + "--dt nan", "dt"},                {kTiny + "--lambda nan", "lambda"},
      {kTiny + "--lambda 2", "lambda"},          {kTiny + "--skin 0.3", "--skin"},
      {kTiny + "--density 1e400", "density"},
      {kTiny + "--rounds 0", "rounds"},          {kTiny + "-g tea32 --rounds 65", "rounds"},
      {kTiny + "-g philox4x32 --rounds 17", "rounds"}, {kTiny + "--rounds -1", "rounds"},
      {kTiny + "--rounds 99999999999", "rounds"}, {kTiny + "-g bogus", "generator"},
      {kTiny + "--seeding bogus", "seeding"},    {kTiny + "--seeding counter", "seeding"},
      {kTiny + "--distribution bogus", "distribution"}, {kTiny + "--scene bogus", "scene"},
      {kTiny + "--pairs bogus", "pairs"},        {kTiny + "--threads -1", "threads"},
      {kTiny + "--seed -1", "seed"},             {kTiny + "--init-seed -5", "init-seed"},
      {kTiny + "--sample-every 0", "--sample-every"}, {kTiny + "--key 1,2,3", "key"},
      {kTiny + "--integrator bogus", "integrator"},
      {kTiny + "--integrator scmvv:0", "--integrator"},  {kTiny + "--integrator scmvv:101", "--integrator"},
      {kTiny + "--integrator scmvv:x", "--integrator"},  {kTiny + "--integrator pnhln:0", "--integrator"},
      {kTiny + "--integrator pnhln:nan", "--integrator"}, {kTiny + "--integrator mvv:0.5", "--integrator"},
      {kTiny + "--integrator pnhln -g tea32", "--generator"},
      {kTiny + "--integrator pnhln --seeding pair-step", "--seeding"},
      {kTiny + "--integrator pnhln --rounds 2", "--rounds"},
      {kTiny + "--integrator pnhln --distribution uniform", "--distribution"},
      {kTiny + "--integrator pnhln --feed blocks", "--feed"},
      {kTiny + "--feed bogus", "feed"},          {kTiny + "--distribution uniform --feed blocks", "feed"},
      {kTiny + "--distribution uniform --feed inverse", "feed"},
      {kTiny + "--compare bogus", "--compare"},
      {kTiny + "--zeta-autocorrelation -1", "--zeta-autocorrelation"},
      {kTiny + "--zeta-autocorrelation 1001", "--zeta-autocorrelation"},
      {"simulate -q --particles 1", "particles"}, {"simulate -q -n 8", "particles/density"},
      {"simulate -q -n 64 --steps -5 --equilibrate 0", "steps"},
      {"simulate -q -n 64 --steps 0 --equilibrate 0", "steps"},
      {"simulate -q -n 64 --steps 1e3", "steps"},
      {"simulate -q -n 64 --steps 100 --equilibrate 100", "equilibrate"},
      {"simulate -q -n 64 --steps 100 --equilibrate 200", "equilibrate"},
      {"simulate -q -n 64 --steps 100 --equilibrate -1", "equilibrate"},
  };
  for (const auto& c : cases) expect_refused(c);
}

TEST(CliSimulate, BadBilayerParametersExitTwoNamingTheParameter) {
  const std::vector<BadCase> cases = {
      {kTinyBilayer + "--dt 0", "dt"},            {kTinyBilayer + "--dt nan", "dt"},
      {kTinyBilayer + "--kT 0", "kT"},            {kTinyBilayer + "--gamma inf", "gamma"},
      {kTinyBilayer + "--lambda nan", "lambda"},  {kTinyBilayer + "--skin 0.3", "--skin"},
      {kTinyBilayer + "--rounds 0", "rounds"},    {kTinyBilayer + "-g bogus", "generator"},
      {kTinyBilayer + "--seeding bogus", "seeding"}, {kTinyBilayer + "--distribution nope", "distribution"},
      {kTinyBilayer + "--pairs bogus", "pairs"},  {kTinyBilayer + "--threads -2", "threads"},
      {kTinyBilayer + "--seed -1", "seed"},       {kTinyBilayer + "--sample-every 0", "--sample-every"},
      {kTinyBilayer + "--density 3", "density"},  {kTinyBilayer + "--a 25", "--a"},
      {kTinyBilayer + "--particles 100", "particles"}, {kTinyBilayer + "--rc 1", "rc"},
      {kTinyBilayer + "--integrator shardlow", "integrator"},
      {kTinyBilayer + "--integrator scmvv:5", "integrator"},
      {kTinyBilayer + "--integrator pnhln", "integrator"},
      {kTinyBilayer + "--compare mt19937", "--compare"},
      {kTinyBilayer + "--distribution uniform --feed blocks", "feed"},
      {"simulate --scene bilayer -q --steps -1 --equilibrate 0", "steps"},
      {"simulate --scene bilayer -q --steps 20 --equilibrate 20", "equilibrate"},
      {"simulate-bilayer -q --steps 20 --equilibrate 10 --warmup 5 --dt-warmup inf", "dt-warmup"},
      {"simulate-bilayer -q --steps 20 --equilibrate 10 --warmup 5 --dt -1", "dt"},
      {"simulate-bilayer -q --steps 20 --equilibrate 10 --warmup 30", "warmup"},
  };
  for (const auto& c : cases) expect_refused(c);
}

// The record's fixed keys, and no others: the record is what scripts and the study read.
TEST(CliSimulate, TinyWaterRunGivesTheIssuesJson) {
  const json j = run_json(kTiny);
  EXPECT_EQ(j.at("status"), "ok");
  EXPECT_EQ(j.at("integrator"), "mvv");
  EXPECT_EQ(j.at("steps_done"), 20);
  for (const char* k : {"temperature_mean", "temperature_std", "pressure_mean", "pressure_conservative_mean"})
    EXPECT_TRUE(j.at(k).is_number()) << k;
  // 10 production steps leave fewer than 8 MSD frames: no diffusion coefficient (null), not 0.
  EXPECT_TRUE(j.at("diffusion_coefficient").is_null()) << j.at("diffusion_coefficient");
  EXPECT_GT(j.at("temperature_mean").get<double>(), 0.5);  // k_BT = 1 fluid, 10 samples
  EXPECT_LT(j.at("temperature_mean").get<double>(), 2.0);
  const std::set<std::string> want = {
      "box_length", "configurational_temperature", "diffusion_coefficient", "diffusion_coefficient_sem",
      "distribution", "dpdrng_version", "feed", "generator", "inputs", "integrator", "not_applicable",
      "pressure_components", "schema",
      "temperature_components",
      "momentum_drift_per_bead", "momentum_final", "msd_fit", "pairs", "particles", "pressure",
      "pressure_conservative", "pressure_conservative_diag", "pressure_conservative_mean",
      "pressure_conservative_sem", "pressure_diag", "pressure_mean", "pressure_sem", "seeding", "status",
      "steps_done", "temperature", "temperature_mean", "temperature_sem", "temperature_std", "temperature_std_sem",
      "timings", "velocity_pdf_error_rate", "velocity_pdf_error_rate_measured_T", "velocity_pdf_error_rate_sem",
      "velocity_pdf_error_rate_xyz", "zeta", "zeta_sums"};
  EXPECT_EQ(keys(j), want);
  EXPECT_EQ(j.at("schema"), "dpdrng.simulate.water/1");
  EXPECT_EQ(j.at("inputs").at("particles"), 64);
  EXPECT_EQ(j.at("inputs").at("steps"), 20);
  EXPECT_EQ(j.at("inputs").at("generator"), "tea32");
  // 10 production steps sample the configurational temperature once: no error to give, so null with the reason.
  EXPECT_TRUE(j.at("configurational_temperature").is_null());
  EXPECT_TRUE(j.at("not_applicable").at("configurational_temperature").is_string());
  EXPECT_EQ(j.at("feed"), "halves");
  const std::set<std::string> timings = {
      "force_s", "list_builds", "ns_per_number", "ns_per_zeta", "particle_steps_per_s", "per_step_s",
      "production_particle_steps_per_s", "production_s", "random_numbers", "rng_share_estimate", "team",
      "threads", "total_s", "zetas"};
  EXPECT_EQ(keys(j.at("timings")), timings);
  // 64 beads run on one thread: every one of the 20 steps on a team of one, no move.
  EXPECT_EQ(j.at("timings").at("team"), (nlohmann::json{{"moves", 0}, {"steps", {{"1", 20}}}}));
  EXPECT_EQ(keys(j.at("temperature")),
            (std::set<std::string>{"mean", "std", "sem", "sem_dof", "std_sem", "std_sem_dof", "n"}));
}

TEST(CliSimulate, TinyBilayerRunGivesItsJsonAlikeFromEitherCommand) {
  const json a = run_json(kTinyBilayer + "--threads 1");
  const json b = run_json("simulate-bilayer -q --steps 20 --equilibrate 10 --warmup 10 --threads 1");
  EXPECT_EQ(a.at("status"), "ok");
  const std::set<std::string> want = {
      "bilayer_thickness", "bilayer_thickness_sem", "box", "distribution", "dpdrng_version", "feed", "generator",
      "head_separation", "inputs", "schema",
      "head_separation_sem", "lipids", "lipids_out_max", "membrane_tension", "membrane_tension_conservative",
      "membrane_tension_conservative_sem", "membrane_tension_convention", "membrane_tension_sem",
      "membrane_tension_without_bend_virial", "membrane_tension_without_bond_virial", "momentum_drift_per_bead",
      "momentum_final", "nematic_order", "nematic_order_sem", "pairs", "particles", "pressure_diag", "pressure_mean",
      "pressure_sem",
      "pressure_xx_mean", "pressure_xx_sem", "pressure_xx_minus_yy_mean", "pressure_xx_minus_yy_sem", "pressure_yy_mean",
      "pressure_yy_sem", "pressure_zz_mean", "pressure_zz_sem", "scene", "seeding", "status", "steps_done", "tail_order", "tail_order_sem",
      "tail_order_stat", "temperature", "temperature_mean", "temperature_sem", "tension", "thickness", "timings"};
  EXPECT_EQ(keys(a), want);
  EXPECT_TRUE(keys(a.at("timings")).count("bonded_s"));
  EXPECT_FALSE(keys(a.at("timings")).count("production_s"));
  // --scene bilayer keeps the scene's defaults (cells, its seeds): the same run as simulate-bilayer.
  json a_phys = a, b_phys = b;
  a_phys.erase("timings"), b_phys.erase("timings");
  EXPECT_EQ(a_phys, b_phys);
}

TEST(CliSimulate, SeriesWritesItsFiles) {
  const std::string dir = scratch("_series");
  std::filesystem::remove_all(dir);
  const Result r = run(kTiny + "--series \"" + dir + "\"");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"series.csv", "velocity_pdf.csv", "msd.csv", "rdf.csv"})
    EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::path(dir) / f)) << f;
  const std::string series = slurp(dir + "/series.csv");
  EXPECT_EQ(series.rfind("step,temperature,pressure,pressure_conservative,px,py,pz\n", 0), 0u) << series;
  EXPECT_EQ(std::count(series.begin(), series.end(), '\n'), 21);  // header + one row per step
  std::filesystem::remove_all(dir);
}

TEST(CliSimulate, BilayerSeriesWritesItsFiles) {
  const std::string dir = scratch("_series");
  std::filesystem::remove_all(dir);
  const Result r = run(kTinyBilayer + "--series \"" + dir + "\"");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"profile.csv", "series.csv", "order.csv"})
    EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::path(dir) / f)) << f;
  std::filesystem::remove_all(dir);
}

// A blow-up is data: exit 0, the JSON record, status "unstable at step k: reason". The 200-bead cells cases
// (3 cells a side) crashed in the cell grid on non-finite positions before System::wrap parked such beads.
TEST(CliSimulate, BlowUpIsAStatusNotACrash) {
  struct Case {
    std::string args, status;
  };
  const std::vector<Case> cases = {
      {kTiny + "--dt 5", "unstable at step 1: temperature runaway"},
      {kTiny + "--a 1e6", "unstable at step 1: temperature runaway"},
      {kTiny + "--a 1e300", "unstable at step 1: non-finite velocities or forces"},
      {"simulate -q -n 200 --steps 20 --equilibrate 10 --pairs cells --a 1e300",
       "unstable at step 1: non-finite velocities or forces"},
      {kTiny + "--integrator shardlow --dt 1e300", "unstable at step 1: non-finite velocities or forces"},
      {"simulate -q -n 200 --steps 20 --equilibrate 10 --pairs cells --integrator shardlow --a 1e300",
       "unstable at step 1: non-finite velocities or forces"},
      {kTinyBilayer + "--dt 5", "unstable at step 11: temperature runaway"},
  };
  for (const auto& c : cases) {
    const Result r = run(c.args + " --json");
    ASSERT_EQ(r.code, 0) << c.args << ": " << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j.at("status").get<std::string>().rfind(c.status, 0), 0u) << c.args << ": " << j.at("status");
  }
}

TEST(CliSimulate, ShardlowIntegratorIsChosenAndReported) {
  const json j = run_json(kTiny + "--integrator shardlow --dt 0.06");
  EXPECT_EQ(j.at("status"), "ok");
  EXPECT_EQ(j.at("integrator"), "shardlow");
  // S1 reports no D+R virial (equal but for the rounding of two virial sums)
  EXPECT_NEAR(j.at("pressure_mean").get<double>(), j.at("pressure_conservative_mean").get<double>(), 1e-9);
  const Result human = run(kTiny + "--integrator shardlow");
  EXPECT_NE(human.out.find(", integrator shardlow"), std::string::npos) << human.out;
}

// scmvv and pnhln are spelt name[:parameter]; the JSON and the human line name the parameter. pnhln draws no
// pair noise: its record names the reference, and -g mt19937 (the reference itself) is accepted.
TEST(CliSimulate, ScmvvAndPnhlnAreChosenAndReported) {
  const json sc = run_json(kTiny + "--integrator scmvv:5");
  EXPECT_EQ(sc.at("status"), "ok");
  EXPECT_EQ(sc.at("integrator"), "scmvv:5");
  EXPECT_EQ(sc.at("generator"), "tea32(32)");  // the default pair noise
  EXPECT_GT(sc.at("zeta").at("n").get<std::uint64_t>(), 1000u);  // the pair noise, as mvv draws it
  EXPECT_EQ(run_json(kTiny + "--integrator scmvv").at("integrator"), "scmvv:1");
  const json nh = run_json(kTiny + "--integrator pnhln:2.5 -g mt19937");
  EXPECT_EQ(nh.at("status"), "ok");
  EXPECT_EQ(nh.at("integrator"), "pnhln:2.5");
  EXPECT_EQ(nh.at("generator"), "mt19937");
  EXPECT_EQ(nh.at("zeta").at("n"), 0u);
  EXPECT_NEAR(nh.at("pressure_mean").get<double>(), nh.at("pressure_conservative_mean").get<double>(), 1e-9);
  const Result human = run(kTiny + "--integrator pnhln");
  EXPECT_NE(human.out.find(", integrator pnhln:10"), std::string::npos) << human.out;
}

TEST(CliSimulate, HumanOutputNamesTheObservables) {
  const Result r = run(kTiny);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* line : {"scene water: 64 beads", "status                 ok (20 steps)", "temperature k_BT",
                           "pressure (conservative)", "diffusion coefficient", "momentum drift / bead"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
}

}  // namespace

namespace {

// The ζ moments of the production steps' pairs inside r_c, under each feed; n says how many draws went in.
TEST(CliSimulate, ZetaMomentsInTheJson) {
  for (const char* feed : {"halves", "blocks", "inverse"}) {
    const json j = run_json(kTiny + "-g tea32 -r 1 --feed " + feed);
    EXPECT_EQ(j.at("feed"), feed);
    const json& z = j.at("zeta");
    const auto n = z.at("n").get<std::uint64_t>();
    EXPECT_GT(n, 1000u) << feed;
    EXPECT_EQ(n, j.at("zeta_sums").at("n").get<std::uint64_t>());
    // Production steps only: fewer than every evaluation's pairs in range.
    EXPECT_LT(n, j.at("timings").at("zetas").get<std::uint64_t>());
    const double v = z.at("variance").get<double>();
    ASSERT_EQ(z.at("variance_ci").size(), 2u);
    EXPECT_LT(z.at("variance_ci")[0].get<double>(), v);
    EXPECT_GT(z.at("variance_ci")[1].get<double>(), v);
    for (const char* k : {"mean", "skewness", "kurtosis"}) EXPECT_TRUE(z.at(k).is_number()) << k;
  }
  const Result human = run(kTiny + "--feed blocks");
  EXPECT_NE(human.out.find("/ feed blocks"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("zeta (pairs in r_c)    variance"), std::string::npos) << human.out;
}

}  // namespace

namespace {

bool is_mean_se(const json& j) { return j.is_object() && j.at("mean").is_number() && j.at("se").is_number(); }

// The error budget's observables in {mean, se} form; the ζ autocorrelation only when asked for, null with the
// reason otherwise.
TEST(CliSimulate, PhysicsObservablesInTheJson) {
  const json j = run_json("simulate -n 64 --steps 120 --equilibrate 20 -q -g mt19937");
  EXPECT_TRUE(is_mean_se(j.at("configurational_temperature"))) << j.at("configurational_temperature");
  for (const char* k : {"temperature_components", "pressure_components"}) {
    ASSERT_EQ(j.at(k).size(), 3u) << k;
    for (const json& c : j.at(k)) EXPECT_TRUE(is_mean_se(c)) << k;
  }
  const json& z = j.at("zeta");
  EXPECT_TRUE(is_mean_se(z.at("weighted_second_moment")));
  EXPECT_TRUE(z.at("autocorrelation").is_null());
  EXPECT_NE(z.at("not_applicable").at("autocorrelation").get<std::string>().find("not requested"), std::string::npos);
  EXPECT_TRUE(z.at("variance").is_number());  // the moments stay beside them
  const json k = run_json("simulate -n 64 --steps 120 --equilibrate 20 -q -g mt19937 --zeta-autocorrelation 3");
  ASSERT_EQ(k.at("zeta").at("autocorrelation").size(), 3u) << k.at("zeta");
  for (const json& e : k.at("zeta").at("autocorrelation")) EXPECT_TRUE(is_mean_se(e)) << e;
  EXPECT_TRUE(is_mean_se(k.at("zeta").at("shared_bead_correlation")));
  const Result human = run("simulate -n 64 --steps 120 --equilibrate 20 -q -g mt19937 --zeta-autocorrelation 2");
  for (const char* line : {"k_BT configurational", "k_BT x, y, z", "pressure xx, yy, zz", "zeta <w²ζ²>/<w²>",
                           "zeta autocorrelation   lag 1:", "ε/r_c³"})
    EXPECT_NE(human.out.find(line), std::string::npos) << line << "\n" << human.out;
  // The reference itself needs no comparison; any other generator is told it does.
  EXPECT_EQ(human.out.find("--compare mt19937"), std::string::npos);
  EXPECT_NE(run(kTiny + "-g tea32 -r 1").out.find("--compare mt19937"), std::string::npos);
}

// --compare runs the reference at the same settings (feed, seeding, integrator, Δt, initial state) and gives the
// shift of each main observable with its 95 % CI, which must contain the shift.
TEST(CliSimulate, CompareRunsTheReferenceAtTheSameSettings) {
  const json j = run_json(kTiny + "-g tea32 -r 1 --feed blocks --dt 0.03 --sample-every 2 --compare mt19937");
  const json &v = j.at("variant"), &ref = j.at("reference");
  EXPECT_EQ(v.at("generator"), "tea32(1)");
  EXPECT_EQ(ref.at("generator"), "mt19937");
  EXPECT_EQ(ref.at("feed"), "blocks");
  EXPECT_EQ(ref.at("steps_done"), v.at("steps_done"));
  const json& shifts = j.at("shifts");
  ASSERT_EQ(shifts.size(), 9u);  // T, T_conf, P, three T_α, three P_αα
  for (const json& s : shifts) {
    const json& d = s.at("shift");
    ASSERT_TRUE(d.is_object()) << s;
    const double m = d.at("mean").get<double>();
    EXPECT_LT(d.at("ci95")[0].get<double>(), m) << s;
    EXPECT_GT(d.at("ci95")[1].get<double>(), m) << s;
  }
  EXPECT_NEAR(shifts[0].at("shift").at("mean").get<double>(),
              v.at("temperature_mean").get<double>() - ref.at("temperature_mean").get<double>(), 1e-12);
  const Result human = run(kTiny + "-g tea32 -r 1 --compare mt19937");
  ASSERT_EQ(human.code, 0) << human.err;
  EXPECT_NE(human.out.find("comparison: tea32(1) − mt19937"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("k_BT (configurational)"), std::string::npos) << human.out;
}

}  // namespace

namespace {

// 32TEA(1) under pair-step seeding draws nearly one ζ for every pair and step: the dissipative force drains the
// fluid to k_BT ≈ 1e-4, where the Maxwell–Boltzmann density at the measured temperature vanishes outside one bin.
// The velocity PDF's error rate at the measured T then has no value: null with its reason, never nan or 0.
TEST(CliSimulate, ErrorRateAtAFrozenTemperatureIsNotApplicable) {
  const std::string args = "simulate -g tea32 -r 1 --seeding pair-step --steps 600 --equilibrate 300 ";
  const json j = run_json(args);
  EXPECT_LT(j.at("temperature_mean").get<double>(), 0.01);
  EXPECT_TRUE(j.at("velocity_pdf_error_rate_measured_T").is_null());
  EXPECT_NE(j.at("not_applicable").at("velocity_pdf_error_rate_measured_T").get<std::string>().find("vanishes"),
            std::string::npos);
  EXPECT_TRUE(j.at("velocity_pdf_error_rate").is_number());
  const Result human = run(args);
  ASSERT_EQ(human.code, 0) << human.err;
  EXPECT_EQ(human.out.find("nan"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("at measured T not applicable: the Maxwell-Boltzmann density"), std::string::npos)
      << human.out;
}

}  // namespace

}  // namespace dpdrng_test::cli_test_simulate
