// dpdrng bench nist: CPU and wall time of each SP800-22 test over K sequences of 2^20 bits.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "dpdrng/cli/options.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/machine.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/stats/nist/battery.hpp"
#include "dpdrng/stats/nist/tests.hpp"

namespace dpdrng::cli {
namespace cmd_bench_nist {
namespace {

namespace nist = stats::nist;

struct BenchArgs {
  GeneratorOptions gen;
  int sequences = 100;
  std::size_t bits = std::size_t{1} << 20;
  bool json = false;
  bool fft_wisdom = false;
};

struct Clock {
  double wall, cpu;
  static Clock now() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    return {wall, static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec)};
  }
};

std::vector<nist::BitSequence> make_sequences(const BenchArgs& a) {
  const rng::GeneratorSpec spec = a.gen.spec();
  std::vector<nist::BitSequence> seqs(static_cast<std::size_t>(a.sequences));
  const std::size_t words = a.bits / 64;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < a.sequences; ++i) {
    std::vector<std::uint64_t> buf(words);
    rng::fill_stream(spec, 0, static_cast<std::uint64_t>(i) * words, buf);
    seqs[static_cast<std::size_t>(i)] = nist::BitSequence::from_words_le(buf);
  }
  return seqs;
}

void run_bench(const BenchArgs& a) {
  if (a.sequences < 1) throw InputError("--sequences must be positive");
  if (a.bits < 64 || a.bits % 64 != 0) throw InputError("--bits must be a positive multiple of 64");
  a.gen.spec();  // a bad generator is refused before any sequence is made
  begin_work();
  if (a.fft_wisdom) {
    std::cout << nist::fft_patient_wisdom(a.bits);
    return;
  }
  const auto seqs = make_sequences(a);
  nlohmann::json rows = nlohmann::json::array();
  double cpu_sum = 0;
  const long count = static_cast<long>(seqs.size());
  for (nist::Test t : nist::all_tests()) {
    std::vector<double> sink(seqs.size());
    const Clock c0 = Clock::now();
#pragma omp parallel for schedule(dynamic, 1)
    for (long i = 0; i < count; ++i) sink[i] = nist::run_test(t, seqs[i]).min_p();
    const Clock c1 = Clock::now();
    cpu_sum += c1.cpu - c0.cpu;
    rows.push_back({{"test", nist::test_name(t)}, {"cpu_s", c1.cpu - c0.cpu}, {"wall_s", c1.wall - c0.wall}});
  }
  const Clock b0 = Clock::now();
  const auto all = nist::run_battery(seqs);
  const Clock b1 = Clock::now();
  nlohmann::json j = {{"sequences", a.sequences},
                      {"bits", a.bits},
                      {"generator", rng::describe(a.gen.spec())},
                      {"threads", omp_get_max_threads()},
                      {"cpu_model", cpu_model()},
                      {"simd_width_bits", simd_width_bits()},
                      {"fft_plan", nist::fft_plan(a.bits)},
                      {"tests", rows},
                      {"sum_cpu_s", cpu_sum},
                      {"battery", {{"cpu_s", b1.cpu - b0.cpu}, {"wall_s", b1.wall - b0.wall}}}};
  if (a.json) {
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::printf("SP800-22 battery, %d sequences of %zu bits (%s), %d threads\n%s, %d-bit SIMD (%s)\n", a.sequences,
              a.bits, rng::describe(a.gen.spec()).c_str(), omp_get_max_threads(), cpu_model().c_str(),
              simd_width_bits(), simd_name());
  std::printf("FFT plan: %s\n", nist::fft_plan(a.bits).c_str());
  std::printf("%-26s %10s %10s\n", "test", "CPU s", "wall s");
  for (const auto& r : rows)
    std::printf("%-26s %10.3f %10.3f\n", r["test"].get<std::string>().c_str(), r["cpu_s"].get<double>(),
                r["wall_s"].get<double>());
  std::printf("%-26s %10.3f\n", "sum of tests", cpu_sum);
  std::printf("%-26s %10.3f %10.3f\n", "whole battery", b1.cpu - b0.cpu, b1.wall - b0.wall);
}

const bool registered = register_command(45, [](CLI::App& root) {
  auto args = std::make_shared<BenchArgs>();
  args->gen.name = "splitmix64";
  CLI::App& bench = group(root, "bench", "benchmarks");
  CLI::App* sub = bench.add_subcommand("nist", "CPU and wall time per SP800-22 test (OpenMP across sequences)");
  args->gen.add_to(*sub);
  add_integer(*sub, "--sequences,-k", args->sequences, "number of sequences", {1, 1'000'000});
  add_integer(*sub, "--bits", args->bits, "bits per sequence (a multiple of 64)", {64, std::uint64_t{1} << 34});
  sub->add_flag("--json", args->json, "machine-readable output");
  sub->add_flag("--fft-wisdom", args->fft_wisdom,
                "plan the spectral test's transform of --bits bits with FFTW_PATIENT (about a minute at 2^20) and "
                "print FFTW's wisdom for it (what src/stats/nist/fft_wisdom.cpp ships), instead of the benchmark");
  sub->callback([args] { run_bench(*args); });
});

}  // namespace
}  // namespace cmd_bench_nist
}  // namespace dpdrng::cli
