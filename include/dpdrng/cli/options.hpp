#pragma once
// Options shared by subcommands that choose a generator.
#include <CLI/CLI.hpp>
#include <string>

#include "dpdrng/rng/registry.hpp"

namespace dpdrng::cli {

struct GeneratorOptions {
  std::string name = "tea32";
  int rounds = 0;
  std::string key = "3,4,5,6";
  CLI::Option* rounds_option = nullptr;  // set by add_to(): tells an explicit --rounds 0 from the default

  void add_to(CLI::App& app);
  rng::GeneratorSpec spec() const;  // validated; throws InputError
};

}  // namespace dpdrng::cli
