#pragma once
// The generators a "for every generator" test runs, taken from the registry so that a new family is tested
// without editing the test. The defect generator (a test article with tests of its own) is left out.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "dpdrng/rng/registry.hpp"

namespace dpdrng_test {

// The round counts worth a test: the range's ends, the default, every compiled count and the smallest count
// that runs the run-time-rounds instantiation.
inline std::vector<int> interesting_rounds(const dpdrng::rng::GeneratorInfo& g) {
  const auto compiled = dpdrng::rng::compiled_round_list(g.family);
  std::set<int> r{g.min_rounds, g.default_rounds, g.max_rounds};
  r.insert(compiled.begin(), compiled.end());
  for (int k = g.min_rounds; k <= g.max_rounds; ++k)
    if (std::find(compiled.begin(), compiled.end(), k) == compiled.end()) {
      r.insert(k);
      break;
    }
  return {r.begin(), r.end()};
}

// Every built-in generator but the defect; keyed hashes only unless with_streams (mt19937 too). all_rounds: every
// interesting count (interesting_rounds), otherwise the default only.
inline std::vector<dpdrng::rng::GeneratorSpec> every_generator(bool all_rounds, bool with_streams = false) {
  std::vector<dpdrng::rng::GeneratorSpec> out;
  for (const auto& g : dpdrng::rng::generator_table()) {
    if (g.family == dpdrng::rng::Family::defect || (!g.keyed_hash && !with_streams)) continue;
    const std::vector<int> rounds = all_rounds ? interesting_rounds(g) : std::vector<int>{g.default_rounds};
    for (int r : rounds) out.push_back(dpdrng::rng::validated({std::string(g.name), r}));
  }
  return out;
}

}  // namespace dpdrng_test
