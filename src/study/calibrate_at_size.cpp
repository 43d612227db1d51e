// `study calibrate --at-size`: null studies with the config's own variants, tests and Holm family. Null study s
// (of the config's R variant replicas) is a disjoint block of the pool; once its cells are stored it is analysed
// and its outcome kept as OUT/pool/null-studies/study-NNN.json, a few kB, so that a calibration too long for one
// sitting can be carried over in those files alone: a study with a record is never computed again.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>

#include "calibrate_common.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/stats/equivalence.hpp"
#include "dpdrng/study/store.hpp"

namespace dpdrng::study {
namespace calibration_detail {
namespace {

// Where each pool cell belongs: variant and paired reference replicas [sR, sR + R) to null study s, extra
// reference replicas (numbered from S·R) R_ref − R to a study.
struct Layout {
  int r = 0, r_ref = 0, extra0 = 0, studies = 0;
  int study_of(const Cell& c) const {
    if (c.reference && c.replica >= extra0) return (c.replica - extra0) / (r_ref - r);
    return c.replica / r;
  }
};

// What one null study says: enough to add null studies up without their cells.
struct NullStudy {
  int study = 0;
  bool alarmed = false;  // any "differs", the reference's own tests included
  std::size_t alarms = 0, verdicts = 0, tests = 0;
  std::vector<double> p_values;
  struct Equivalence {
    std::string observable;
    double margin = 0;
    std::size_t passes = 0, tests = 0;
  };
  std::vector<Equivalence> equivalence;
  // Per scalar observable, the normal score of each variant's shift against the reference: N(0, 1) when the
  // error model is right. Empty in records written before they were kept.
  std::map<std::string, std::vector<double>> scores;
  std::size_t failed = 0;
  double cell_seconds = 0;
};

nlohmann::json to_json(const NullStudy& n) {
  nlohmann::json eq = nlohmann::json::array();
  for (const auto& e : n.equivalence)
    eq.push_back({{"observable", e.observable}, {"margin", e.margin}, {"passes", e.passes}, {"tests", e.tests}});
  return {{"study", n.study},         {"alarmed", n.alarmed},   {"alarms", n.alarms},
          {"verdicts", n.verdicts},   {"tests", n.tests},       {"p_values", n.p_values},
          {"equivalence", eq},        {"scores", n.scores},     {"failed_cells", n.failed},
          {"cell_seconds", n.cell_seconds}};
}

NullStudy null_study_from(const nlohmann::json& j) {
  NullStudy n;
  n.study = j.at("study").get<int>();
  n.alarmed = j.at("alarmed").get<bool>();
  n.alarms = j.at("alarms").get<std::size_t>();
  n.verdicts = j.at("verdicts").get<std::size_t>();
  n.tests = j.at("tests").get<std::size_t>();
  n.p_values = j.at("p_values").get<std::vector<double>>();
  for (const auto& e : j.at("equivalence"))
    n.equivalence.push_back({e.at("observable").get<std::string>(), e.at("margin").get<double>(),
                             e.at("passes").get<std::size_t>(), e.at("tests").get<std::size_t>()});
  if (j.contains("scores")) n.scores = j.at("scores").get<std::map<std::string, std::vector<double>>>();
  n.failed = j.at("failed_cells").get<std::size_t>();
  n.cell_seconds = j.at("cell_seconds").get<double>();
  return n;
}

std::filesystem::path record_path(const Store& store, int s) {
  char name[32];
  std::snprintf(name, sizeof name, "study-%03d.json", s);
  return store.dir() / "null-studies" / name;
}

// The stored record of null study s, if any; OutputError for a damaged one (delete it: its cells are recomputed).
std::optional<NullStudy> load_record(const Store& store, int s) {
  const auto p = record_path(store, s);
  if (!std::filesystem::exists(p)) return std::nullopt;
  try {
    NullStudy n = null_study_from(nlohmann::json::parse(read_whole_file(p)));
    if (n.study != s) throw std::runtime_error("it is the record of null study " + std::to_string(n.study));
    return n;
  } catch (const std::exception& e) {
    throw OutputError(p.string() + " is unreadable (" + e.what() + "): delete it and run calibrate again");
  }
}

NullStudy analyse_null_study(const StudyConfig& pool, const Layout& l, const std::vector<CellResult>& cells, int s) {
  StudyConfig study = pool;
  study.replicas = l.r;
  study.reference_replicas = l.r_ref;
  const Analysis a = analyse(study, cells);
  NullStudy n;
  n.study = s;
  n.tests = a.family_size;
  std::map<std::string, NullStudy::Equivalence> eq;
  for (const auto& v : a.variants) {
    const bool d = says_differs(v, a.alpha);
    n.alarmed = n.alarmed || d;
    if (v.key.reference || !v.no_reference.empty() || v.cells.empty()) continue;
    ++n.verdicts;
    n.alarms += d;
    append_p_values(v, n.p_values);
    for (const auto& o : v.observables) {
      if (o.available && std::isfinite(o.score)) n.scores[o.observable].push_back(o.score);
      if (!o.available || !o.equivalence.tested()) continue;
      auto& e = eq[o.observable];
      e.observable = o.observable, e.margin = o.margin;
      e.passes += o.equivalence.equivalent, ++e.tests;
    }
  }
  for (auto& [name, e] : eq) n.equivalence.push_back(e);
  for (const auto& c : cells) n.failed += c.status == CellStatus::failed, n.cell_seconds += c.seconds;
  return n;
}

// Analyses null study s and stores its record when all its cells are stored (by this or another shard).
std::optional<NullStudy> record_if_complete(const StudyConfig& pool, const Layout& l, Store& store,
                                            const std::vector<Cell>& cells, int s) {
  for (const auto& c : cells)
    if (!store.has(c)) return std::nullopt;
  std::vector<CellResult> loaded;
  loaded.reserve(cells.size());
  for (const auto& c : cells) loaded.push_back(store.load(c));
  // In id order, as `study report` reads a store.
  std::sort(loaded.begin(), loaded.end(),
            [](const CellResult& a, const CellResult& b) { return a.cell.id() < b.cell.id(); });
  NullStudy n = analyse_null_study(pool, l, loaded, s);
  std::filesystem::create_directories(record_path(store, s).parent_path());
  write_file_atomically(record_path(store, s), to_json(n).dump() + "\n");
  return n;
}

void add_up(Calibration& out, const std::vector<NullStudy>& done, const Layout& l) {
  NullRow row;
  row.replicas = l.r;
  std::size_t alarms = 0, verdicts = 0, alarmed = 0;
  std::map<std::string, NullStudy::Equivalence> eq;
  for (const auto& n : done) {
    alarms += n.alarms, verdicts += n.verdicts, alarmed += n.alarmed;
    row.tests_per_study = std::max(row.tests_per_study, n.tests);
    row.p_values.insert(row.p_values.end(), n.p_values.begin(), n.p_values.end());
    for (const auto& e : n.equivalence) {
      auto& sum = eq[e.observable];
      sum.observable = e.observable, sum.margin = e.margin;
      sum.passes += e.passes, sum.tests += e.tests;
    }
    out.failed += n.failed;
    out.cell_seconds += n.cell_seconds;
  }
  row.verdicts = make_rate(alarms, verdicts);
  row.studies = make_rate(alarmed, done.size());
  out.nulls.push_back(std::move(row));
  for (const auto& [name, e] : eq)
    out.equivalence.push_back({l.r, l.r_ref, name, e.margin, make_rate(e.passes, e.tests)});
  std::map<std::string, std::vector<double>> scores;
  for (const auto& n : done) {
    out.scored_studies += !n.scores.empty();
    for (const auto& [name, z] : n.scores) scores[name].insert(scores[name].end(), z.begin(), z.end());
  }
  for (const auto& [name, z] : scores) out.dispersion.push_back({name, stats::score_dispersion(z)});
}

}  // namespace

Calibration calibrate_at_size(const StudyConfig& config, const CalibrationPlan& plan, Store& store,
                              const MeasureFn& measure, int threads, std::ostream* progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const StudyConfig pool = at_size_pool(config, plan);
  store.open_for(pool);
  const Layout l{config.replicas, config.reference_replica_count(), pool.replicas, plan.null_studies};
  std::vector<std::vector<Cell>> by_study(std::size_t(l.studies));
  for (const auto& c : enumerate_cells(pool)) by_study[std::size_t(l.study_of(c))].push_back(c);

  std::vector<std::optional<NullStudy>> records(by_study.size());
  std::vector<Cell> open;  // cells of the null studies without a record, study by study
  for (int s = 0; s < l.studies; ++s) {
    records[std::size_t(s)] = load_record(store, s);
    if (!records[std::size_t(s)])
      open.insert(open.end(), by_study[std::size_t(s)].begin(), by_study[std::size_t(s)].end());
  }
  Calibration out;
  const std::vector<Cell> todo = shard_todo(open, plan.shard, store, out);
  for (const auto& cells : by_study) out.cells += cells.size();
  const auto recorded = std::count_if(records.begin(), records.end(), [](const auto& r) { return r.has_value(); });
  if (progress)
    *progress << "[calibrate] " << config.name << " at size: " << l.studies << " null studies of " << l.r
              << " replicas (" << recorded << " recorded), " << open.size() << " cells open, shard "
              << plan.shard.index << "/" << plan.shard.count << ": " << out.resumed << " stored, " << todo.size()
              << " to compute, into " << store.dir().string() << "\n";
  const auto complete = [&](int s) {
    if (!records[std::size_t(s)])
      records[std::size_t(s)] = record_if_complete(pool, l, store, by_study[std::size_t(s)], s);
  };
  out.computed = compute_cells(todo, pool, measure, threads, store, progress,
                               [&](const Cell& c) { complete(l.study_of(c)); }, plan.max_seconds);
  for (int s = 0; s < l.studies; ++s) complete(s);

  std::vector<NullStudy> done;
  for (int s = 0; s < l.studies; ++s) {
    if (records[std::size_t(s)]) {
      done.push_back(*records[std::size_t(s)]);
      continue;
    }
    for (const auto& c : by_study[std::size_t(s)]) out.missing += !store.has(c);
  }
  describe(out, config, pool);
  out.at_size = true;
  out.reference_replicas = l.r_ref;
  out.null_studies_planned = l.studies;
  if (!done.empty()) add_up(out, done, l);
  add_wall_time(out, store, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return out;
}

}  // namespace calibration_detail

StudyConfig at_size_pool(const StudyConfig& config, const CalibrationPlan& plan) {
  if (config.scene.is_bilayer()) throw InputError("study calibrate: the membrane scene is not supported (water only)");
  if (plan.null_studies < 1) throw InputError("--null-studies: at least 1");
  if (!config.extra_replicas.empty() || !config.integrators.empty() || !config.reference_gammas.empty())
    throw InputError("study calibrate --at-size: configs with extra_replicas, integrators or reference_gammas are "
                     "not supported (their replica blocks differ per Δt or integrator)");
  if (!plan.variance.empty() || !plan.lag1.empty() || !plan.mean.empty() || !plan.aniso.empty())
    throw InputError("study calibrate --at-size: runs null studies only; power against defects is measured at the "
                     "CI scene's size (pass --variance '' and no --lag1, --mean, --aniso)");
  for (int r : plan.replicas)
    if (r != config.replicas)
      throw InputError("study calibrate --at-size: null studies have the config's " + std::to_string(config.replicas) +
                       " replicas (--replicas " + std::to_string(r) + " is for the CI-size calibration)");
  StudyConfig p = config;
  p.name = config.name + "-calibration-at-size";
  p.tests.nist_generators.clear();
  p.generators.clear();
  for (const auto& g : config.generators)
    for (std::size_t k = 0; k < std::max<std::size_t>(g.rounds.size(), 1); ++k)
      p.generators.push_back({"defect:key=" + std::to_string(p.generators.size()), {1}, g.seedings, {}});
  p.replicas = plan.null_studies * config.replicas;
  p.reference_replicas = p.replicas + plan.null_studies * (config.reference_replica_count() - config.replicas);
  p.source_text = "# The at-size calibration pool of study '" + config.name +
                  "' (dpdrng study calibrate --at-size); its canonical form:\n# " + p.canonical().dump() + "\n";
  p.hash = fnv1a64_hex(p.canonical().dump());
  return p;
}

}  // namespace dpdrng::study
