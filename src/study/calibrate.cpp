#include "dpdrng/study/calibrate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <ostream>
#include <set>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/stats/binomial.hpp"
#include "dpdrng/study/analysis.hpp"
#include "dpdrng/study/observables.hpp"
#include "calibrate_common.hpp"

namespace dpdrng::study {
namespace calibration_detail {

std::vector<int> replica_counts(const StudyConfig& config, const CalibrationPlan& plan) {
  std::set<int> r(plan.replicas.begin(), plan.replicas.end());
  r.insert(config.replicas);
  return {r.begin(), r.end()};
}

Analysis analyse_block(const StudyConfig& study, const std::vector<const CellResult*>& cells) {
  std::vector<CellResult> copy;
  copy.reserve(cells.size());
  for (const auto* c : cells) copy.push_back(*c);
  return analyse(study, copy);
}

bool says_differs(const VariantReport& v, double alpha) { return v.cells.size() > 0 && v.min_p < alpha; }

// The raw P-value of every test of a variant that has one (observables, pass fractions, ζ correlations, ⟨ζ²⟩ = 1).
void append_p_values(const VariantReport& v, std::vector<double>& out) {
  for (const auto& o : v.observables)
    if (o.decision.tested()) out.push_back(o.decision.p);
  for (const auto& p : v.passes)
    if (p.decision.tested()) out.push_back(p.decision.p);
  for (const auto& c : v.correlations)
    if (c.decision.tested()) out.push_back(c.decision.p);
  if (v.zeta_decision.tested()) out.push_back(v.zeta_decision.p);
}

std::string duration(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buf;
}

}  // namespace calibration_detail

namespace {
using namespace calibration_detail;

// Generators the study calls good: 10 and 20 rounds are Random123's defaults, with margin over the rounds that
// pass BigCrush (Salmon et al. SC'11); SplitMix64 passes BigCrush (Steele et al. 2014).
const std::vector<GeneratorEntry> kGood = {{"philox4x32", {10}, {}, {}}, {"threefry2x64", {20}, {}, {}}, {"splitmix64", {1}, {}, {}}};

struct Defect {
  std::string kind;
  double size;
  // Exact: two sizes that differ in any bit are two generators (and two cell ids).
  std::string name() const { return "defect:" + kind + "=" + exact_decimal(size); }
};

std::vector<Defect> defects_of(const CalibrationPlan& plan) {
  std::vector<Defect> d;
  for (double e : plan.variance) d.push_back({"variance", e});
  for (double r : plan.lag1) d.push_back({"lag1", r});
  for (double m : plan.mean) d.push_back({"mean", m});
  for (double k : plan.aniso) d.push_back({"aniso", k});
  return d;
}

bool is_good(const std::string& g) {
  return std::any_of(kGood.begin(), kGood.end(), [&](const GeneratorEntry& e) { return e.name == g; });
}


// The cells of pool replicas [first, first + count) with these generators.
std::vector<const CellResult*> block(const std::vector<CellResult>& cells, int first, int count,
                                     const std::set<std::string>& generators) {
  std::vector<const CellResult*> out;
  for (const auto& c : cells)
    if (c.cell.replica >= first && c.cell.replica < first + count &&
        (c.cell.reference || generators.count(c.cell.generator)))
      out.push_back(&c);
  return out;
}

StudyConfig sub_study(const StudyConfig& pool, int replicas, const std::vector<GeneratorEntry>& generators) {
  StudyConfig s = pool;
  s.replicas = replicas;
  s.reference_replicas = 0;  // a null study's block holds as many reference replicas as variant ones
  s.generators = generators;
  return s;
}




NullRow null_row(const StudyConfig& pool, const std::vector<CellResult>& cells, int replicas, int studies) {
  const StudyConfig study = sub_study(pool, replicas, kGood);
  std::set<std::string> good;
  for (const auto& g : kGood) good.insert(g.name);
  std::size_t alarms = 0, verdicts = 0, alarmed_studies = 0;
  std::vector<double> p_values;
  for (int s = 0; s < studies; ++s) {
    const Analysis a = analyse_block(study, block(cells, s * replicas, replicas, good));
    bool any = false;
    for (const auto& v : a.variants) {
      const bool d = says_differs(v, a.alpha);
      any = any || d;
      if (v.key.reference || !v.no_reference.empty() || v.cells.empty()) continue;
      ++verdicts;
      alarms += d;
      append_p_values(v, p_values);
    }
    alarmed_studies += any;
  }
  return {replicas, make_rate(alarms, verdicts), make_rate(alarmed_studies, std::size_t(studies)), p_values, 0};
}

double temperature_error(const std::vector<CellResult>& cells, const std::string& generator) {
  std::map<int, double> ref;
  for (const auto& c : cells)
    if (c.cell.reference && c.status == CellStatus::ok) ref[c.cell.replica] = c.scalar(kinetic_temperature().key, NAN);
  double s = 0;
  std::size_t n = 0;
  for (const auto& c : cells) {
    if (c.cell.generator != generator || c.status != CellStatus::ok || !ref.count(c.cell.replica)) continue;
    const double t = c.scalar(kinetic_temperature().key, NAN), r = ref[c.cell.replica];
    if (std::isfinite(t) && std::isfinite(r) && r != 0) s += (t - r) / r, ++n;
  }
  return n ? s / double(n) : NAN;
}

PowerRow power_row(const StudyConfig& pool, const std::vector<CellResult>& cells, const Defect& d, int replicas,
                   int studies) {
  std::vector<GeneratorEntry> gens = kGood;
  for (const auto& g : pool.generators)
    if (g.name == d.name()) gens.push_back(g);
  const StudyConfig study = sub_study(pool, replicas, gens);
  std::set<std::string> names;
  for (const auto& g : gens) names.insert(g.name);
  std::size_t hits = 0;
  for (int s = 0; s < studies; ++s) {
    const Analysis a = analyse_block(study, block(cells, s * replicas, replicas, names));
    for (const auto& v : a.variants)
      if (v.key.generator == d.name()) hits += says_differs(v, a.alpha);
  }
  PowerRow row{d.kind, d.size, replicas, make_rate(hits, std::size_t(studies)), temperature_error(cells, d.name())};
  return row;
}

std::vector<Threshold> thresholds(const std::vector<PowerRow>& rows) {
  std::map<std::pair<std::string, int>, std::vector<const PowerRow*>> curves;
  for (const auto& r : rows)
    if (r.detected.trials > 0) curves[{r.kind, r.replicas}].push_back(&r);
  std::vector<Threshold> out;
  for (auto& [key, pts] : curves) {
    // Sizes by magnitude: a negative ε or μ is as much a defect as a positive one.
    std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return std::abs(a->size) < std::abs(b->size); });
    for (double target : {0.5, 0.9}) {
      Threshold t{key.first, key.second, target, NAN, false, false};
      if (pts.front()->detected.rate >= target) {
        t.below = true, t.size = pts.front()->size;
      } else {
        t.above = true;
        for (std::size_t k = 1; k < pts.size(); ++k)
          if (pts[k]->detected.rate >= target) {
            const double x0 = pts[k - 1]->size, x1 = pts[k]->size;
            const double y0 = pts[k - 1]->detected.rate, y1 = pts[k]->detected.rate;
            t.size = x0 + (x1 - x0) * (target - y0) / (y1 - y0);
            t.above = false;
            break;
          }
      }
      out.push_back(t);
    }
  }
  return out;
}


}  // namespace

