// dpdrng bench rng: the cost of each generator per 64-bit output (the paper's Fig. 1), scalar and batched, and of
// each distribution on top, all in one run beside mt19937 so that ratios are taken on the same machine state.
// Built on Google Benchmark (its timing loop, iteration-count estimation and repetitions); a collecting
// reporter keeps every repetition and the table shows medians, which shrug off the odd preempted repetition.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/machine.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/rng/inverse_normal.hpp"
#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/summary.hpp"
#include "dpdrng/version.hpp"
#include "bench_rng_scalar.hpp"

namespace dpdrng::cli {
namespace cmd_bench_rng {
namespace {

using rng::GeneratorSpec;
using namespace bench_rng;

struct BenchArgs {
  bool json = false;
  double min_time = 0.02;
  int repetitions = 5;
  std::string filter = ".";
  std::size_t buffer = 2048;
  std::vector<std::string> plugins;  // ext:PATH rows beside the built-ins
};

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::scalar: return "scalar";
    case Mode::batch: return "batch";
    case Mode::scalar_uniform: return "scalar-uniform";
    case Mode::scalar_gauss: return "scalar-gauss";
    case Mode::uniform: return "batch-uniform";
    case Mode::gauss: return "batch-gauss";
    case Mode::scalar_inverse: return "scalar-inverse";
    case Mode::inverse: return "batch-inverse";
  }
  return "?";
}

struct Row {
  std::string label;  // "tea32(8)", "std::mt19937_64"
  GeneratorSpec spec;
  bool std64 = false;  // the std::mt19937_64 reference, outside the registry
};

std::vector<Row> rows(const std::vector<std::string>& plugins) {
  std::vector<Row> out;
  auto add = [&](const std::string& name, int rounds) {
    GeneratorSpec s;
    s.name = name;
    s.rounds = rounds;
    s = rng::validated(s);
    out.push_back({rng::describe(s), s});
  };
  // Every generator at its compiled round counts (one row for those without a round parameter).
  for (const auto& g : rng::generator_table()) {
    if (g.family == rng::Family::defect) continue;
    const auto rounds = rng::compiled_round_list(g.family);
    if (rounds.empty()) add(std::string(g.name), g.default_rounds);
    for (int r : rounds) add(std::string(g.name), r);
  }
  Row std64{"std::mt19937_64", GeneratorSpec{}, true};
  out.push_back(std64);
  for (const auto& name : plugins) {
    const GeneratorSpec s = rng::validated({name, 0});
    out.push_back({"ext:" + rng::load_plugin(name).name, s});
  }
  return out;
}

// mt19937 (32-bit, two draws a word) and std::mt19937_64 have no counter: one engine, advanced in place.
template <class Next>
void scalar_stream(benchmark::State& state, Next next, Mode mode) {
  for (auto _ : state) {
    for (std::size_t k = 0; k < kScalarCalls; ++k) {
      const std::array<std::uint64_t, 1> b{next()};
      if (mode == Mode::scalar)
        benchmark::DoNotOptimize(b[0]);
      else
        benchmark::DoNotOptimize(scalar_number(mode, b));
    }
  }
}

void run_case(benchmark::State& state, const Row& row, Mode mode, std::size_t buffer) {
  const bool scalar = is_scalar(mode);
  if (row.std64) {
    std::mt19937_64 eng(1);
    if (scalar) return scalar_stream(state, [&] { return eng(); }, mode);
    std::vector<std::uint64_t> words(buffer);
    for (auto _ : state) {
      for (auto& w : words) w = eng();
      benchmark::ClobberMemory();
    }
    return;
  }
  if (scalar && row.spec.name == "mt19937") {
    rng::Mt19937 mt(1);
    return scalar_stream(state, [&] { return mt.next64(); }, mode);
  }
  if (scalar) return time_scalar_hash(state, row.spec, mode);
  if (mode == Mode::batch) {
    std::vector<std::uint64_t> words(buffer);
    for (auto _ : state) {
      rng::fill_stream(row.spec, 1, 0, words);
      benchmark::ClobberMemory();
    }
    return;
  }
  if (mode == Mode::inverse) {
    const std::size_t w = static_cast<std::size_t>(rng::words_per_call(row.spec));
    std::vector<std::uint64_t> words(buffer * w);
    std::vector<double> u(buffer), z(buffer);
    for (auto _ : state) {
      rng::fill_stream(row.spec, 1, 0, words);
      for (std::size_t i = 0; i < buffer; ++i) u[i] = rng::to_unit_mid(words[i * w]);
      rng::inverse_normal(u.data(), z.data(), buffer);
      benchmark::ClobberMemory();
    }
    return;
  }
  std::vector<double> out(buffer);
  const auto dist = mode == Mode::gauss ? rng::Distribution::gauss : rng::Distribution::uniform;
  for (auto _ : state) {
    rng::fill_noise(row.spec, dist, 1, 0, out);
    benchmark::ClobberMemory();
  }
}

std::size_t outputs_per_iteration(const Row& row, Mode mode, std::size_t buffer) {
  if (mode == Mode::scalar) return kScalarCalls * (row.std64 ? 1 : rng::words_per_call(row.spec));
  if (is_scalar(mode)) return kScalarCalls;
  return buffer;
}

struct Case {
  std::size_t row;
  Mode mode;
  std::size_t outputs;
};

// Keeps every repetition of every benchmark; Google Benchmark's own aggregates are ignored.
class Collector : public benchmark::BenchmarkReporter {
 public:
  explicit Collector(const std::map<std::string, std::size_t>& index) : index_(index) {}
  bool ReportContext(const Context& c) override {
    cpus_ = c.cpu_info.num_cpus;
    mhz_ = c.cpu_info.cycles_per_second / 1e6;
    scaling_ = c.cpu_info.scaling == benchmark::CPUInfo::Scaling::ENABLED;
    load_ = c.cpu_info.load_avg;
    return true;
  }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration) continue;
      const auto it = index_.find(r.run_name.function_name);
      if (it == index_.end()) continue;
      if (r.error_occurred) throw std::runtime_error("benchmark " + r.benchmark_name() + ": " + r.error_message);
      // CPU time, not wall time: on a shared machine the time the OS gives to other processes must not count.
      samples[it->second].push_back(r.GetAdjustedCPUTime());  // ns per iteration (Unit set below)
      ++done_;
      if (progress_) std::fprintf(stderr, "\r%zu/%zu benchmarks", done_, total);
    }
  }
  void Finalize() override {
    if (progress_) std::fprintf(stderr, "\n");
  }

  std::map<std::size_t, std::vector<double>> samples;
  std::size_t total = 0;
  int cpus_ = 0;
  double mhz_ = 0;
  bool scaling_ = false;
  std::vector<double> load_;

 private:
  const std::map<std::string, std::size_t>& index_;
  std::size_t done_ = 0;
  bool progress_ = isatty(STDERR_FILENO) != 0;  // a progress counter for people, not for log files
};

