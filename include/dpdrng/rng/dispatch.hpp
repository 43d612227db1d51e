#pragma once
// Every keyed hash, and the dispatch from a run-time generator choice over all families (registry.hpp has the
// one-family dispatch, which compiles only that family).
#include <cstdint>
#include <utility>

#include "dpdrng/rng/family_headers.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::rng {

// Calls f(generator) with a concrete keyed-hash type chosen by the spec's family. mt19937 is not a keyed hash:
// InputError.
template <class F>
decltype(auto) with_hash(const GeneratorSpec& s, F&& f) {
  return visit_keyed_family(family_of(s.name), s.name, [&]<Family Fam>() -> decltype(auto) {
    return with_family_hash<Fam>(s, std::forward<F>(f));
  });
}

// Calls f(PairNoise<G, S, D>) for a keyed hash, a pair seeding and a distribution chosen at run time; the feed
// is the noise's run-time field.
template <class F>
decltype(auto) with_pair_noise(const GeneratorSpec& s, Seeding seeding, Distribution dist, std::uint64_t seed,
                               F&& f, Feed feed = Feed::halves) {
  check_feed(dist, feed);
  check_seeding(s, seeding);
  return with_hash(s, [&](const auto& gen) -> decltype(auto) {
    using G = std::decay_t<decltype(gen)>;
    auto with_dist = [&]<Seeding S>() -> decltype(auto) {
      if (dist == Distribution::gauss) return f(PairNoise<G, S, Distribution::gauss>{gen, seed, feed});
      return f(PairNoise<G, S, Distribution::uniform>{gen, seed, feed});
    };
    if (seeding == Seeding::distance) return with_dist.template operator()<Seeding::distance>();
    if (seeding == Seeding::pair_step) return with_dist.template operator()<Seeding::pair_step>();
    throw_counter_not_pair_seeding();
  });
}

}  // namespace dpdrng::rng
