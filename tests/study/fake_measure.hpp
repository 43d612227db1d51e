#pragma once
// A stand-in for the engine in the study's own tests: deterministic numbers from the cell, so that storing,
// resuming, merging and reporting can be tested in milliseconds. It counts its calls per cell id.
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

#include "config_text.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/study/cell_result.hpp"
#include "dpdrng/study/config.hpp"

namespace dpdrng::study::fake {

// The small sweep the fake-measure tests share: tea32 at 1 and 8 rounds, tea64 at 1, a 16-bead scene.
inline std::string small_config_toml(const std::string& name, int replicas) {
  return config_text::StudyText{.name = name,
                                .replicas = replicas,
                                .generators = {{}, {.name = "tea64", .rounds = "[1]"}},
                                .scene = "particles = 16\nsteps = 20\nequilibrate = 2\n",
                                .tests = "ttest_pairs = 2\n"}
      .text();
}

struct FakeMeasure {
  std::mutex mu;
  std::map<std::string, int> calls;
  double temperature_shift_tea32_r1 = 0.0;  // makes tea32(1) differ from MT when non-zero

  static double noise(std::uint64_t seed, int k) {
    // Uniform in (-0.5, 0.5) from the seed: reproducible "replica noise".
    return double(rng::splitmix64_mix(seed * 31 + std::uint64_t(k)) >> 11) * 0x1p-53 - 0.5;
  }

  CellResult operator()(const Cell& c, const StudyConfig&, int) {
    {
      std::lock_guard lk(mu);
      ++calls[c.id()];
    }
    CellResult r;
    r.cell = c;
    const std::uint64_t s = c.seed ^ (std::uint64_t(c.rounds) << 40) ^ std::hash<std::string>{}(c.generator);
    double t = 1.03 + 0.003 * noise(s, 1);
    if (c.generator == "tea32" && c.rounds == 1) t += temperature_shift_tea32_r1;
    r.scalars["temperature_mean"] = t;
    r.scalars["temperature_std"] = 0.09 + 0.002 * noise(s, 2);
    r.scalars["pressure_mean"] = 23.9 + 0.05 * noise(s, 3);
    r.scalars["diffusion_coefficient"] = 0.28 + 0.02 * noise(s, 4);
    r.scalars["vpdf_error_mb"] = 0.02 + 0.004 * noise(s, 5);
    r.scalars["cost.ns_per_number"] = c.reference ? 3.0 : 0.5 * c.rounds;
    r.scalars["cost.step_seconds"] = 1e-4 * (1 + 0.1 * c.rounds);
    r.scalars["cost.rng_share"] = 0.1;
    std::vector<double> v, p, g, rr, tau, msd;
    for (int k = 0; k < 40; ++k) {
      const double x = -4 + 0.2 * k;
      v.push_back(x);
      p.push_back(std::exp(-x * x / 2) / std::sqrt(2 * M_PI) * (1 + 0.01 * noise(s, 100 + k)));
      rr.push_back(0.05 * (k + 1));
      g.push_back(1 + 0.3 * std::sin(rr.back() * 3) * (1 + 0.01 * noise(s, 200 + k)));
      tau.push_back(0.4 * k);
      msd.push_back(6 * 0.28 * tau.back() * (1 + 0.02 * noise(s, 300 + k)));
    }
    r.series["vpdf/v"] = v;
    r.series["vpdf/p"] = p;
    r.series["rdf/r"] = rr;
    r.series["rdf/g"] = g;
    r.series["msd/tau"] = tau;
    r.series["msd/msd"] = msd;
    const char* streams[] = {"a", "b"};
    const int n = c.generator == "tea64" ? 2 : 1;
    for (int k = 0; k < n; ++k) {
      const std::string base = std::string("chi2.") + (n == 1 ? "x" : streams[k]);
      r.scalars[base + ".trials"] = 100;
      r.scalars[base + ".passed"] = 99;
      const std::string tb = std::string("ttest.") + (n == 1 ? "x" : streams[k]);
      r.scalars[tb + ".trials"] = 50;
      r.scalars[tb + ".passed"] = 50;
    }
    return r;
  }
};

}  // namespace dpdrng::study::fake