using stats::median;

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

nlohmann::json run_context(const Collector& c, const BenchArgs& a) {
  char host[256] = "?";
  gethostname(host, sizeof host - 1);
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("gcc ") + __VERSION__;
#else
  const std::string compiler = "unknown";
#endif
#if defined(NDEBUG) && defined(__OPTIMIZE__)
  const char* build = "release (optimised, NDEBUG)";
#elif defined(__OPTIMIZE__)
  const char* build = "optimised with assertions";
#else
  const char* build = "debug (unoptimised)";
#endif
  return {{"host", host},          {"date", utc_now()},        {"dpdrng_version", dpdrng::kVersion},
          {"compiler", compiler},  {"build_type", build},      {"simd", simd_name()},
          {"simd_width_bits", simd_width_bits()}, {"cpu_model", cpu_model()},
          {"num_cpus", c.cpus_},   {"mhz_per_cpu", c.mhz_},    {"cpu_scaling_enabled", c.scaling_},
          {"load_avg", c.load_},   {"min_time_s", a.min_time}, {"repetitions", a.repetitions},
          {"buffer_outputs", a.buffer},  {"time", "process CPU time, median over repetitions"}};
}

void run_bench(const BenchArgs& a) {
  if (!(a.min_time > 0)) throw InputError("--min-time must be positive (seconds)");
  if (a.repetitions < 1) throw InputError("--repetitions must be at least 1");
  if (a.buffer < 16 || a.buffer > (1u << 24)) throw InputError("--buffer must be 16..16777216 outputs");
  // libstdc++ compiles a regular expression recursively: a long one overflows the stack. Row names are short.
  constexpr std::size_t kMaxFilter = 256;
  if (a.filter.size() > kMaxFilter)
    throw InputError("--filter: " + quote_input(a.filter) + " is " + std::to_string(a.filter.size()) +
                     " characters long; at most " + std::to_string(kMaxFilter));
  std::regex filter;
  try {
    filter = std::regex(a.filter);
  } catch (const std::regex_error&) {
    throw InputError("--filter: not a valid regular expression: " + quote_input(a.filter));
  }
  for (const auto& name : a.plugins) {
    if (!rng::is_plugin(name)) throw InputError("--generator: '" + name + "' is not ext:PATH (the built-ins are rows already)");
    rng::check_seeding({name, 0}, rng::Seeding::counter);
  }
  begin_work();

  const std::vector<Row> table = rows(a.plugins);
  std::vector<Case> cases;
  std::map<std::string, std::size_t> index;
  for (std::size_t r = 0; r < table.size(); ++r) {
    for (Mode m : kModes) {
      if (table[r].std64 && m != Mode::scalar && m != Mode::batch) continue;
      const std::string name = table[r].label + "/" + mode_name(m);
      if (!std::regex_search(name, filter) && !(table[r].label == "mt19937")) continue;  // mt19937: the ratio base
      index[name] = cases.size();
      cases.push_back({r, m, outputs_per_iteration(table[r], m, a.buffer)});
      const Row& row = table[r];
      const std::size_t buffer = a.buffer;
      benchmark::RegisterBenchmark(name.c_str(), [&row, m, buffer](benchmark::State& s) { run_case(s, row, m, buffer); })
          ->Unit(benchmark::kNanosecond)
          ->MinTime(a.min_time)
          ->Repetitions(a.repetitions);
    }
  }
  int argc = 1;
  char arg0[] = "dpdrng";
  char* argv[] = {arg0, nullptr};
  benchmark::Initialize(&argc, argv);
  Collector collector(index);
  collector.total = cases.size() * a.repetitions;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::ClearRegisteredBenchmarks();

  // Medians in ns per output, and the mt19937 row of the same mode as the ratio base.
  std::vector<double> med(cases.size(), 0.0);
  std::map<Mode, double> base;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    std::vector<double> per_output;
    for (double t : collector.samples[c]) per_output.push_back(t / cases[c].outputs);
    med[c] = per_output.empty() ? 0.0 : median(per_output);
    if (table[cases[c].row].label == "mt19937") base[cases[c].mode] = med[c];
  }
  auto ratio = [&](std::size_t c) { return base[cases[c].mode] > 0 ? med[c] / base[cases[c].mode] : 0.0; };

  if (a.json) {
    nlohmann::json results = nlohmann::json::array();
    for (std::size_t c = 0; c < cases.size(); ++c) {
      const Row& row = table[cases[c].row];
      std::vector<double> reps;
      for (double t : collector.samples[c]) reps.push_back(t / cases[c].outputs);
      results.push_back({{"generator", row.std64 ? "std::mt19937_64" : row.spec.name},
                         {"rounds", row.std64 ? 1 : row.spec.rounds},
                         {"label", row.label},
                         {"mode", mode_name(cases[c].mode)},
                         {"unit", cases[c].mode == Mode::scalar || cases[c].mode == Mode::batch
                                      ? "ns per 64-bit output"
                                      : "ns per number"},
                         {"median_ns", med[c]},
                         {"ratio_vs_mt19937", ratio(c)},
                         {"repetitions_ns", reps}});
    }
    std::cout << nlohmann::json{{"context", run_context(collector, a)}, {"results", results}}.dump(2) << "\n";
    return;
  }
  std::map<std::pair<std::size_t, Mode>, std::size_t> at;
  for (std::size_t c = 0; c < cases.size(); ++c) at[{cases[c].row, cases[c].mode}] = c;
  std::printf("dpdrng bench rng: median of %d repetitions, ns per 64-bit output (scalar, batch) or per number\n"
              "(distributions); in brackets the ratio to mt19937 in the same mode and run; last columns: batched gauss\n"
              "over batched uniform, and the inverse normal CDF over Box-Muller (gauss), scalar and batched.\n\n",
              a.repetitions);
  std::printf("%-16s", "generator");
  for (Mode m : kModes) std::printf(" %17s", mode_name(m));
  std::printf(" %12s %12s %12s\n", "gauss/unif.", "inv/gauss sc", "inv/gauss b.");
  for (std::size_t r = 0; r < table.size(); ++r) {
    bool any = false;
    for (Mode m : kModes) any = any || at.count({r, m});
    if (!any) continue;
    std::printf("%-16s", table[r].label.c_str());
    for (Mode m : kModes) {
      const auto it = at.find({r, m});
      if (it == at.end()) {
        std::printf(" %17s", "-");
        continue;
      }
      char cell[32];
      std::snprintf(cell, sizeof cell, "%.3f (%.2fx)", med[it->second], ratio(it->second));
      std::printf(" %17s", cell);
    }
    auto quotient = [&](Mode top, Mode bottom) {
      const auto t = at.find({r, top}), b = at.find({r, bottom});
      if (t != at.end() && b != at.end() && med[b->second] > 0)
        std::printf(" %11.2fx", med[t->second] / med[b->second]);
      else
        std::printf(" %12s", "-");
    };
    quotient(Mode::gauss, Mode::uniform);
    quotient(Mode::scalar_inverse, Mode::scalar_gauss);
    quotient(Mode::inverse, Mode::gauss);
    std::printf("\n");
  }
  const nlohmann::json ctx = run_context(collector, a);
  std::printf("\n%s, %s, %s, %s, %s (%d-bit), dpdrng %s, %d CPUs at %.0f MHz%s\n",
              ctx["host"].get<std::string>().c_str(), ctx["cpu_model"].get<std::string>().c_str(),
              ctx["compiler"].get<std::string>().c_str(), ctx["build_type"].get<std::string>().c_str(),
              ctx["simd"].get<std::string>().c_str(), simd_width_bits(), dpdrng::kVersion, collector.cpus_, collector.mhz_,
              collector.scaling_ ? ", CPU frequency scaling on" : "");
}

