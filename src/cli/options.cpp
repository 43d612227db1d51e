#include "dpdrng/cli/options.hpp"

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

}  // namespace dpdrng::cli