Rate make_rate(std::size_t events, std::size_t trials) {
  Rate r;
  r.events = events, r.trials = trials;
  r.rate = trials ? double(events) / double(trials) : NAN;
  const auto [lo, hi] = stats::clopper_pearson(events, trials, 0.95);
  r.low = lo, r.high = hi;
  return r;
}

nlohmann::json calibration_key(const StudyConfig& config) {
  const nlohmann::json c = config.canonical();
  nlohmann::json scene = c["scene"];
  scene["dt"] = config.scene.dt.front();
  return {{"scene", scene},
          {"distribution", rng::to_string(config.distributions.front())},
          {"seeding", rng::to_string(config.seedings.front())},
          {"alpha", config.tests.alpha},
          {"error_control", to_string(config.tests.error_control)},
          {"chi2_steps", config.tests.chi2_steps},
          {"ttest_pairs", config.tests.ttest_pairs}};
}

int defect_replicas(const StudyConfig& config, const CalibrationPlan& plan) {
  if (defects_of(plan).empty()) return 0;
  return plan.power_studies * replica_counts(config, plan).back();
}

StudyConfig calibration_pool(const StudyConfig& config, const CalibrationPlan& plan) {
  if (config.scene.is_bilayer()) throw InputError("study calibrate: the membrane scene is not supported (water only)");
  if (plan.null_studies < 1) throw InputError("--null-studies: at least 1");
  if (plan.power_studies < 1) throw InputError("--power-studies: at least 1");
  for (int r : plan.replicas)
    if (r < 2) throw InputError("--replicas: each at least 2 (a t-test needs a spread)");
  StudyConfig p = config;
  p.name = config.name + "-calibration";
  p.distributions = {config.distributions.front()};
  p.seedings = {config.seedings.front()};
  p.feeds = {config.feeds.front()};  // good generators do not depend on the feed; more feeds only multiply cells
  p.scene.dt = {config.scene.dt.front()};
  p.tests.nist_generators.clear();
  p.generators = kGood;
  p.reference_replicas = 0;  // the pool's replicas serve the reference and the generators alike
  for (const auto& d : defects_of(plan)) {
    GeneratorEntry e{d.name(), {1}, {}, {}};
    rng::validated({e.name, 0});  // InputError for an out-of-range size
    if (d.kind == "lag1") e.seedings = {rng::Seeding::pair_step};  // the step must be in the hash input
    if (d.kind == "aniso") e.seedings = {rng::Seeding::distance};  // the separation must be
    p.generators.push_back(e);
  }
  p.replicas = std::max(plan.null_studies * config.replicas, defect_replicas(config, plan));
  p.replicas = std::max(p.replicas, replica_counts(config, plan).back());
  p.source_text = "# The calibration pool of study '" + config.name +
                  "' (dpdrng study calibrate); its canonical form:\n# " + p.canonical().dump() + "\n";
  p.hash = fnv1a64_hex(p.canonical().dump());
  return p;
}

