// dpdrng bench dpd: what the pair-noise choice costs a whole DPD run. Particle-steps per second for
// all/cells × generators × rounds, the RNG's share of a step by difference against the same run with ζ = 0
// (no generator, no distribution) and with the seed words passed unhashed (no generator), and the paper's
// headline: the all-pairs 256-bead run with tea32(8) against tea32(1) (Okada et al. 2021: RNG 40 % of the
// time at 8 rounds, 1.5x faster at 1 round). The cells-mode 1- vs 2-thread comparison runs any one integrator;
// a list of integrators times each one's step against GW-MVV's, the runs interleaved. When LAMMPS is built
// (lmp_dpdrng: --lammps, build/lammps/ or PATH), each scene of the table (cells; all pairs, the paper's fluid,
// which LAMMPS runs with its neighbour list) also runs in LAMMPS, with its own pair_style dpd and with pair_style
// dpd/hash, in turn with dpdrng's tea32(1) run, and the table gives each row's speed against LAMMPS's.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/machine.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/stats/summary.hpp"
#include "bench_dpd_lammps.hpp"
#include "dpdrng/version.hpp"

namespace dpdrng::cli {
namespace cmd_bench_dpd {
namespace {

struct BenchDpdArgs {
  std::string generators = "tea32,tea64,philox4x32,threefry2x64,splitmix64,mt19937";
  std::string rounds = "1,8,32";
  std::string pairs = "all,cells";
  std::string distribution = "gauss", feed = "halves";
  std::string integrator = "mvv";
  std::int64_t steps_all = 2000, steps_cells = 100;
  int particles_cells = 24000;
  int threads = 1;
  int repeat = 3;
  bool paper = false, json = false, scaling = true, scaling_only = false, oversubscribe = false;
  std::string lammps;  // lmp_dpdrng's path; empty: looked for
  bool no_lammps = false;
};

struct Case {
  std::string label;
  dpd::WaterConfig cfg;
};

// What a scene's pairs cost: the step's time per pair inside r_c, and how many candidate pairs the search
// computed a separation for per pair it kept (all mode: every pair; cells: the 27-cell stencil's half).
struct PairCost {
  double pairs_per_step = 0;       // pairs inside r_c per force evaluation, the run's mean
  double candidates_per_pair = 0;  // candidates visited per pair kept
  double ns_per_pair = 0;          // median production time per step / pairs_per_step
  // This run's particle-steps/s over LAMMPS's pair_style dpd's on the same scene and CPU; nullopt: not
  // applicable, for the reason in lammps_not_applicable.
  std::optional<double> dpdrng_over_lammps;
  std::string lammps_not_applicable;
};

struct Measured {
  std::string label, pairs;
  std::size_t particles = 0;
  std::int64_t steps = 0;
  int threads = 1;
  double median_s = 0, particle_steps_per_s = 0;
  double pair_steps_per_s = 0;  // pairs inside r_c per step (the run's mean) × steps / median_s
  double share_estimate = 0;
  PairCost cost;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

dpd::WaterConfig scene(const BenchDpdArgs& a, dpd::PairMode mode, std::int64_t steps) {
  dpd::WaterConfig c;
  c.pairs = mode;
  if (mode == dpd::PairMode::cells) {
    // The LAMMPS comparison system: 24 000 beads at ρ = 3, γ = 4.5.
    c.particles = a.particles_cells;
    c.gamma = 4.5;
  }
  // A short untimed start: a random initial configuration is hot for a few dozen steps.
  c.equilibrate = mode == dpd::PairMode::cells ? 50 : 20;
  c.steps = c.equilibrate + steps;
  c.observables = false;
  c.threads = a.threads;
  dpd::set_integrator(c, split(a.integrator).front(), "--integrator");
  c.distribution = rng::parse_distribution(a.distribution);
  c.feed = rng::parse_feed(a.feed);
  rng::check_feed(c.distribution, c.feed);
  return c;
}

void progress(const std::string& what) {
  if (isatty(STDERR_FILENO)) std::cerr << "\r\033[K" << what << std::flush;
}

dpd::Timings run_once(const Case& k) {
  const dpd::RunResult res = dpd::run_water(k.cfg);
  if (!res.ok()) throw std::runtime_error(k.label + ": " + res.status.text());
  return res.timings;
}

using stats::median;

// The pair counts of a run (every force evaluation: the start and each step) against its median time.
PairCost pair_cost(const dpd::Timings& tm, const dpd::WaterConfig& cfg, double median_s) {
  PairCost c;
  const double evaluations = double(cfg.steps + 1), production = double(cfg.steps - cfg.equilibrate);
  c.pairs_per_step = double(tm.pairs_in_range) / evaluations;
  if (tm.pairs_in_range > 0) c.candidates_per_pair = double(tm.pair_candidates) / double(tm.pairs_in_range);
  if (c.pairs_per_step > 0) c.ns_per_pair = 1e9 * median_s / production / c.pairs_per_step;
  return c;
}

Measured summarise(const Case& k, const std::vector<double>& t, double share, double pairs_per_step = 0) {
  Measured m;
  m.label = k.label;
  m.pairs = std::string(dpd::to_string(k.cfg.pairs));
  m.particles = static_cast<std::size_t>(k.cfg.particles);
  m.steps = k.cfg.steps - k.cfg.equilibrate;
  m.threads = dpd::team_threads(k.cfg.threads, m.particles, k.cfg.team_beads);  // what the run used
  m.median_s = median(t);
  m.particle_steps_per_s = double(m.particles) * m.steps / m.median_s;
  m.pair_steps_per_s = pairs_per_step * m.steps / m.median_s;
  m.share_estimate = share;
  return m;
}

Measured measure(const Case& k, int repeat) {
  std::vector<double> t;
  double share = 0;
  dpd::Timings last;
  for (int r = 0; r < repeat; ++r) {
    last = run_once(k);
    t.push_back(last.production_s);
    share = last.rng_share_estimate;
  }
  Measured m = summarise(k, t, share);
  m.cost = pair_cost(last, k.cfg, m.median_s);
  m.pair_steps_per_s = m.cost.pairs_per_step * double(m.steps) / m.median_s;
  return m;
}

// One and two threads run alternately, and the speed-up is the median of the pairs' ratios: on a shared
// machine a burst of other load then spoils one pair, not the whole of one side. Each pair is followed by two
// independent one-thread copies of the run side by side, which share no data and never wait for each other:
// 2 t₁ / (the later copy's time) is what the two cores give two independent runs at that moment. It is a
// reference, not a bound: the copies hold twice the data of one run in the shared cache.
// The share of a run's steps that its team governor ran on one thread.
double one_thread_share(const dpd::Timings& t) {
  std::int64_t all = 0;
  for (const auto& [team, steps] : t.steps_by_team) all += steps;
  const auto one = t.steps_by_team.find(1);
  return all > 0 && one != t.steps_by_team.end() ? double(one->second) / double(all) : 0.0;
}

struct Scaling {
  Measured one, two;
  double speedup = 0, machine = 0;
  std::vector<double> ratios, machine_ratios;
  double one_thread_share = 0;  // median over the two-thread runs of the share of steps run on one thread
};

double side_by_side(const Case& k) {
  double a = 0, b = 0;
  std::exception_ptr failed;
  std::thread other([&] {
    try {
      b = run_once(k).production_s;
    } catch (...) {
      failed = std::current_exception();
    }
  });
  try {
    a = run_once(k).production_s;
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (failed) std::rethrow_exception(failed);
  return std::max(a, b);
}

Scaling measure_scaling(Case k, int repeat) {
  Case k2 = k;
  k.cfg.threads = 1, k2.cfg.threads = 2;
  std::vector<double> t1, t2, shares;
  Scaling out;
  dpd::Timings one;
  for (int r = 0; r < repeat; ++r) {
    progress("bench dpd: cells scaling, pair " + std::to_string(r + 1) + " of " + std::to_string(repeat));
    one = run_once(k);
    t1.push_back(one.production_s);
    const dpd::Timings two = run_once(k2);
    t2.push_back(two.production_s), shares.push_back(one_thread_share(two));
    out.ratios.push_back(t1.back() / t2.back());
    out.machine_ratios.push_back(2 * t1.back() / side_by_side(k));
  }
  const double pairs_per_step = pair_cost(one, k.cfg, 1).pairs_per_step;
  out.one = summarise(k, t1, 0, pairs_per_step), out.two = summarise(k2, t2, 0, pairs_per_step);
  out.one.cost = pair_cost(one, k.cfg, out.one.median_s), out.two.cost = pair_cost(one, k2.cfg, out.two.median_s);
  out.speedup = median(out.ratios), out.machine = median(out.machine_ratios), out.one_thread_share = median(shares);
  return out;
}

// Oversubscription: a busy loop of our own takes one core, as another job on a shared node or a laptop would,
// and one- and two-thread runs alternate beside it. Two threads then share the remaining core time with the
// loop; waits that spin on would burn what the other thread needs, and the two-thread run would take twice the
// one-thread time or more.
class BusyLoop {
 public:
  BusyLoop()
      : thread_([this] {
          double x = 1;
          while (!stop_.load(std::memory_order_relaxed)) {
            for (int i = 0; i < 4096; ++i) x = x * 0.999999 + 1e-7;
            sink_ = x;
          }
        }) {}
  ~BusyLoop() {
    stop_.store(true, std::memory_order_relaxed);
    thread_.join();
  }

 private:
  std::atomic<bool> stop_{false};
  volatile double sink_ = 0;
  std::thread thread_;
};

struct Oversubscribed {
  std::string scene;
  Measured one, two;
  double ratio = 0;  // median over the pairs of t(2 threads) / t(1 thread)
  std::vector<double> ratios;
  double one_thread_share = 0;  // median over the two-thread runs of the share of steps run on one thread
};

Oversubscribed measure_oversubscribed(const std::string& scene, Case k, int repeat) {
  Case k2 = k;
  k.cfg.threads = 1, k2.cfg.threads = 2;
  Oversubscribed out;
  out.scene = scene;
  std::vector<double> t1, t2, shares;
  const BusyLoop busy;
  for (int r = 0; r < repeat; ++r) {
    progress("bench dpd: " + scene + " beside a busy loop, pair " + std::to_string(r + 1) + " of " +
             std::to_string(repeat));
    t1.push_back(run_once(k).production_s);
    const dpd::Timings two = run_once(k2);
    t2.push_back(two.production_s), shares.push_back(one_thread_share(two));
    out.ratios.push_back(t2.back() / t1.back());
  }
  out.one = summarise(k, t1, 0), out.two = summarise(k2, t2, 0);
  out.ratio = median(out.ratios), out.one_thread_share = median(shares);
  return out;
}

Case with_generator(dpd::WaterConfig c, const std::string& name, int rounds) {
  c.generator = rng::validated({name, rounds});
  // A plug-in by its own name: a table row, not a path.
  if (rng::is_plugin(name)) return {"ext:" + rng::load_plugin(name).name, c};
  return {rng::describe(c.generator), c};
}

Case baseline(dpd::WaterConfig c, dpd::NoiseOverride o) {
  c.noise_override = o;
  return {o == dpd::NoiseOverride::none ? "none (zeta = 0)" : "unhashed", c};
}

nlohmann::json to_json(const Measured& m) {
  return {{"case", m.label}, {"pairs", m.pairs}, {"particles", m.particles}, {"steps", m.steps},
          {"threads", m.threads}, {"median_s", m.median_s}, {"particle_steps_per_s", m.particle_steps_per_s},
          {"pair_steps_per_s", m.pair_steps_per_s},
          {"pairs_per_step", m.cost.pairs_per_step}, {"ns_per_pair", m.cost.ns_per_pair},
          {"candidates_per_pair", m.cost.candidates_per_pair},
          {"rng_share_estimate", m.share_estimate},
          {"dpdrng_over_lammps", m.cost.dpdrng_over_lammps ? nlohmann::json(*m.cost.dpdrng_over_lammps) : nullptr},
          {"dpdrng_over_lammps_not_applicable",
           m.cost.dpdrng_over_lammps ? nlohmann::json(nullptr) : nlohmann::json(m.cost.lammps_not_applicable)}};
}

std::vector<Measured> measure_table(const BenchDpdArgs& a) {
  const auto rounds = parse_list<int>(a.rounds, "--rounds", {1, kIntMax});
  std::vector<Measured> table;
  for (const auto& p : split(a.pairs)) {
    const dpd::PairMode mode = dpd::parse_pair_mode(p);
    const dpd::WaterConfig base = scene(a, mode, mode == dpd::PairMode::all ? a.steps_all : a.steps_cells);
    std::vector<Case> cases{baseline(base, dpd::NoiseOverride::none), baseline(base, dpd::NoiseOverride::unhashed)};
    for (const auto& g : split(a.generators)) {
      const auto& info = rng::find_generator(g);
      if (info.max_rounds == 1 || g == "philox4x32" || g == "threefry2x64") {
        cases.push_back(with_generator(base, g, 0));
        continue;
      }
      for (long long r : rounds)
        if (r >= info.min_rounds && r <= info.max_rounds) cases.push_back(with_generator(base, g, int(r)));
    }
    for (const Case& k : cases) {
      progress("bench dpd: " + std::string(dpd::to_string(mode)) + " " + k.label);
      table.push_back(measure(k, a.repeat));
    }
  }
  return table;
}

// The paper's setting: 256 beads, all pairs, tea32(8) vs tea32(1) vs no noise.
struct Paper {
  std::int64_t steps = 0;
  Measured t8, t1, t0;
  double share8() const { return (t8.median_s - t0.median_s) / t8.median_s; }
  double share1() const { return (t1.median_s - t0.median_s) / t1.median_s; }
  double speedup() const { return t8.median_s / t1.median_s; }
  double full_run_s() const { return t1.median_s * 10000.0 / steps; }
};

Paper measure_paper(const BenchDpdArgs& a) {
  Paper p;
  p.steps = a.paper ? 10000 : a.steps_all;
  dpd::WaterConfig pc = scene(a, dpd::PairMode::all, p.steps);
  pc.distribution = rng::Distribution::gauss;
  pc.feed = rng::parse_feed(a.feed);
  progress("bench dpd: paper setting");
  p.t8 = measure(with_generator(pc, "tea32", 8), a.repeat);
  p.t1 = measure(with_generator(pc, "tea32", 1), a.repeat);
  p.t0 = measure(baseline(pc, dpd::NoiseOverride::none), a.repeat);
  return p;
}

void print_table(const BenchDpdArgs& a, const std::vector<Measured>& table) {
  std::cout << "particle-steps/s (median of " << a.repeat << ", " << a.threads << " thread(s), " << a.distribution
            << ", feed " << a.feed << ")\nRNG share by difference: 'vs none' against the table's zeta = 0 run, 'in-run' against zeta = 0\n"
            << "force evaluations alternated with the run's own on its final state (timings.rng_share_estimate)\n";
  std::cout << "ns/pair: the step's time per pair inside r_c; cand/pair: candidate pairs whose separation the search "
               "computed per pair kept\n";
  std::cout << std::left << std::setw(7) << "pairs" << std::setw(9) << "beads" << std::setw(20) << "noise"
            << std::right << std::setw(14) << "p-steps/s" << std::setw(10) << "ns/pair" << std::setw(11)
            << "cand/pair" << std::setw(12) << "vs none" << std::setw(12) << "in-run" << std::setw(11) << "vs LAMMPS"
            << "\n";
  double none_s = 0;
  for (const auto& m : table) {
    if (m.label.rfind("none", 0) == 0) none_s = m.median_s;
    std::cout << std::left << std::setw(7) << m.pairs << std::setw(9) << m.particles << std::setw(20) << m.label
              << std::right << std::setw(14) << std::setprecision(4) << m.particle_steps_per_s << std::fixed
              << std::setprecision(1) << std::setw(10) << m.cost.ns_per_pair << std::setw(11)
              << m.cost.candidates_per_pair << std::setw(11) << 100 * (m.median_s - none_s) / m.median_s << "%"
              << std::setw(11) << 100 * m.share_estimate << "%" << std::setprecision(2) << std::setw(11);
    if (m.cost.dpdrng_over_lammps)
      std::cout << *m.cost.dpdrng_over_lammps;
    else
      std::cout << "n/a";
    std::cout << std::defaultfloat << "\n";
  }
  // Each scene's reason once: the rows of one scene share it.
  std::vector<std::pair<std::string, std::string>> reasons;
  for (const auto& m : table)
    if (!m.cost.dpdrng_over_lammps && std::find(reasons.begin(), reasons.end(), std::pair(m.pairs,
                                                m.cost.lammps_not_applicable)) == reasons.end())
      reasons.emplace_back(m.pairs, m.cost.lammps_not_applicable);
  std::cout << "vs LAMMPS: the row's particle-steps/s over LAMMPS's pair_style dpd's on the same scene (below)";
  for (const auto& [pairs, why] : reasons) std::cout << "; " << pairs << ": not applicable: " << why;
  std::cout << "\n";
}

void print_paper(const BenchDpdArgs& a, const Paper& p) {
  std::cout << std::setprecision(3);
  std::cout << "\npaper setting (256 beads, all pairs, gauss, " << p.steps << " steps):\n"
            << "  tea32(8) " << p.t8.median_s << " s, tea32(1) " << p.t1.median_s << " s, zeta = 0 "
            << p.t0.median_s << " s\n"
            << "  RNG share at 8 rounds " << 100 * p.share8() << " % (paper: 40 %), at 1 round " << 100 * p.share1()
            << " %\n"
            << "  whole-run speed-up 8 -> 1 rounds " << p.speedup() << "x (paper: 1.5x)\n"
            << "  10 000 steps with tea32(1): " << p.full_run_s() << " s" << (a.paper ? "" : " (extrapolated)") << "\n";
}

void print_scaling(const BenchDpdArgs& a, const Scaling& sc) {
  auto range = [](const std::vector<double>& v) {
    std::ostringstream o;
    o << std::setprecision(3) << *std::min_element(v.begin(), v.end()) << "-" << *std::max_element(v.begin(), v.end());
    return o.str();
  };
  std::cout << std::setprecision(3) << "\ncells, " << sc.one.particles << " beads, tea32(1), integrator "
            << a.integrator << ", one and two threads alternately, " << sc.ratios.size() << " pairs: 1 thread "
            << sc.one.particle_steps_per_s << " p-steps/s = " << sc.one.pair_steps_per_s << " pair-steps/s, 2 threads "
            << sc.two.particle_steps_per_s << " p-steps/s = " << sc.two.pair_steps_per_s << " pair-steps/s ("
            << std::fixed << std::setprecision(0) << 100 * sc.one_thread_share << std::defaultfloat
            << std::setprecision(3) << " % of their steps on one thread; medians); " << sc.one.cost.ns_per_pair
            << " ns per pair inside r_c on 1 thread, "
            << sc.two.cost.ns_per_pair << " on 2, " << sc.one.cost.candidates_per_pair
            << " candidates visited per pair kept; speed-up "
            << sc.speedup << "x (median of the pairs' ratios; range " << range(sc.ratios) << ")\n"
            << "two independent one-thread runs side by side after each pair: " << sc.machine
            << "x together (median; range " << range(sc.machine_ratios) << "); the threaded speed-up is "
            << std::fixed << std::setprecision(0) << 100 * sc.speedup / sc.machine << " % of that\n"
            << std::defaultfloat;
}

// The paper's scene twice: as a run does it (under dpd::kTeamBeads, on one thread whatever was asked) and with a
// team forced (team_beads 0), which shows what that rule saves.
std::vector<Oversubscribed> measure_oversubscription(const BenchDpdArgs& a) {
  const Case paper = with_generator(scene(a, dpd::PairMode::all, a.steps_all), "tea32", 1);
  Case forced = paper;
  forced.cfg.team_beads = 0;
  return {measure_oversubscribed("paper (all pairs, 256 beads)", paper, a.repeat),
          measure_oversubscribed("paper, team forced", forced, a.repeat),
          measure_oversubscribed("cells (" + std::to_string(a.particles_cells) + " beads)",
                                 with_generator(scene(a, dpd::PairMode::cells, a.steps_cells), "tea32", 1),
                                 a.repeat)};
}

void print_oversubscription(const std::vector<Oversubscribed>& rows) {
  std::cout << "\nbeside a busy loop on one core, tea32(1), one and two threads alternately (medians; the ratio is "
               "the median of the pairs' t2/t1; a run picks its team from measured step times, so at most 1 wanted):\n";
  for (const auto& o : rows)
    std::cout << std::setprecision(3) << "  " << std::left << std::setw(30) << o.scene << std::right << " 1 thread "
              << o.one.median_s << " s, 2 threads asked (" << o.two.threads << " used) " << o.two.median_s
              << " s, ratio " << o.ratio << " (range "
              << *std::min_element(o.ratios.begin(), o.ratios.end()) << "-"
              << *std::max_element(o.ratios.begin(), o.ratios.end()) << "), "
              << std::fixed << std::setprecision(0) << 100 * o.one_thread_share << std::defaultfloat
              << " % of the two-thread runs' steps on one\n";
}

nlohmann::json to_json(const Oversubscribed& o) {
  return {{"scene", o.scene}, {"one_thread", to_json(o.one)}, {"two_threads", to_json(o.two)},
          {"ratio_2_to_1", o.ratio}, {"pair_ratios", o.ratios}, {"one_thread_step_share", o.one_thread_share}};
}

// Each integrator's production step against GW-MVV's, on each --pairs scene with tea32(1) (pnhln draws no pair
// noise): the integrators run in turn, --repeat rounds, so that a burst of other load spreads over all of them;
// the factor is the ratio of the medians. Jdpd's published factors (its kernel's four schemes) beside them.
struct IntegratorCost {
  std::string integrator, pairs;
  Measured m;
  double factor = 0;  // median step time / GW-MVV's
};

// Jdpd (van den Broek et al., J. Cheminform. 10, 2018): GWMVV 1.0, S1MVV 1.1, SCMVV(1) 1.4, SCMVV(5) 2.3, PNHLN 1.9.
std::optional<double> jdpd_factor(const dpd::WaterConfig& c) {
  switch (c.integrator) {
    case dpd::Integrator::mvv: return 1.0;
    case dpd::Integrator::shardlow: return 1.1;
    case dpd::Integrator::scmvv:
      if (c.scmvv_iterations == 1) return 1.4;
      if (c.scmvv_iterations == 5) return 2.3;
      return std::nullopt;
    case dpd::Integrator::pnhln: return 1.9;
  }
  return std::nullopt;
}

std::vector<std::string> compared_integrators(const BenchDpdArgs& a) {
  std::vector<std::string> names = split(a.integrator);
  dpd::WaterConfig probe;
  for (const auto& n : names) dpd::set_integrator(probe, n, "--integrator");  // InputError for a bad entry
  if (std::find(names.begin(), names.end(), "mvv") == names.end()) names.insert(names.begin(), "mvv");
  return names;
}

std::vector<IntegratorCost> measure_integrators(const BenchDpdArgs& a) {
  std::vector<IntegratorCost> out;
  for (const auto& p : split(a.pairs)) {
    const dpd::PairMode mode = dpd::parse_pair_mode(p);
    std::vector<Case> cases;
    for (const auto& name : compared_integrators(a)) {
      dpd::WaterConfig c = scene(a, mode, mode == dpd::PairMode::all ? a.steps_all : a.steps_cells);
      dpd::set_integrator(c, name, "--integrator");
      Case k = with_generator(c, "tea32", 1);
      k.label = c.integrator_name();
      cases.push_back(k);
    }
    std::vector<std::vector<double>> t(cases.size());
    for (int r = 0; r < a.repeat; ++r)
      for (std::size_t i = 0; i < cases.size(); ++i) {
        progress("bench dpd: " + p + " " + cases[i].label + ", round " + std::to_string(r + 1) + " of " +
                 std::to_string(a.repeat));
        t[i].push_back(run_once(cases[i]).production_s);
      }
    const std::size_t first = out.size();
    for (std::size_t i = 0; i < cases.size(); ++i)
      out.push_back({cases[i].label, p, summarise(cases[i], t[i], 0), 0});
    const auto mvv = std::find_if(out.begin() + first, out.end(), [](const auto& c) { return c.integrator == "mvv"; });
    for (auto it = out.begin() + first; it != out.end(); ++it) it->factor = it->m.median_s / mvv->m.median_s;
  }
  return out;
}

void print_integrators(const BenchDpdArgs& a, const std::vector<IntegratorCost>& rows) {
  std::cout << "cost of a step against GW-MVV (tea32(1), median of " << a.repeat << " interleaved runs, " << a.threads
            << " thread(s)); Jdpd's published factors beside them\n"
            << std::left << std::setw(7) << "pairs" << std::setw(9) << "beads" << std::setw(14) << "integrator"
            << std::right << std::setw(14) << "s/step" << std::setw(10) << "factor" << std::setw(8) << "Jdpd" << "\n";
  for (const auto& c : rows) {
    dpd::WaterConfig probe;
    dpd::set_integrator(probe, c.integrator, "--integrator");
    const auto j = jdpd_factor(probe);
    std::ostringstream jd;
    if (j) jd << *j; else jd << "n/a";
    std::cout << std::left << std::setw(7) << c.pairs << std::setw(9) << c.m.particles << std::setw(14)
              << c.integrator << std::right << std::setw(14) << std::setprecision(4) << c.m.median_s / c.m.steps
              << std::setw(10) << std::setprecision(3) << c.factor << std::setw(8) << jd.str() << "\n";
  }
}

nlohmann::json to_json(const IntegratorCost& c) {
  dpd::WaterConfig probe;
  dpd::set_integrator(probe, c.integrator, "--integrator");
  const auto j = jdpd_factor(probe);
  nlohmann::json out = to_json(c.m);
  out["integrator"] = c.integrator;
  out["seconds_per_step"] = c.m.median_s / c.m.steps;
  out["factor_vs_mvv"] = c.factor;
  out["jdpd_factor"] = j ? nlohmann::json(*j) : nlohmann::json(nullptr);
  return out;
}

// Each scene of the table beside LAMMPS when LAMMPS was found (the cells scene on --threads, the all-pairs
// scene on one thread, as the table runs it), and each row's speed against LAMMPS's pair_style dpd on its scene
// (not applicable, with the reason, when LAMMPS has no figures for it).
std::vector<bench_dpd_lammps::Side> beside_lammps(const BenchDpdArgs& a, const std::optional<std::string>& launcher,
                                                  const std::string& why, std::vector<Measured>& table) {
  const auto modes = split(a.pairs);
  std::vector<bench_dpd_lammps::Side> sides;
  for (const auto mode : {dpd::PairMode::cells, dpd::PairMode::all}) {
    const bool cells = mode == dpd::PairMode::cells;
    const std::string name(dpd::to_string(mode)), label = cells ? "cells scene" : "all-pairs scene";
    if (std::find(modes.begin(), modes.end(), name) == modes.end()) continue;
    if (!launcher) {
      sides.push_back(bench_dpd_lammps::not_applicable(label, why));
    } else {
      const Case tea1 = with_generator(scene(a, mode, cells ? a.steps_cells : a.steps_all), "tea32", 1);
      const int threads = dpd::team_threads(tea1.cfg.threads, std::size_t(tea1.cfg.particles), tea1.cfg.team_beads);
      sides.push_back(bench_dpd_lammps::measure(label, *launcher, tea1.cfg, a.distribution, a.feed, threads, a.repeat,
                                                [&] { return run_once(tea1).production_s; }));
    }
    for (auto& m : table) {
      if (m.pairs != name) continue;
      if (sides.back().measured())
        m.cost.dpdrng_over_lammps = m.particle_steps_per_s / sides.back().own_ps;
      else
        m.cost.lammps_not_applicable = sides.back().not_applicable;
    }
  }
  return sides;
}

void run_bench_dpd(const BenchDpdArgs& a) {
  if (a.repeat < 1) throw InputError("--repeat must be at least 1");
  if (a.threads < 1) throw InputError("--threads must be at least 1");
  if (a.steps_all < 1 || a.steps_cells < 1) throw InputError("--steps-all and --steps-cells must be at least 1");
  if (a.scaling_only && !a.scaling) throw InputError("--scaling-only and --no-scaling exclude each other");
  if (!a.lammps.empty() && a.no_lammps) throw InputError("--lammps and --no-lammps exclude each other");
  if (a.oversubscribe && a.scaling_only) throw InputError("--oversubscribe and --scaling-only exclude each other");
  const bool compare = split(a.integrator).size() > 1;
  if (split(a.integrator).empty()) throw InputError("--integrator: name at least one integrator");
  if (compare && (a.scaling_only || a.oversubscribe))
    throw InputError("--integrator with a list times the integrators against GW-MVV only: drop --scaling-only and "
                     "--oversubscribe");
  dpd::WaterConfig probe;
  for (const auto& name : split(a.integrator)) dpd::set_integrator(probe, name, "--integrator");
  // The table and the paper setting time MVV's pair noise against ζ = 0 and unhashed runs, which the other
  // integrators have no counterpart of.
  if (!compare && probe.integrator != dpd::Integrator::mvv && !a.scaling_only)
    throw InputError("--integrator " + a.integrator +
                     " times the 1- vs 2-thread comparison only: add --scaling-only (or list several integrators "
                     "to time each against mvv)");
  const auto& tea = rng::find_generator("tea32");
  for (int r : parse_list<int>(a.rounds, "--rounds", {1, kIntMax}))
    if (r < tea.min_rounds || r > tea.max_rounds)
      throw InputError("--rounds: " + std::to_string(r) + " is outside tea32/tea64's " +
                       std::to_string(tea.min_rounds) + ".." + std::to_string(tea.max_rounds));
  for (const auto& p : split(a.pairs)) dpd::parse_pair_mode(p);
  rng::check_feed(rng::parse_distribution(a.distribution), rng::parse_feed(a.feed));
  for (const auto& g : split(a.generators)) rng::find_generator(g);  // InputError for unknown names
  std::string lammps_why;
  const auto launcher = bench_dpd_lammps::locate(a.lammps, a.no_lammps, lammps_why);  // InputError: bad --lammps
  begin_work();

  nlohmann::json out;
  out["context"] = {{"version", dpdrng::kVersion}, {"cpu_model", cpu_model()}, {"simd_width_bits", simd_width_bits()},
                    {"simd", simd_name()}, {"threads", a.threads}, {"repeat", a.repeat},
                    {"integrator", a.integrator},
                    {"distribution", a.distribution}, {"feed", a.feed}, {"statistic", "median wall time of the production steps (after a short untimed start)"}};
  if (compare) {
    const auto rows = measure_integrators(a);
    progress("");
    if (a.json) {
      for (const auto& c : rows) out["integrators"].push_back(to_json(c));
      std::cout << out.dump(2) << "\n";
      return;
    }
    std::cout << cpu_model() << ", " << simd_width_bits() << "-bit SIMD (" << simd_name() << ")\n";
    print_integrators(a, rows);
    return;
  }
  if (a.oversubscribe) {
    const auto rows = measure_oversubscription(a);
    progress("");
    if (a.json) {
      for (const auto& o : rows) out["oversubscribed"].push_back(to_json(o));
      std::cout << out.dump(2) << "\n";
      return;
    }
    std::cout << cpu_model() << ", " << simd_width_bits() << "-bit SIMD (" << simd_name() << ")\n";
    print_oversubscription(rows);
    return;
  }
  std::vector<Measured> table = a.scaling_only ? std::vector<Measured>{} : measure_table(a);
  std::vector<bench_dpd_lammps::Side> beside;
  if (!a.scaling_only) beside = beside_lammps(a, launcher, lammps_why, table);
  const Paper paper = a.scaling_only ? Paper{} : measure_paper(a);
  std::optional<Scaling> scaling;
  if (a.scaling)
    scaling = measure_scaling(with_generator(scene(a, dpd::PairMode::cells, a.steps_cells), "tea32", 1), a.repeat);
  progress("");

  if (a.json) {
    for (const auto& m : table) out["throughput"].push_back(to_json(m));
    for (const auto& side : beside)
      out[side.label == "cells scene" ? "lammps" : "lammps_all_pairs"] = bench_dpd_lammps::to_json(side);
    if (!a.scaling_only)
      out["paper"] = {{"steps", paper.steps},
                      {"tea32_8_s", paper.t8.median_s},
                      {"tea32_1_s", paper.t1.median_s},
                      {"none_s", paper.t0.median_s},
                      {"rng_share_tea32_8", paper.share8()},
                      {"rng_share_tea32_1", paper.share1()},
                      {"speedup_8_to_1", paper.speedup()},
                      {"tea32_1_10000_steps_s", paper.full_run_s()},
                      {"paper_reference", {{"rng_share_8_rounds", 0.40}, {"speedup_8_to_1", 1.5}}}};
    if (scaling) {
      out["scaling"] = {to_json(scaling->one), to_json(scaling->two)};
      out["scaling_speedup_2_threads"] = scaling->speedup;
      out["scaling_pair_ratios"] = scaling->ratios;
      out["scaling_side_by_side_2_copies"] = scaling->machine;
      out["scaling_side_by_side_ratios"] = scaling->machine_ratios;
      out["scaling_two_thread_runs_one_thread_step_share"] = scaling->one_thread_share;
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  std::cout << cpu_model() << ", " << simd_width_bits() << "-bit SIMD (" << simd_name() << ")\n";
  if (!a.scaling_only) print_table(a, table), print_paper(a, paper);
  for (const auto& side : beside) bench_dpd_lammps::print(side);
  if (scaling) print_scaling(a, *scaling);
}

const bool registered = register_command(62, [](CLI::App& root) {
  auto a = std::make_shared<BenchDpdArgs>();
  CLI::App& bench = group(root, "bench", "benchmarks: generator cost, NIST battery throughput, DPD step cost");
  CLI::App* sub = bench.add_subcommand("dpd", "cost of the pair noise in whole DPD runs (particle-steps/s, RNG share)");
  sub->add_option("--generators", a->generators, "comma-separated generators")->capture_default_str();
  sub->add_option("--rounds", a->rounds, "round counts for tea32/tea64")->capture_default_str();
  sub->add_option("--pairs", a->pairs, "all, cells or all,cells")->capture_default_str();
  sub->add_option("--distribution", a->distribution, "gauss or uniform")->capture_default_str();
  sub->add_option("--integrator", a->integrator,
                  "mvv, shardlow, scmvv[:K] or pnhln[:mu] (simulate --help); one other than mvv with "
                  "--scaling-only; a comma-separated list (e.g. mvv,shardlow,scmvv:1,scmvv:5,pnhln) times each "
                  "one's step against mvv's on the --pairs scenes and does nothing else")
      ->capture_default_str();
  sub->add_option("--feed", a->feed, "uniforms feeding the Gaussian: halves, blocks or inverse (simulate --help)")
      ->capture_default_str();
  add_integer(*sub, "--steps-all", a->steps_all, "steps of the 256-bead all-pairs runs", {1, kIntMax});
  add_integer(*sub, "--steps-cells", a->steps_cells, "steps of the cells-mode runs", {1, kIntMax});
  add_integer(*sub, "--particles-cells", a->particles_cells, "beads of the cells-mode system", {2, 50'000'000});
  add_integer(*sub, "--threads", a->threads, "OpenMP threads for the table (the 256-bead scene runs on one)",
              {1, 1024});
  add_integer(*sub, "--repeat", a->repeat, "runs per case (the median is reported); for the scaling, pairs of runs",
              {1, 1000});
  sub->add_flag("--paper", a->paper, "time the paper's full 10 000-step run for tea32(8)/tea32(1)");
  sub->add_flag("!--no-scaling", a->scaling, "skip the 1- vs 2-thread cells comparison");
  sub->add_flag("--scaling-only", a->scaling_only,
                "only the 1- vs 2-thread cells comparison: --repeat pairs of runs, one and two threads alternately, "
                "each followed by two one-thread copies side by side (the machine's own two-core speed-up)");
  sub->add_flag("--oversubscribe", a->oversubscribe,
                "only this: the paper scene (--steps-all) and the cells scene (--steps-cells) with one and two "
                "threads alternately (--repeat pairs) beside a busy loop that bench dpd starts on a thread of its "
                "own, and each two-thread time against the one-thread time");
  sub->add_option("--lammps", a->lammps,
                  "lmp_dpdrng (lammps/build.sh) to run each --pairs scene in LAMMPS beside dpdrng: pair_style dpd "
                  "and pair_style dpd/hash tea32 1, in turn with dpdrng's tea32(1), --repeat rounds, 1 rank, the "
                  "threads dpdrng's run uses (cells: --threads, with -sf omp; the 256-bead scene: one); default: build/lammps/lmp_dpdrng under the working folder, else "
                  "lmp_dpdrng on PATH, else the comparison is not applicable");
  sub->add_flag("--no-lammps", a->no_lammps, "do not run LAMMPS even when it is found");
  sub->add_flag("--json", a->json, "machine-readable output");
  sub->callback([a] { run_bench_dpd(*a); });
});

}  // namespace
}  // namespace cmd_bench_dpd
}  // namespace dpdrng::cli
