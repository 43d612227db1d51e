#include "dpdrng/cli/options.hpp"

#include <cmath>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"

namespace dpdrng::cli {

void GeneratorOptions::add_to(CLI::App& app) {
  std::string names;
  for (const auto& g : rng::generator_table()) names += (names.empty() ? "" : ", ") + std::string(g.name);
  app.add_option("--generator,-g", name, "generator: " + names)->capture_default_str();
  rounds_option = app.add_option("--rounds,-r", rounds,
                                 "round count (omitted: the generator's default; tea32/tea64: 1..64; see `dpdrng list`)");
  app.add_option("--key", key, "four 32-bit key words k0,k1,k2,k3 (TEA: the paper's 3,4,5,6)")->capture_default_str();
}

rng::GeneratorSpec GeneratorOptions::spec() const {
  rng::GeneratorSpec s;
  s.name = name;
  s.rounds = rounds;
  const auto words = parse_int_list(key, "--key");
  if (words.size() != 4) throw InputError("--key needs four words k0,k1,k2,k3");
  for (std::size_t i = 0; i < 4; ++i) {
    if (words[i] < 0 || words[i] > 0xffffffffll) throw InputError("--key words must fit in 32 bits");
    s.key[i] = static_cast<std::uint32_t>(words[i]);
  }
  if (rounds < 0 || (rounds == 0 && rounds_option != nullptr && rounds_option->count() > 0))
    throw InputError("--rounds must be at least 1 (omit it for the generator's default)");
  return rng::validated(s);
}

const CLI::Validator& finite_number() {
  static const CLI::Validator v(
      [](std::string& text) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(text, x)) return "not a number: " + text;
        return std::isfinite(x) ? "" : "must be a finite number, not " + text;
      },
      "");
  return v;
}

CLI::Option* add_real(CLI::App& app, const std::string& name, double& value, const std::string& help) {
  return app.add_option(name, value, help)->check(finite_number())->capture_default_str();
}

namespace {
// Unsigned options: CLI11 would wrap "-1" around to 2^64 - 1 silently.
const CLI::Validator& not_negative() {
  static const CLI::Validator v(
      [](std::string& text) -> std::string {
        return text.find('-') == std::string::npos ? "" : "must not be negative: " + text;
      },
      "");
  return v;
}
}  // namespace

void RunOptions::add_noise_and_output(CLI::App& app, const Help& help, std::uint64_t& seed,
                                      std::uint64_t& init_seed, int& threads, int& sample_every) {
  app.add_option("--pairs", pairs, help.pairs)->check(CLI::IsMember({"all", "cells"}))->capture_default_str();
  gen.add_to(app);
  app.add_option("--seeding", seeding, "distance (the paper) or pair-step")->capture_default_str();
  app.add_option("--distribution", distribution, "gauss (Box-Muller) or uniform (sqrt3(2u-1))")
      ->capture_default_str();
  app.add_option("--seed", seed, "noise seed (pair-step key, mt19937 seed)")->check(not_negative())
      ->capture_default_str();
  app.add_option("--init-seed", init_seed, "seed of the initial configuration")->check(not_negative())
      ->capture_default_str();
  app.add_option("--threads", threads, "OpenMP threads (0 = default); results are identical for any count")
      ->capture_default_str();
  app.add_option("--sample-every", sample_every, help.sample_every)->capture_default_str();
  app.add_flag("--json", json, "machine-readable output");
  app.add_flag("--quiet,-q", quiet, "no progress on stderr");
  app.add_option("--series", series_dir, help.series);
}

}  // namespace dpdrng::cli