namespace calibration_detail {

std::size_t compute_cells(const std::vector<Cell>& todo, const StudyConfig& pool, const MeasureFn& measure,
                          int threads, Store& store, std::ostream* progress,
                          const std::function<void(const Cell&)>& saved, double max_seconds) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  double busy = 0;
  for (std::size_t k = 0; k < todo.size(); ++k) {
    const auto c0 = clock::now();
    if (max_seconds > 0 && k > 0 && std::chrono::duration<double>(c0 - start).count() >= max_seconds) {
      if (progress)
        *progress << "[calibrate] time limit reached after " << k << " cells; " << todo.size() - k
                  << " left: rerun the same command to go on\n";
      return k;
    }
    CellResult r;
    try {
      r = measure(todo[k], pool, threads);
    } catch (const std::exception& e) {
      r = CellResult{};
      r.status = CellStatus::failed;
      r.reason = e.what();
    }
    r.cell = todo[k];
    r.seconds = std::chrono::duration<double>(clock::now() - c0).count();
    store.save(r);
    busy += r.seconds;
    if (progress) {
      char line[256];
      std::snprintf(line, sizeof line, "[calibrate] %zu/%zu  %-28s rep%03d %5.1fs %s  ETA %s\n", k + 1, todo.size(),
                    todo[k].label().c_str(), todo[k].replica, r.seconds, std::string(to_string(r.status)).c_str(),
                    duration(busy / double(k + 1) * double(todo.size() - k - 1)).c_str());
      *progress << line << std::flush;
    }
    if (saved) saved(todo[k]);
  }
  return todo.size();
}

