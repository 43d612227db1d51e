// dpdrng study run|merge|report|cells: thin glue over dpdrng::study.
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/measure.hpp"
#include "dpdrng/study/report.hpp"
#include "dpdrng/study/runner.hpp"
#include "dpdrng/study/store.hpp"

namespace dpdrng::cli {
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
  for (const auto& d : dirs)
    if (fs::absolute(d) != fs::absolute(out.dir())) copied += out.merge_from(Store(d));
  const std::size_t stored = out.assemble(config);
  std::cerr << "[study] merged " << copied << " cell files into " << out.dir() << "; " << out.study_file() << " holds "
            << stored << " of " << enumerate_cells(config).size() << " cells\n";
}

void report(const std::string& dir, bool charts) {
  Store store(dir);
  const StudyConfig config = store.stored_config();
  prepare_output_directory(store.dir() / "report", "study report: the report directory");
  if (fs::exists(store.dir() / "cells")) store.assemble(config);
  ReportOptions o;
  o.charts = charts;
  o.log = &std::cerr;
  std::vector<UnreadableCell> unreadable;
  const auto cells = store.load_all(&unreadable);
  for (const auto& u : unreadable) {
    std::cerr << "[report] warning: " << u.file.string() << " is unreadable (" << u.reason
              << "): left out of the report; `study run` computes it again\n";
    o.unreadable.push_back(u.file.filename().string());
  }
  const fs::path md = write_report(config, cells, store.dir(), o);
  std::cout << md.string() << "\n";
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
  r->callback([ra] { run(*ra); });

  auto dirs = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  CLI::App* m = g.add_subcommand("merge", "combine the cells of several result directories (shards) into one");
  m->add_option("dirs", *dirs, "result directories made with the same config")->required();
  m->add_option("--out,-o", *out, "target directory (default: the first one)")->check(non_empty_path());
  m->callback([dirs, out] { merge(*dirs, *out); });

  auto dir = std::make_shared<std::string>();
  auto no_charts = std::make_shared<bool>(false);
  CLI::App* p = g.add_subcommand("report", "write DIR/report/: report.md, CSV tables, SVG/PNG charts");
  p->add_option("dir", *dir, "results directory")->required();
  p->add_flag("--no-charts", *no_charts, "skip gnuplot");
  p->callback([dir, no_charts] { report(*dir, !*no_charts); });

  auto cfg = std::make_shared<std::string>();
  auto shard = std::make_shared<std::string>("1/1");
  CLI::App* c = g.add_subcommand("cells", "list the cell ids of a config (or of one shard) without running them");
  c->add_option("config", *cfg, "study config (TOML)")->required();
  c->add_option("--shard", *shard, "k/N")->capture_default_str();
  c->callback([cfg, shard] {
    const StudyConfig config = load_config(*cfg);
    for (const auto& cell : select_shard(enumerate_cells(config), parse_shard(*shard)))
      std::cout << cell.id() << (cell.nist ? "  [nist]" : "") << "\n";
  });
});

}  // namespace
}  // namespace dpdrng::cli