const bool registered = register_command(40, [](CLI::App& root) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App& bench = group(root, "bench", "benchmarks: generator cost, NIST battery throughput, DPD step cost");
  CLI::App* sub = bench.add_subcommand("rng", "ns per 64-bit output for every generator and round count");
  sub->footer(
      "Rows: tea32/tea64 at 1,2,3,4,5,6,8,16,32 rounds, philox4x32 at 7 and 10, threefry2x64 at 13 and 20,\n"
      "splitmix64, saru, and the references mt19937 (the paper's) and std::mt19937_64; -g ext:PATH adds a\n"
      "plug-in's row (labelled ext:<its name>; its batch mode is one counter() call per buffer).\n"
      "Modes: scalar = independent counter-mode calls one at a time, each output forced into a register, so\n"
      "the CPU may overlap calls but the compiler cannot vectorise them; batch = fill_stream() into a buffer\n"
      "(SIMD kernels for tea32, tea64, philox4x32, threefry2x64, splitmix64); scalar-/batch- uniform and gauss =\n"
      "one number per call (draw<> and fill_noise()); scalar-/batch- inverse = one Gaussian number per call from\n"
      "the block's first word through the inverse normal CDF (scalar, and fill_stream() then the batched kernel).\n"
      "Times are process CPU time (time lent to other processes\n"
      "does not count), medians over repetitions; on a shared machine compare ratios, not absolute times.");
  sub->add_flag("--json", args->json, "machine-readable output with run context and every repetition");
  add_real(*sub, "--min-time", args->min_time, "minimum seconds per repetition of each benchmark",
           {0, 3600, true, false});
  add_integer(*sub, "--repetitions", args->repetitions, "repetitions per benchmark (the table shows medians)",
              {1, 1000});
  sub->add_option("--filter", args->filter, "regular expression on 'label/mode', e.g. 'tea32\\(8\\)|philox'")
      ->capture_default_str();
  add_integer(*sub, "--buffer", args->buffer, "outputs per batched call (default fits in L1)", {16, 1u << 24});
  sub->add_option("--generator,-g", args->plugins, "a plug-in (ext:PATH) timed beside the built-ins; repeatable")
      ->type_name("ext:PATH");
  sub->callback([args] { run_bench(*args); });
});

}  // namespace
}  // namespace cmd_bench_rng
}  // namespace dpdrng::cli
