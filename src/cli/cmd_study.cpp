// dpdrng study run|merge|report|cells|calibrate: thin glue over dpdrng::study.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/calibrate.hpp"
#include "dpdrng/study/measure.hpp"
#include "dpdrng/study/report.hpp"
#include "dpdrng/study/runner.hpp"
#include "dpdrng/study/store.hpp"

namespace dpdrng::cli {
namespace cmd_study {
namespace {
namespace fs = std::filesystem;
using namespace dpdrng::study;

struct RunArgs {
  std::string config, out, shard = "1/1";
  int threads = 0;
};

void run(const RunArgs& a) {
  // Everything that can be wrong with the input is checked before the first byte is written.
  const StudyConfig config = load_config(a.config);
  validate_scene(config);
  study::RunOptions o;
  o.shard = parse_shard(a.shard);
  o.threads = a.threads > 0 ? a.threads : std::max(1u, std::thread::hardware_concurrency());
  o.progress = &std::cerr;
  begin_work();
  Store store(a.out.empty() ? fs::path("results") / config.name : fs::path(a.out));
  prepare_output_directory(store.dir(), "--out");
  store.open_for(config);
  std::cerr << "[study] " << config.name << ": " << select_shard(enumerate_cells(config), o.shard).size()
            << " cells in shard " << o.shard.index << "/" << o.shard.count << ", " << o.threads << " threads, into "
            << store.dir() << "\n";
  const RunSummary s = run_study(config, store, o, measure_cell);
  const std::size_t stored = store.assemble(config);
  std::cerr << "[study] done in " << s.seconds << " s: " << s.computed << " computed, " << s.resumed << " resumed, "
            << s.unstable << " unstable, " << (s.disrupted ? std::to_string(s.disrupted) + " disrupted, " : "")
            << s.failed << " failed; " << store.study_file() << " holds " << stored
            << " of " << enumerate_cells(config).size() << " cells\n";
}

void merge(const std::vector<std::string>& dirs, const std::string& out_dir) {
  if (dirs.empty()) throw InputError("study merge: give at least one study directory");
  begin_work();
  Store first(dirs.front());
  const StudyConfig config = first.stored_config();
  Store out(out_dir.empty() ? fs::path(dirs.front()) : fs::path(out_dir));
  prepare_output_directory(out.dir(), "--out");
  // Checks every source before copying anything, so a wrong directory leaves the output untouched.
  for (const auto& d : dirs) {
    const StudyConfig c = Store(d).stored_config();
    if (c.hash != config.hash)
      throw InputError(d + " was made with a different config (hash " + c.hash + ", " + dirs.front() + ": " +
                       config.hash + ")");
  }
  out.open_for(config);
  std::size_t copied = 0;
  std::vector<UnreadableCell> refused;
  for (const auto& d : dirs)
    if (fs::absolute(d) != fs::absolute(out.dir())) copied += out.merge_from(Store(d), &refused);
  for (const auto& u : refused)
    std::cerr << "[study] warning: " << u.file.string() << " is unreadable (" << u.reason
              << "): not merged; `study run` computes it again\n";
  const std::size_t stored = out.assemble(config);
  std::cerr << "[study] merged " << copied << " cell files into " << out.dir() << "; " << out.study_file() << " holds "
            << stored << " of " << enumerate_cells(config).size() << " cells\n";
}

struct CalibrateArgs {
  std::string config, out, replicas, variance = "0.0025,0.005,0.01,0.02", lag1, mean, aniso, shard = "1/1";
  int null_studies = 100, power_studies = 10, threads = 1;
  double max_minutes = 0;
  bool json = false, no_charts = false, at_size = false;
  bool variance_given = false;  // --at-size runs no defects unless --variance is named (then refused)
};

// "a,b,c" within `range` (the defect's own, so that the flag, not the generator built from it, is blamed); a
// value listed twice is refused, as in every list.
std::vector<double> real_list(const std::string& text, const std::string& what, const RealRange& range) {
  std::vector<double> out;
  if (text.empty()) return out;
  std::string_view rest = text;
  for (;;) {
    const std::size_t comma = rest.find(',');
    const double v = parse_real(rest.substr(0, comma), what, range);
    if (std::find(out.begin(), out.end(), v) != out.end())
      throw InputError(what + ": lists " + exact_decimal(v) + " twice");
    out.push_back(v);
    if (comma == std::string_view::npos) return out;
    rest.remove_prefix(comma + 1);
  }
}

std::string machine_name() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("model name")) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  return "unknown CPU";
}

void calibrate_cmd(const CalibrateArgs& a) {
  const StudyConfig config = load_config(a.config);
  CalibrationPlan plan;
  plan.null_studies = a.null_studies;
  plan.power_studies = a.power_studies;
  if (!a.replicas.empty()) plan.replicas = parse_list<int>(a.replicas, "--replicas", {2, 1000});
  for (std::size_t i = 0; i < plan.replicas.size(); ++i)
    if (std::find(plan.replicas.begin(), plan.replicas.begin() + i, plan.replicas[i]) != plan.replicas.begin() + i)
      throw InputError("--replicas: lists " + std::to_string(plan.replicas[i]) + " twice");
  // The ranges of defect:variance=E,lag1=R,mean=M (rng/defect.hpp).
  plan.at_size = a.at_size;
  if (!a.at_size || a.variance_given) plan.variance = real_list(a.variance, "--variance", {-1.0, 1e6, true, false});
  else plan.variance.clear();
  plan.lag1 = real_list(a.lag1, "--lag1", {-0.5, 0.5, false, false});
  plan.mean = real_list(a.mean, "--mean", {-1e6, 1e6, false, false});
  plan.aniso = real_list(a.aniso, "--aniso", {-0.5, 1.0, true, true});
  plan.shard = parse_shard(a.shard);
  plan.max_seconds = 60 * a.max_minutes;
  // Every input checked before anything is written.
  const StudyConfig pool = plan.at_size ? at_size_pool(config, plan) : calibration_pool(config, plan);
  validate_scene(pool);
  begin_work();
  const fs::path out(a.out);
  prepare_output_directory(out, "--out");
  Store store(out / "pool");
  Calibration c = calibrate(config, plan, store, measure_cell, a.threads, &std::cerr);
  if (c.missing > 0) {
    std::cerr << "[calibrate] shard " << plan.shard.index << "/" << plan.shard.count << " stopped; " << c.missing
              << " cells not stored yet (other shards', or left by --max-minutes): run the same command again, and "
                 "any other shards, into the same --out to finish\n";
    if (c.nulls.empty()) return;
    std::cerr << "[calibrate] summary of the " << c.nulls.front().studies.trials << " of " << c.null_studies_planned
              << " null studies recorded so far\n";
  }
  c.machine = machine_name() + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
  write_calibration(c, out, !a.no_charts, &std::cerr);
  if (a.json)
    std::cout << to_json(c).dump(2) << "\n";
  else
    std::cout << (out / "summary.md").string() << "\n";
}

void report(const std::string& dir, bool charts, const std::string& calibration) {
  begin_work();
  Store store(dir);
  const StudyConfig config = store.stored_config();
  prepare_output_directory(store.dir() / "report", "study report: the report directory");
  if (fs::exists(store.dir() / "cells")) store.assemble(config);
  ReportOptions o;
  o.charts = charts;
  o.calibration = calibration;
  o.log = &std::cerr;
  std::vector<UnreadableCell> unreadable;
  const auto cells = store.load_all(&unreadable);
  for (const auto& u : unreadable) {
    std::cerr << "[report] warning: " << u.file.string() << " is unreadable (" << u.reason
              << "): left out of the report; `study run` computes it again\n";
    o.unreadable.push_back(u.file.filename().string());
  }
  // A folder without its cells (a clone's committed results keep the report, not the raw store) would get an
  // empty report written over the one it has.
  if (cells.empty() && unreadable.empty())
    throw InputError("study report " + dir + ": no cells to report (neither study.h5 nor cells/ holds any); " +
                     "`dpdrng study run` computes them. Nothing was written.");
  const fs::path md = write_report(config, cells, store.dir(), o);
  std::cout << md.string() << "\n";
}

// A config that names a plug-in loads native code: the command line may allow a library the config does not pin.
void add_allow_plugin(CLI::App& app) {
  app.add_option("--allow-plugin")
      ->description("let the config load this plug-in library (ext:PATH) without a sha256 pin; repeatable")
      ->type_name("PATH")
      ->each([](const std::string& path) { allow_plugin(path); });
}

const bool registered = register_command(60, [](CLI::App& root) {
  CLI::App& g = group(root, "study", "run a sweep of DPD runs and tests, merge shards, and report");
  g.footer("A study: generators x rounds x distributions x seedings x replicas (x dt), each cell one DPD run with\n"
           "its chi2 / lag-1 t / NIST tests and observables, compared with MT19937; [scene] name = \"bilayer\"\n"
           "sweeps the membrane scene (physics only). See study/README.md.");

  auto ra = std::make_shared<RunArgs>();
  CLI::App* r = g.add_subcommand("run", "run the cells of a study config (resumes: finished cells are kept)");
  r->add_option("config", ra->config, "study config (TOML), e.g. study/okada2021.toml")->required();
  r->add_option("--out,-o", ra->out, "results directory (default results/<study name>)")->check(non_empty_path());
  r->add_option("--shard", ra->shard, "run only shard k of N (1-based, round-robin over the cells), e.g. 3/16")
      ->capture_default_str();
  add_integer(*r, "--threads,-t", ra->threads, "cells run side by side (0 = all cores)", {0, 1024});
  add_allow_plugin(*r);
  r->callback([ra] { run(*ra); });

  auto dirs = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  CLI::App* m = g.add_subcommand("merge", "combine the cells of several result directories (shards) into one");
  m->add_option("dirs", *dirs, "result directories made with the same config")->required();
  m->add_option("--out,-o", *out, "target directory (default: the first one)")->check(non_empty_path());
  add_allow_plugin(*m);
  m->callback([dirs, out] { merge(*dirs, *out); });

  auto dir = std::make_shared<std::string>();
  auto no_charts = std::make_shared<bool>(false);
  CLI::App* p = g.add_subcommand("report", "write DIR/report/: report.md, CSV tables, SVG/PNG charts");
  p->add_option("dir", *dir, "results directory")->required();
  p->add_flag("--no-charts", *no_charts, "skip gnuplot");
  auto calibration = std::make_shared<std::string>();
  p->add_option("--calibration", *calibration,
                "calibration.json (or a directory of them) for the detection limit; default DIR/../calibration and "
                "DIR/../*/calibration.json")
      ->check(non_empty_path());
  add_allow_plugin(*p);
  p->callback([dir, no_charts, calibration] { report(*dir, !*no_charts, *calibration); });

  auto ca = std::make_shared<CalibrateArgs>();
  CLI::App* k = g.add_subcommand("calibrate", "measure the verdicts' false-alarm rate and their power against injected defects");
  k->footer("Runs null studies (MT19937 against philox4x32(10), threefry2x64(20), splitmix64) and power studies\n"
            "(plus one defect:variance=E / lag1=R / mean=M / aniso=K generator) on the config's scene, tests and error\n"
            "control, one cell at a time; resumes from OUT/pool. Writes OUT/summary.md, calibration.json,\n"
            "false_alarms.csv, power.csv and charts/. A study report reads the detection limit from a\n"
            "calibration.json whose scene and tests match its config. See study/README.md.");
  k->add_option("config", ca->config, "study config (TOML), e.g. study/ci.toml")->required();
  k->add_option("--out,-o", ca->out, "output directory (its pool/ holds the cells)")->required()->check(non_empty_path());
  add_integer(*k, "--null-studies", ca->null_studies, "null studies at the config's replica count", {1, 100000});
  add_integer(*k, "--power-studies", ca->power_studies,
              "power studies per defect size at the largest replica count (more at smaller counts)", {1, 100000});
  k->add_option("--replicas", ca->replicas, "replica counts to calibrate, e.g. 4,8,16 (the config's is always added)");
  CLI::Option* variance =
      k->add_option("--variance", ca->variance, "variance defects ε, comma-separated ('' for none)")->capture_default_str();
  k->add_option("--lag1", ca->lag1, "lag-1 correlation defects ρ (run in pair-step seeding)");
  k->add_option("--mean", ca->mean, "mean-shift defects μ");
  k->add_option("--aniso", ca->aniso, "anisotropic defects κ: ζ's variance × (1 + κ(3cos²θ − 1)), θ the pair's angle to z");
  add_integer(*k, "--threads,-t", ca->threads, "threads inside each cell (cells run one at a time)", {1, 1024});
  k->add_option("--shard", ca->shard,
                "compute only shard k of N of the pool's cells (round-robin), e.g. 1/2: shards share --out, and "
                "the one that finds every cell stored writes the summary")
      ->capture_default_str();
  k->add_flag("--at-size", ca->at_size,
              "null studies at the config's own size: every variant slot (generator x rounds) gets its own good "
              "generator, defect:key=k, so each null study has the config's variants, tests and Holm family; "
              "also reports how often those are shown equivalent per replica count (no defects)");
  add_real(*k, "--max-minutes", ca->max_minutes,
           "start no cell after this many minutes (0: no limit); rerun the same command to go on", {0, 1e6, false, false});
  k->add_flag("--json", ca->json, "print calibration.json on standard output");
  k->add_flag("--no-charts", ca->no_charts, "skip gnuplot");
  add_allow_plugin(*k);
  k->callback([ca, variance] {
    ca->variance_given = variance->count() > 0;
    calibrate_cmd(*ca);
  });

  auto cfg = std::make_shared<std::string>();
  auto shard = std::make_shared<std::string>("1/1");
  CLI::App* c = g.add_subcommand("cells", "list the cell ids of a config (or of one shard) without running them");
  c->add_option("config", *cfg, "study config (TOML)")->required();
  c->add_option("--shard", *shard, "k/N")->capture_default_str();
  add_allow_plugin(*c);
  c->callback([cfg, shard] {
    const StudyConfig config = load_config(*cfg);
    const Shard part = parse_shard(*shard);
    begin_work();
    for (const auto& cell : select_shard(enumerate_cells(config), part))
      std::cout << cell.id() << (cell.nist ? "  [nist]" : "") << "\n";
  });
});

}  // namespace
}  // namespace cmd_study
}  // namespace dpdrng::cli