std::vector<Cell> shard_todo(const std::vector<Cell>& cells, Shard shard, const Store& store, Calibration& out) {
  std::vector<Cell> todo;
  for (const auto& c : select_shard(cells, shard)) {
    if (store.has(c))
      ++out.resumed;
    else
      todo.push_back(c);
  }
  return todo;
}

std::vector<CellResult> load_cells(const Store& store) {
  std::vector<UnreadableCell> unreadable;
  std::vector<CellResult> cells = store.load_all(&unreadable);
  if (!unreadable.empty())
    throw OutputError(unreadable.front().file.string() + " is unreadable (" + unreadable.front().reason +
                      "): delete it and run calibrate again");
  return cells;
}

void describe(Calibration& out, const StudyConfig& config, const StudyConfig& pool) {
  out.config_name = config.name;
  out.scene = calibration_key(config);
  out.alpha = config.tests.alpha;
  out.error_control = to_string(config.tests.error_control);
  out.steps = config.scene.steps;
  out.production = config.scene.steps - config.scene.equilibrate;
  out.config_replicas = config.replicas;
  out.pool_replicas = pool.replicas;
}

void add_wall_time(Calibration& out, const Store& store, double seconds) {
  out.seconds = seconds;
  const std::filesystem::path wall = store.dir() / "wall_seconds";
  double before = 0;
  if (std::ifstream in(wall); in) in >> before;
  out.wall_total = before + out.seconds;
  write_file_atomically(wall, std::to_string(out.wall_total) + "\n");
}

}  // namespace calibration_detail

Calibration calibrate(const StudyConfig& config, const CalibrationPlan& plan, Store& store, const MeasureFn& measure,
                      int threads, std::ostream* progress) {
  if (plan.at_size) return calibrate_at_size(config, plan, store, measure, threads, progress);
  const auto t0 = std::chrono::steady_clock::now();
  const StudyConfig pool = calibration_pool(config, plan);
  const int q = defect_replicas(config, plan);
  store.open_for(pool);
  std::vector<Cell> all;
  for (const auto& c : enumerate_cells(pool))
    if (c.reference || is_good(c.generator) || c.replica < q) all.push_back(c);
  Calibration out;
  const std::vector<Cell> todo = shard_todo(all, plan.shard, store, out);
  out.cells = all.size();
  if (progress)
    *progress << "[calibrate] " << config.name << ": " << all.size() << " cells (" << pool.replicas
              << " pool replicas, defects on the first " << q << "), shard " << plan.shard.index << "/"
              << plan.shard.count << ": " << out.resumed << " stored, " << todo.size() << " to compute, into "
              << store.dir().string() << "\n";
  out.computed = compute_cells(todo, pool, measure, threads, store, progress, nullptr, plan.max_seconds);

  for (const auto& c : all) out.missing += !store.has(c);
  if (out.missing > 0) return out;
  const std::vector<CellResult> cells = load_cells(store);
  for (const auto& c : cells) {
    out.cell_seconds += c.seconds;
    out.failed += c.status == CellStatus::failed;
  }
  describe(out, config, pool);
  out.defect_replicas = q;
  for (int r : replica_counts(config, plan)) out.nulls.push_back(null_row(pool, cells, r, pool.replicas / r));
  for (const auto& d : defects_of(plan))
    for (int r : replica_counts(config, plan))
      if (q / r > 0) out.power.push_back(power_row(pool, cells, d, r, q / r));
  out.thresholds = thresholds(out.power);
  add_wall_time(out, store, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return out;
}

}  // namespace dpdrng::study
