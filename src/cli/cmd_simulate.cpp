// dpdrng simulate: one DPD run of a scene (water: the paper's) with human or JSON output.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <memory>
#include <optional>

#include "dpdrng/cli/options.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/stats/moments.hpp"
#include "bilayer_cli.hpp"
#include "csv_out.hpp"
#include "run_json.hpp"
#include "simulate_physics.hpp"
#include "simulate_taps.hpp"

namespace dpdrng::cli {
namespace cmd_simulate {
namespace {

struct SimulateArgs {
  std::string scene = "water";
  std::string integrator = "mvv";
  dpd::WaterConfig cfg;
  RunOptions run{"all"};
  std::string compare;  // a reference generator to run at the same settings
  TapOptions taps;
};

void write_series(const std::filesystem::path& dir, const dpd::RunResult& r) {
  std::vector<double> step(r.series.step.begin(), r.series.step.end());
  write_csv(dir / "series.csv", {"step", "temperature", "pressure", "pressure_conservative", "px", "py", "pz"},
            {&step, &r.series.temperature, &r.series.pressure, &r.series.pressure_conservative, &r.series.px,
             &r.series.py, &r.series.pz});
  const auto& p = r.velocity_pdf;
  write_csv(dir / "velocity_pdf.csv", {"v", "pdf_x", "pdf_y", "pdf_z", "maxwell_boltzmann_kT", "maxwell_boltzmann_measured"},
            {&p.v, &p.pdf[0], &p.pdf[1], &p.pdf[2], &p.mb_kT, &p.mb_measured});
  write_csv(dir / "msd.csv", {"tau", "msd"}, {&r.msd.tau, &r.msd.msd});
  write_csv(dir / "rdf.csv", {"r", "g"}, {&r.rdf.r, &r.rdf.g});
}

// Moments of the run's ζ (nullopt when none was drawn or too few for intervals).
std::optional<stats::MomentsResult> zeta_moments(const dpd::ZetaSums& z) {
  if (z.n < 4) return std::nullopt;
  return stats::moments_of(stats::MomentSums::from_powers(z.n, z.s1, z.s2, z.s3, z.s4));
}

// The ζ of every production step's pairs inside r_c (fewer than 4 drawn: n, the rest null).
nlohmann::json zeta_json(const dpd::ZetaSums& z) {
  nlohmann::json j = {{"n", z.n}};
  const auto m = zeta_moments(z);
  if (m)
    j.update({{"mean", m->mean},
              {"mean_ci", {m->mean_ci.low, m->mean_ci.high}},
              {"variance", m->variance},
              {"variance_ci", {m->variance_ci.low, m->variance_ci.high}},
              {"second_moment", m->second_moment},
              {"second_moment_ci", {m->second_moment_ci.low, m->second_moment_ci.high}},
              {"second_moment_p", m->second_moment_p},
              {"skewness", m->skewness},
              {"excess_kurtosis", m->kurtosis},
              {"kurtosis", m->kurtosis + 3.0},
              {"confidence", m->confidence}});
  else
    for (const char* k : {"mean", "variance", "variance_ci", "skewness", "kurtosis"}) j[k] = nullptr;
  return j;
}

std::string zeta_line(const dpd::RunResult& r) {
  const auto m = zeta_moments(r.zeta);
  if (dpd::blew_up(r.status) || !m) return "n/a";
  std::ostringstream o;
  o << "variance " << std::setprecision(5) << m->variance << " [" << m->variance_ci.low << ", "
    << m->variance_ci.high << "] (95 %), kurtosis " << std::setprecision(4) << m->kurtosis + 3.0 << ", n " << m->n;
  return o.str();
}

// "2 thread(s)", or with the steps each team size ran where the run moved to fewer: "2 thread(s) (steps on
// 2: 140, on 1: 10)".
std::string threads_text(const dpd::Timings& t) {
  std::string text = std::to_string(t.threads) + " thread(s)";
  if (t.steps_by_team.size() < 2) return text;
  std::string steps;
  for (auto it = t.steps_by_team.rbegin(); it != t.steps_by_team.rend(); ++it)
    steps += (steps.empty() ? "" : ", on ") + std::to_string(it->first) + ": " + std::to_string(it->second);
  return text + " (steps on " + steps + ")";
}

void print_human(const dpd::RunResult& r) {
  // A run that blew up has no observables: "n/a", never a number.
  const bool na = dpd::blew_up(r.status);
  auto pm = [na](const dpd::Stat& s) {
    if (na) return std::string("n/a");
    std::ostringstream o;
    o << std::setprecision(6) << s.mean;
    if (!std::isfinite(s.sem)) return o.str() + " (error not applicable: " + std::to_string(s.n) + " sample(s))";
    o << " ± " << std::setprecision(2) << s.sem << " (std " << std::setprecision(4) << s.std << ")";
    return o.str();
  };
  auto num = [na](double v) {
    std::ostringstream o;
    o << v;
    return na ? std::string("n/a") : o.str();
  };
  std::cout << "scene water: " << r.particles << " beads, box " << r.box_length << ", pairs " << r.pairs << ", "
            << r.generator << " / " << r.seeding << " / " << r.distribution << " / feed " << r.feed
            << (r.integrator == "mvv" ? "" : ", integrator " + r.integrator) << "\n"
            << "status                 " << r.status << " (" << r.steps_done << " steps)\n"
            << "temperature k_BT       " << pm(r.temperature) << "\n"
            << "pressure               " << pm(r.pressure) << "\n"
            << "pressure (conservative)" << " " << pm(r.pressure_conservative) << "\n"
            << "diffusion coefficient  "
            << (na                               ? "n/a"
                : !std::isfinite(r.msd.diffusion) ? "not applicable: " + r.msd.not_applicable
                                                  : num(r.msd.diffusion) + " ± " + num(r.msd.diffusion_sem))
            << "\n"
            << "velocity PDF error     "
            << (na ? "n/a"
                   : num(r.velocity_pdf.error_rate_kT_mean) + " (vs MB at k_BT), " +
                         (std::isfinite(r.velocity_pdf.error_rate_measured_mean)
                              ? num(r.velocity_pdf.error_rate_measured_mean) + " (at measured T)"
                              : "at measured T not applicable: " + r.velocity_pdf.measured_not_applicable))
            << "\n"
            << (na ? "" : physics_lines(r))
            << "momentum drift / bead  " << r.momentum_drift << "\n"
            << "zeta (pairs in r_c)    " << zeta_line(r) << "\n"
            << "time                   " << r.timings.total_s << " s, " << r.timings.particle_steps_per_s
            << " particle-steps/s, " << threads_text(r.timings) << "\n"
            << "random numbers         " << r.timings.random_numbers << ", " << r.timings.ns_per_number
            << " ns each (RNG share of a step, by difference against zeta = 0: " << 100 * r.timings.rng_share_estimate << " %)\n";
}

// pnhln draws no pair noise (its thermostat's noise comes from the mt19937 stream): a pair-noise option that
// names anything else would be silently ignored, so it is refused.
void check_reference_only(const CLI::App& sub, const SimulateArgs& a) {
  const auto given = [&](const char* name) { return sub.count(name) > 0; };
  const auto refuse = [&](const std::string& what) {
    throw InputError(what + ": --integrator " + a.integrator +
                     " draws no pair noise (its thermostat's noise comes from the mt19937 reference stream); leave "
                     "the option out");
  };
  if (given("--generator") && a.run.gen.name != "mt19937") refuse("--generator " + a.run.gen.name);
  for (const char* o : {"--rounds", "--key", "--seeding"})
    if (given(o)) refuse(o);
  if (given("--distribution") && a.run.distribution != "gauss") refuse("--distribution " + a.run.distribution);
  if (given("--feed") && a.run.feed != "halves") refuse("--feed " + a.run.feed);
}

nlohmann::json simulate_json(const dpd::RunResult& r) {
  nlohmann::json j = dpd::to_json(r, false);
  if (!dpd::blew_up(r.status)) j["zeta"].update(zeta_json(r.zeta));
  return j;
}

// The document's version, schema and inputs: the water scene's physics beside the noise settings.
nlohmann::json stamped(const nlohmann::json& j, const dpd::WaterConfig& c) {
  return cli::stamped(j, "dpdrng.simulate.water/1", c,
                      {{"particles", c.particles}, {"density", c.density}, {"a", c.a}, {"rc", c.rc}, {"kT", c.kT},
                       {"gamma", c.gamma}, {"lambda", c.lambda}, {"dt", c.dt}, {"integrator", c.integrator_name()},
                       {"steps", c.steps}, {"equilibrate", c.equilibrate}});
}

// The run's config with the reference generator: the same feed, seeding, integrator, Δt and initial state.
dpd::WaterConfig reference_config(dpd::WaterConfig cfg, const std::string& name) {
  try {
    cfg.generator = rng::validated(rng::GeneratorSpec{name, 0, cfg.generator.key});
    cfg.series = false;
    cfg.taps = {};
    cfg.validate();
  } catch (const InputError& e) {
    throw InputError(std::string("--compare: ") + e.what());
  }
  return cfg;
}

void run_simulate(SimulateArgs& a, const CLI::App& sub) {
  if (a.scene != "water") throw InputError("unknown scene '" + a.scene + "' (known: water, bilayer)");
  dpd::WaterConfig cfg = a.cfg;
  a.run.apply(cfg);
  dpd::set_integrator(cfg, a.integrator, "--integrator");
  if (cfg.integrator == dpd::Integrator::pnhln) check_reference_only(sub, a);
  cfg.series = !a.run.series_dir.empty();
  cfg.validate();
  a.taps.apply(cfg);  // against the validated steps
  std::optional<dpd::WaterConfig> reference;
  if (!a.compare.empty()) reference = reference_config(cfg, a.compare);
  begin_work();
  if (cfg.series)
    prepare_output_files(a.run.series_dir, {"series.csv", "velocity_pdf.csv", "msd.csv", "rdf.csv"}, "--series");
  std::optional<TapWriter> taps;
  if (a.taps.any()) a.taps.check_paths(), taps.emplace(a.taps, cfg);
  dpd::RunHooks hooks;
  const bool long_run = double(cfg.particles) * double(cfg.steps) > 2e7;
  if (!a.run.quiet && long_run)
    hooks.progress = [](std::int64_t step, std::int64_t steps) {
      std::cerr << "\rstep " << step << " / " << steps << std::flush;
      if (step == steps) std::cerr << "\n";
    };
  dpd::RunHooks tapped = hooks;
  if (taps) tapped.in_range = [&taps](const dpd::InRangeTap& tap) { taps->step(tap); };
  const dpd::RunResult r = dpd::run_water(cfg, tapped);
  if (!a.run.series_dir.empty()) write_series(a.run.series_dir, r);
  if (taps) taps->commit(r);
  if (reference) {
    const dpd::RunResult ref = dpd::run_water(*reference, hooks);
    if (a.run.json) {
      const nlohmann::json j = {{"variant", simulate_json(r)},
                                {"reference", simulate_json(ref)},
                                {"shifts", compare_shifts_json(r, ref)}};
      std::cout << stamped(j, cfg).dump(2) << "\n";
      return;
    }
    print_human(r);
    std::cout << "\nreference run:\n";
    print_human(ref);
    std::cout << compare_lines(r, ref);
    return;
  }
  if (a.run.json) {
    std::cout << stamped(simulate_json(r), cfg).dump(2) << "\n";
  } else {
    print_human(r);
    std::cout << reference_note(r);
  }
}

const bool registered = register_command(40, [](CLI::App& root) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* sub = root.add_subcommand("simulate", "run a DPD scene (water: the paper's 256-bead fluid)");
  sub->footer(
      "Defaults are the paper's water run: 256 beads, rho 3, a 25, rc 1, kT 1, gamma 6.75, lambda 0.5, dt 0.04,\n"
      "10000 steps (500 equilibration), every pair every step. mt19937 (the reference) draws each step's\n"
      "numbers from one stream in a fixed pair order. --series DIR writes series.csv, velocity_pdf.csv,\n"
      "msd.csv and rdf.csv. A run that blows up still exits 0: its status reads 'unstable at step k: reason'.\n"
      "Taps (water; mvv and scmvv): --tap-zeta FILE writes the zeta the force used, --tap-words FILE the\n"
      "generator words each came from (the block's words, then under --feed blocks the second block's), for the\n"
      "production steps A:B of --tap-steps (default: all of them, the steps of the zeta block of --json; a step\n"
      "that blows up is left out, as there). Step-major; within a step only the pairs inside r_c (r < rc, those\n"
      "whose zeta enters the force), in the order (i, j), i < j, ascending by bead index, whatever --pairs and\n"
      "--threads (the files are the same bit for bit for any --threads). Raw little-endian: words uint64 (for\n"
      "chi2/ttest/corr --format u64, nist --format raw, dieharder -g 200, PractRand stdin64), zeta float64 (for\n"
      "moments/gof --format f64). FILE.json describes each: generator, key, seeding, distribution, feed, words\n"
      "per pair, steps, pairs per step, count, dtype. Files appear whole, after the run, or not at all.\n"
      "Integrators (water only):\n"
      "  mvv         Groot-Warren modified velocity-Verlet with --lambda (the default).\n"
      "  shardlow    Shardlow's S1 splitting: k_BT much nearer 1 at large dt; the reported pressure is the\n"
      "              conservative one.\n"
      "  scmvv[:K]   self-consistent velocity-Verlet (Besold et al. 2000; Vattulainen et al. 2002): the random\n"
      "              force drawn once a step from the pair noise (--generator, --seeding, --distribution,\n"
      "              --feed, as mvv), the dissipative force re-evaluated K times with the updated velocities.\n"
      "              K = 1 (the default) is DPD-VV; K from 1 to 100.\n"
      "  pnhln[:mu]  pairwise Nose-Hoover-Langevin thermostat (Leimkuhler & Shang 2015), coupling mu (default 10):\n"
      "              no pair noise; the thermostat variable's noise, one Gaussian a step, comes from the mt19937\n"
      "              reference stream seeded with --seed, so --generator other than mt19937, --rounds, --key,\n"
      "              --seeding, --distribution other than gauss and --feed other than halves are refused.\n"
      "              The reported pressure is the conservative one.");
  auto& c = a->cfg;
  sub->add_option("--scene", a->scene, "scene: water or bilayer (the H3(T6)2 membrane)")->capture_default_str();
  add_integer(*sub, "--particles,-n", c.particles, "number of beads", {2, 50'000'000});
  add_real(*sub, "--density", c.density, "bead density rho");
  add_real(*sub, "--a", c.a, "conservative repulsion a_ij");
  add_real(*sub, "--rc", c.rc, "cut-off radius");
  add_thermostat_options(*sub, c);
  add_real(*sub, "--dt", c.dt, "time step");
  sub->add_option("--integrator", a->integrator,
                  "mvv (Groot-Warren, --lambda), shardlow (S1), scmvv[:K] (self-consistent VV, K iterations) or "
                  "pnhln[:mu] (pairwise Nose-Hoover-Langevin); water only, see below")
      ->capture_default_str();
  add_integer(*sub, "--steps", c.steps, "steps", {1, kInt64Max});
  add_integer(*sub, "--equilibrate", c.equilibrate, "equilibration steps (not sampled)", {0, kInt64Max});
  a->run.add_to(*sub, c,
                {"all (every pair, as the paper) or cells (linked cells, sorted every step)",
                 "sampling interval of the distributions",
                 "directory for time series, histograms and g(r) (CSV)"});
  add_integer(*sub, "--zeta-autocorrelation", c.zeta_lags,
              "lags K of the zeta autocorrelation on tracked pairs inside r_c (0: off)", {0, 1000});
  sub->add_option("--compare", a->compare,
                  "also run this reference generator (e.g. mt19937) at the same settings and print the shifts");
  a->taps.add_to(*sub);
  sub->callback([a, sub] {
    // An option that would change nothing is refused rather than silently ignored.
    if (a->integrator == "shardlow" && sub->count("--lambda") > 0)
      throw InputError("--lambda: the shardlow integrator has no lambda (it belongs to Groot-Warren's MVV)");
    if (a->scene == "bilayer") {
      if (!a->compare.empty()) throw InputError("--compare: the water scene only");
      if (!a->taps.given().empty()) throw InputError(a->taps.given() + ": the water scene only");
      return simulate_bilayer(*sub, a->cfg, a->run);
    }
    run_simulate(*a, *sub);
  });
});

}  // namespace
}  // namespace cmd_simulate
}  // namespace dpdrng::cli
