#pragma once
// Options shared by subcommands: the generator choice, and the run options of the two DPD scene commands.
#include <CLI/CLI.hpp>
#include <string>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/config.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::cli {

struct GeneratorOptions {
  std::string name = "tea32";
  int rounds = 0;
  std::string key = "3,4,5,6";
  CLI::Option* key_option = nullptr;  // set by add_to: whether --key was given

  void add_to(CLI::App& app);
  // Validated; throws InputError, also for a --key given to a generator that has none.
  rng::GeneratorSpec spec() const;
};

// What `simulate` and `simulate-bilayer` both take besides the scene's physics.
struct RunOptions {
  GeneratorOptions gen;
  std::string pairs, seeding = "distance", distribution = "gauss", feed = "halves";
  bool json = false, quiet = false;
  std::string series_dir;
  CLI::Option* seeding_option = nullptr;  // set by add_to: whether --seeding was given

  explicit RunOptions(std::string default_pairs) : pairs(std::move(default_pairs)) {}
  // Help texts that differ between the scenes.
  struct Help {
    std::string pairs, sample_every, series;
  };
  // Noise, pair search, seeds, threads, sampling and output; binds the fields both scene configs name alike.
  template <class Config>
  void add_to(CLI::App& app, Config& c, const Help& help);
  // Fills the config's generator, pair mode, seeding, distribution and feed; throws InputError, also for a
  // --seeding given to a stream generator (which draws in a fixed pair order and has no pair seeding).
  template <class Config>
  void apply(Config& c) const {
    c.generator = gen.spec();
    if (seeding_option && seeding_option->count() > 0 && !rng::find_generator(c.generator.name).keyed_hash)
      throw InputError("--seeding: " + c.generator.name +
                       " is a stream drawn in a fixed pair order; it has no pair seeding to choose");
    c.pairs = dpd::parse_pair_mode(pairs);
    c.seeding = rng::parse_seeding(seeding);
    c.distribution = rng::parse_distribution(distribution);
    c.feed = rng::parse_feed(feed);
    rng::check_feed(c.distribution, c.feed);
  }

 private:
  void add_noise_and_output(CLI::App& app, const Help& help, std::uint64_t& seed,
                            std::uint64_t& init_seed, int& threads, int& sample_every);
};

// γ, k_BT and λ, alike in both scenes.
template <class Config>
void add_thermostat_options(CLI::App& app, Config& c) {
  add_real(app, "--gamma", c.gamma, "dissipative strength (sigma^2 = 2 gamma kT)");
  add_real(app, "--kT", c.kT, "temperature k_BT");
  add_real(app, "--lambda", c.lambda, "Groot-Warren lambda (0.5 = velocity-Verlet)");
}

template <class Config>
void RunOptions::add_to(CLI::App& app, Config& c, const Help& help) {
  add_noise_and_output(app, help, c.seed, c.init_seed, c.threads, c.sample_every);
}

}  // namespace dpdrng::cli
