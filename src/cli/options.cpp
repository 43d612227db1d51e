#include "dpdrng/cli/options.hpp"

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/defect.hpp"

namespace dpdrng::cli {

void GeneratorOptions::add_to(CLI::App& app) {
  std::string names;
  for (const auto& g : rng::generator_table())
    names += (names.empty() ? "" : ", ") + (g.name == "defect" ? rng::defect_syntax() : std::string(g.name));
  app.add_option("--generator,-g", name,
                 "generator: " + names + ", or ext:PATH (your own hash in a shared library: dpdrng/plugin.h)")
      ->capture_default_str();
  add_integer(app, "--rounds,-r", rounds,
              "round count (omitted: the generator's default; tea32/tea64: 1..64; see `dpdrng list`)", {1, kIntMax});
  key_option = app.add_option("--key", key, "four 32-bit key words k0,k1,k2,k3 (TEA: the paper's 3,4,5,6)")
                   ->capture_default_str();
}

rng::GeneratorSpec GeneratorOptions::spec() const {
  rng::GeneratorSpec s;
  s.name = name;
  s.rounds = rounds;
  const auto words = parse_list<std::uint32_t>(key, "--key");
  if (words.size() != 4) throw InputError("--key needs four words k0,k1,k2,k3");
  for (std::size_t i = 0; i < 4; ++i) s.key[i] = words[i];
  s = rng::validated(s);
  if (key_option && key_option->count() > 0) {
    if (!rng::find_generator(s.name).takes_key) throw InputError("--key: " + s.name + " takes no key (the key words would change nothing)");
  }
  return s;
}

void RunOptions::add_noise_and_output(CLI::App& app, const Help& help, std::uint64_t& seed,
                                      std::uint64_t& init_seed, int& threads, int& sample_every) {
  app.add_option("--pairs", pairs, help.pairs)->check(CLI::IsMember({"all", "cells"}))->capture_default_str();
  gen.add_to(app);
  seeding_option =
      app.add_option("--seeding", seeding, "distance (the paper) or pair-step (hash generators only)")
          ->capture_default_str();
  app.add_option("--distribution", distribution, "gauss (Box-Muller) or uniform (sqrt3(2u-1))")
      ->capture_default_str();
  app.add_option("--feed", feed,
                 "uniforms feeding the Gaussian: halves (Box-Muller on one block; a one-word block's two 32-bit\n"
                 "halves), blocks (u1, u2 from two blocks of the pair, 53 bits each) or inverse (one 53-bit uniform\n"
                 "through the inverse normal CDF); uniform noise takes halves only")
      ->capture_default_str();
  add_integer(app, "--seed", seed,
              "noise seed (pair-step key; mt19937 is seeded with its two 32-bit halves XORed, lo32 ^ hi32)");
  add_integer(app, "--init-seed", init_seed, "seed of the initial configuration");
  add_threads(app, threads,
              "OpenMP threads (0 = default); results are identical for any count; systems under 1024 beads "
              "run on one (their steps are too short to share), larger ones on fewer than asked while measured "
              "step times say that is faster (beside a busy core)");
  add_integer(app, "--sample-every", sample_every, help.sample_every, {1, kIntMax});
  app.add_flag("--json", json, "machine-readable output");
  app.add_flag("--quiet,-q", quiet, "no progress on stderr");
  app.add_option("--series", series_dir, help.series)->check(non_empty_path());
}

}  // namespace dpdrng::cli
