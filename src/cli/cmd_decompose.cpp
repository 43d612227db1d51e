// dpdrng decompose: the decomposition check (does a boundary pair get the same ζ from both domains?), one
// configuration or a sweep from a TOML file.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "dpdrng/cli/options.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"

namespace dpdrng::cli {
namespace cmd_decompose {
namespace {

struct DecomposeArgs {
  std::string scene = "water";
  std::string domains = "2";
  std::string seeding = "distance";
  std::string distribution = "gauss", feed = "halves";
  GeneratorOptions gen;
  study::DecompConfig cfg;
  bool no_reference = false, json = false, quiet = false;
  std::string study, out = "results/decomposition", shard = "1/1";
};

void print_boundary(const char* title, const dpd::BoundaryStats& b) {
  const double per = b.evaluations ? 1.0 / b.evaluations : 0;
  std::cout << title << "\n"
            << "  boundary pairs / step     " << b.boundary * per << " (" << b.shifted * per
            << " through a periodic ghost)\n"
            << "  separations differ        " << b.separation_mismatch * per << " / step\n"
            << "  zeta differ               " << b.zeta_mismatch * per << " / step (+ " << b.range_mismatch * per
            << " seen in range by one side only): " << 100 * b.mismatch_fraction() << " % of boundary pairs\n"
            << "  |zeta_A - zeta_B|         mean " << b.zeta_diff_mean() << ", rms " << b.zeta_diff_rms() << ", max "
            << b.zeta_diff_max << "\n"
            << "  |F_A + F_B| max           " << b.force_mismatch_max << "\n"
            << "  |sum F| / bead            rms " << b.net_force_rms() << ", max " << b.net_force_max << "\n";
  if (b.grid_straddle_expected > 0) std::cout << "  grid straddles expected   " << b.grid_straddle_expected << "\n";
}

void print_run(const char* title, const study::DecompRun& r) {
  std::cout << title << ": " << r.status << " (" << r.steps_done << " steps, " << r.seconds << " s)\n"
            << "  k_BT                      " << r.temperature.mean << " ± " << r.temperature.sem << "\n"
            << "  pressure                  " << r.pressure.mean << " ± " << r.pressure.sem << "\n"
            << "  diffusion coefficient     " << r.diffusion << " ± " << r.diffusion_sem << "\n"
            << "  momentum drift / bead     " << r.momentum_drift << " (max), " << r.momentum_final << " (end)\n"
            << "  centre-of-mass share of the kinetic energy " << r.com_kinetic_share << "\n";
}

void print_human(const study::DecompResult& r) {
  std::cout << "decomposition check: water, " << r.particles << " beads, box " << r.box_length << ", domains "
            << r.domains << ", " << r.generator << " / " << r.seeding << " / " << r.distribution << " / feed " << r.feed << "\n";
  print_boundary("first force evaluation (initial configuration)", r.snapshot);
  print_boundary("whole decomposed run", r.decomposed.boundary);
  print_run("decomposed run", r.decomposed);
  if (!r.has_reference) return;
  print_run("undecomposed run", r.reference);
  const auto& c = r.randomness;
  std::ostringstream chi2, lag1, cross;
  if (c.chi2_tests == 0)
    chi2 << "not applicable: no step sampled (--chi2-every 0 or too few production steps)";
  else
    chi2 << c.chi2_pass << " / " << c.chi2_tests << " pass, min p " << c.chi2_min_p;
  if (c.lag1_tests == 0)
    lag1 << "not applicable: no pair series tested (--ttest-pairs 0 or too few production steps)";
  else
    lag1 << c.lag1_pass << " / " << c.lag1_tests << " pass, max |r| " << c.lag1_max_abs_r;
  if (!std::isfinite(c.cross_pair_r))
    cross << "not applicable: no step sampled";
  else
    cross << "r = " << c.cross_pair_r << ", p = " << c.cross_pair_p << " (" << c.cross_pair_verdict << ")";
  std::cout << "randomness of the seeding (undecomposed run, word 0)\n"
            << "  chi2 (one step, all pairs) " << chi2.str() << "\n"
            << "  lag-1 t-test (pair series) " << lag1.str() << "\n"
            << "  neighbouring pairs         " << cross.str() << "\n"
            << "  pairs sharing a word       " << c.duplicates_per_step << " / step\n";
}

// As `study run`: cells already stored are read back, not recomputed; the outputs are written from the store
// once it holds every cell (the last shard to finish writes them).
void run_study(const DecomposeArgs& a) {
  const study::DecompSweep sw = study::load_decomp_sweep(a.study);
  study::DecompRunOptions o;
  o.shard = study::parse_shard(a.shard);
  o.progress = a.quiet ? nullptr : &std::cerr;
  begin_work();
  const study::CellStore store(a.out);
  prepare_output_directory(store.dir(), "--out");
  study::open_decomp_store(store, sw);
  const std::size_t total = study::decomp_cells(sw).size();
  if (!a.quiet)
    std::cerr << "[decompose] " << sw.name << ": " << total << " cells (" << sw.domains.size()
              << " domain grids each), shard " << o.shard.index << "/" << o.shard.count << ", into " << store.dir()
              << "\n";
  const study::DecompRunSummary s = study::run_decomp_sweep(sw, store, o);
  std::vector<std::string> missing;
  const auto rows = study::load_decomp_rows(sw, store, &missing);
  if (!a.quiet)
    std::cerr << "[decompose] done in " << s.seconds << " s: " << s.computed << " computed, " << s.resumed
              << " resumed; " << total - missing.size() << " of " << total << " cells stored\n";
  if (!missing.empty()) {
    std::cerr << "[decompose] outputs are written once every cell is stored: run the other shards into "
              << store.dir() << "\n";
    return;
  }
  study::assemble_decomp_store(store, sw);
  const std::string md = study::write_decomp_outputs(sw, rows, a.out, a.quiet ? nullptr : &std::cerr);
  if (a.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& r : rows) j.push_back(study::to_json(r));
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << md;
  }
}

void run_decompose(DecomposeArgs& a) {
  if (!a.study.empty()) return run_study(a);
  if (a.shard != "1/1") throw InputError("--shard: only with --study (a single check is one cell)");
  if (a.scene != "water") throw InputError("unknown scene '" + a.scene + "' (known: water)");
  study::DecompConfig cfg = a.cfg;
  cfg.domains = dpd::parse_domains(a.domains);
  cfg.noise.generator = a.gen.spec();
  cfg.noise.seeding = dpd::parse_decomp_seeding(a.seeding);
  cfg.noise.distribution = rng::parse_distribution(a.distribution);
  cfg.noise.feed = rng::parse_feed(a.feed);
  cfg.reference = !a.no_reference;
  cfg.validate();
  begin_work();
  const study::DecompResult r = study::run_decomposition(cfg);
  if (a.json)
    std::cout << study::to_json(r).dump(2) << "\n";
  else
    print_human(r);
}

const bool registered = register_command(45, [](CLI::App& root) {
  auto a = std::make_shared<DecomposeArgs>();
  a->cfg.water.steps = 2000;
  CLI::App* sub = root.add_subcommand(
      "decompose", "domain-decomposition check: do both owners of a boundary pair draw the same random number?");
  sub->footer(
      "Emulates a spatial decomposition in one process: each domain evaluates its beads' pairs with ghost copies\n"
      "shifted by +-L in floating point ((x_j - L) - x_i on one side, x_j - (x_i + L) on the other), every\n"
      "boundary pair on both sides. Seedings: distance (the paper), pair-step, grid[:K] (separation rounded to\n"
      "2^-K, default 32, before hashing), canonical (min-image separation of the wrapped coordinates, which the\n"
      "ghost must carry). Pairs inside r_c only (the ones that exert forces).\n"
      "--study FILE runs a sweep (study/decomposition.toml) into --out as `study run` does: one file per\n"
      "(generator, seeding, distribution) in cells/, written whole or not at all; a rerun reads the stored cells\n"
      "back and computes the rest (an unreadable cell file is named and computed again); --shard k/N runs every\n"
      "N-th cell. Once every cell is stored it writes table.md, table.csv, results.json and charts/ there.");
  auto& c = a->cfg;
  sub->add_option("--scene", a->scene, "scene: water")->capture_default_str();
  sub->add_option("--domains", a->domains, "domains per axis: 2 or 2,2,1")->capture_default_str();
  a->gen.add_to(*sub);
  sub->add_option("--seeding", a->seeding, "distance, pair-step, grid, grid:K, canonical")->capture_default_str();
  sub->add_option("--distribution", a->distribution, "gauss or uniform")->capture_default_str();
  sub->add_option("--feed", a->feed, "uniforms feeding the Gaussian: halves, blocks or inverse")->capture_default_str();
  add_integer(*sub, "--particles,-n", c.water.particles, "number of beads", {2, 20000});
  add_real(*sub, "--density", c.water.density, "bead density rho");
  add_real(*sub, "--dt", c.water.dt, "time step");
  add_integer(*sub, "--steps", c.water.steps, "steps of each run", {1, kInt64Max});
  add_integer(*sub, "--equilibrate", c.water.equilibrate, "steps before sampling", {0, kInt64Max});
  add_integer(*sub, "--seed", c.noise.seed, "pair-step key word");
  add_integer(*sub, "--init-seed", c.water.init_seed, "seed of the initial configuration");
  add_integer(*sub, "--chi2-every", c.chi2_every, "chi2 on all pairs every k-th production step (0 = off)",
              {0, kIntMax});
  add_integer(*sub, "--ttest-pairs", c.ttest_pairs, "pairs (i,i+1) whose series get the lag-1 t-test",
              {0, kIntMax});
  sub->add_flag("--no-reference", a->no_reference, "skip the undecomposed run (and the randomness tests)");
  sub->add_option("--study", a->study, "sweep config (TOML), e.g. study/decomposition.toml")->check(non_empty_path());
  sub->add_option("--out", a->out, "output directory of --study (its store: rerun to resume)")
      ->check(non_empty_path())
      ->capture_default_str();
  sub->add_option("--shard", a->shard, "k/N: run only every N-th cell of --study, starting at the k-th")
      ->capture_default_str();
  sub->add_flag("--json", a->json, "machine-readable output");
  sub->add_flag("--quiet,-q", a->quiet, "no progress on stderr");
  sub->callback([a] { run_decompose(*a); });
});

}  // namespace
}  // namespace cmd_decompose
}  // namespace dpdrng::cli
