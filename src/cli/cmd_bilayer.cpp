// dpdrng simulate-bilayer: the membrane scene (an H3(T6)2 bilayer in water) with human or JSON output.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "bilayer_cli.hpp"
#include "csv_out.hpp"
#include "run_json.hpp"
#include "dpdrng/cli/options.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"

namespace dpdrng::cli {
namespace cmd_bilayer {
namespace {

void write_series(const std::filesystem::path& dir, const dpd::BilayerResult& r) {
  const auto& p = r.profile;
  write_csv(dir / "profile.csv", {"z", "head", "tail", "water"}, {&p.z, &p.head, &p.tail, &p.water});
  const auto& s = r.series;
  std::vector<double> step(s.step.begin(), s.step.end()), out(s.lipids_out.begin(), s.lipids_out.end());
  write_csv(dir / "series.csv", {"step", "temperature", "pxx", "pyy", "pzz", "tension", "tail_order", "lipids_out"},
                        {&step, &s.temperature, &s.pxx, &s.pyy, &s.pzz, &s.tension, &s.tail_order, &out});
  std::vector<double> bond;
  for (std::size_t k = 0; k < r.order_by_bond.size(); ++k) bond.push_back(double(k + 1));
  write_csv(dir / "order.csv", {"tail_bond", "p2"}, {&bond, &r.order_by_bond});
}

void print_human(const dpd::BilayerResult& r) {
  // A run that blew up has no observables: "n/a", never a number.
  auto pm = [na = dpd::blew_up(r.status)](const dpd::Stat& s) {
    if (na) return std::string("n/a");
    std::ostringstream o;
    o << std::setprecision(6) << s.mean << " ± " << std::setprecision(2) << s.sem;
    return o.str();
  };
  std::cout << "scene bilayer: " << r.lipids << " H3(T6)2 lipids, " << r.particles << " beads, box " << r.box[0]
            << " x " << r.box[1] << " x " << r.box[2] << ", pairs " << r.pairs << ", " << r.generator << " / "
            << r.seeding << " / " << r.distribution << " / feed " << r.feed << "\n"
            << "status                 " << r.status << " (" << r.steps_done << " steps)\n"
            << "temperature k_BT       " << pm(r.temperature) << "\n"
            << "pressure xx, yy, zz    " << pm(r.pressure_diag[0]) << ", " << pm(r.pressure_diag[1]) << ", "
            << pm(r.pressure_diag[2]) << "\n"
            << "tension Lz[Pzz-(Pxx+Pyy)/2] " << pm(r.tension) << " (conservative virial only: "
            << pm(r.tension_conservative) << ")\n"
            << "  without bond virial  " << pm(r.tension_without_bond_virial) << "\n"
            << "  without bend virial  " << pm(r.tension_without_bend_virial) << "\n"
            << "thickness (H peaks)    " << pm(r.thickness) << "   head separation " << pm(r.head_separation) << "\n"
            << "tail order P2          " << pm(r.tail_order) << " (T-T bonds against z)   nematic S "
            << pm(r.nematic_order) << " (lipid axes)\n"
            << "lipids out (max)       " << r.lipids_out_max << "\n"
            << "momentum drift / bead  " << r.momentum_drift << "\n"
            << "time                   " << r.timings.total_s << " s (" << 1e3 * r.timings.per_step_s
            << " ms/step, bonded " << r.bonded_s << " s), " << r.timings.threads << " thread(s)\n"
            << "random numbers         " << r.timings.random_numbers << ", " << r.timings.ns_per_number
            << " ns each (estimated share of force time " << 100 * r.timings.rng_share_estimate << " %)\n";
}

struct BilayerArgs {
  dpd::BilayerConfig cfg;
  RunOptions run{"cells"};
};

const bool registered = register_command(41, [](CLI::App& root) {
  auto a = std::make_shared<BilayerArgs>();
  CLI::App* sub = root.add_subcommand("simulate-bilayer", "run the membrane scene (H3(T6)2 bilayer in water)");
  sub->footer(
      "Grafmueller et al. (2009) lipids: 146 H3(T6)2 in a 10 x 10 x 18 box with water, 5400 beads, gamma 4.5,\n"
      "a_ij HH 30 HT 35 HW 30 TT 10 TW 75 WW 25, bonds 128/0.5, bending 15. dt_warmup for the first --warmup\n"
      "steps, then --dt. Tension = Lz[Pzz - (Pxx+Pyy)/2] (positive = stretched). --series DIR writes\n"
      "profile.csv (H/T/W densities vs z - z_mid), series.csv and order.csv. `dpdrng simulate --scene bilayer`\n"
      "runs the same scene with the common options (and the warm-up clipped to --equilibrate).");
  auto& c = a->cfg;
  add_integer(*sub, "--steps", c.steps, "steps in all (warm-up included)", {1, kInt64Max});
  add_integer(*sub, "--equilibrate", c.equilibrate, "steps not sampled (warm-up included)", {0, kInt64Max});
  add_integer(*sub, "--warmup", c.warmup, "first steps at --dt-warmup", {0, kInt64Max});
  add_real(*sub, "--dt", c.dt, "time step after the warm-up");
  add_real(*sub, "--dt-warmup", c.dt_warmup, "time step of the warm-up");
  add_thermostat_options(*sub, c);
  a->run.add_to(*sub, c,
                {"cells (linked cells, the default) or all", "sampling interval of profiles and order",
                 "directory for profiles and time series (CSV)"});
  sub->callback([a] {
    dpd::BilayerConfig cfg = a->cfg;
    a->run.apply(cfg);
    run_bilayer_scene(cfg, a->run.json, a->run.quiet, a->run.series_dir);
  });
});

}  // namespace
}  // namespace cmd_bilayer

namespace cmd_bilayer {
namespace {
// The document's version, schema and inputs: the membrane scene's physics beside the noise settings.
nlohmann::json stamped(const nlohmann::json& j, const dpd::BilayerConfig& c) {
  return cli::stamped(j, "dpdrng.simulate.bilayer/1", c,
                      {{"box", c.box}, {"lipids_per_leaflet", c.lipids_per_leaflet}, {"particles", c.particles},
                       {"a", c.a}, {"rc", c.rc}, {"kT", c.kT}, {"gamma", c.gamma}, {"lambda", c.lambda},
                       {"dt_warmup", c.dt_warmup}, {"dt", c.dt}, {"warmup", c.warmup}, {"steps", c.steps},
                       {"equilibrate", c.equilibrate}});
}
}  // namespace
}  // namespace cmd_bilayer

void run_bilayer_scene(const dpd::BilayerConfig& in, bool json, bool quiet, const std::string& series_dir) {
  dpd::BilayerConfig cfg = in;
  cfg.series = !series_dir.empty();
  cfg.validate();
  begin_work();
  if (cfg.series) prepare_output_files(series_dir, {"profile.csv", "series.csv", "order.csv"}, "--series");
  dpd::RunHooks hooks;
  if (!quiet && cfg.steps >= 2000)
    hooks.progress = [](std::int64_t step, std::int64_t steps) {
      std::cerr << "\rstep " << step << " / " << steps << std::flush;
      if (step == steps) std::cerr << "\n";
    };
  const dpd::BilayerResult r = dpd::run_bilayer(cfg, hooks);
  if (!series_dir.empty()) cmd_bilayer::write_series(series_dir, r);
  if (json)
    std::cout << cmd_bilayer::stamped(dpd::to_json(r, false), cfg).dump(2) << "\n";
  else
    cmd_bilayer::print_human(r);
}

void simulate_bilayer(const CLI::App& sub, const dpd::WaterConfig& w, const RunOptions& o) {
  auto given = [&](const char* name) { return sub.count(name) > 0; };
  for (const char* fixed : {"--particles", "--density", "--a", "--rc"})
    if (given(fixed))
      throw InputError(std::string(fixed) + " is fixed by scene bilayer (146 lipids + water, 10 x 10 x 18, rho 3)");
  if (given("--integrator")) throw InputError("--integrator is for scene water (the bilayer integrates with mvv)");
  dpd::BilayerConfig c;
  if (given("--steps")) c.steps = w.steps;
  if (given("--equilibrate")) c.equilibrate = w.equilibrate;
  if (c.equilibrate >= c.steps)
    throw InputError("scene bilayer: --steps " + std::to_string(c.steps) + " leaves no production after --equilibrate " +
                     std::to_string(c.equilibrate) + " (warm-up included); give a smaller --equilibrate");
  c.warmup = std::min<std::int64_t>(c.warmup, c.equilibrate);
  if (given("--dt")) c.dt = w.dt;
  if (given("--lambda")) c.lambda = w.lambda;
  if (given("--gamma")) c.gamma = w.gamma;
  if (given("--kT")) c.kT = w.kT;
  if (given("--seed")) c.seed = w.seed;
  if (given("--init-seed")) c.init_seed = w.init_seed;
  if (given("--sample-every")) c.sample_every = w.sample_every;
  c.threads = w.threads;
  RunOptions scene = o;
  if (!given("--pairs")) scene.pairs = "cells";
  scene.apply(c);
  run_bilayer_scene(c, o.json, o.quiet, o.series_dir);
}

}  // namespace dpdrng::cli
