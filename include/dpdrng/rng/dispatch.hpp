#pragma once
// Every keyed hash, and the dispatch from a run-time generator choice over all families (registry.hpp has the
// one-family dispatch, which compiles only that family).
#include <cstdint>
#include <utility>

#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/random123.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/rng/saru.hpp"
#include "dpdrng/rng/seeding.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng::rng {

// Calls f(generator) with a concrete keyed-hash type chosen by the spec's family. mt19937 is not a keyed hash:
// InputError.
template <class F>
decltype(auto) with_hash(const GeneratorSpec& s, F&& f) {
  switch (family_of(s.name)) {
    case Family::tea32: return with_family_hash<Family::tea32>(s, std::forward<F>(f));
    case Family::tea64: return with_family_hash<Family::tea64>(s, std::forward<F>(f));
    case Family::philox4x32: return with_family_hash<Family::philox4x32>(s, std::forward<F>(f));
    case Family::threefry2x64: return with_family_hash<Family::threefry2x64>(s, std::forward<F>(f));
    case Family::splitmix64: return with_family_hash<Family::splitmix64>(s, std::forward<F>(f));
    case Family::saru: return with_family_hash<Family::saru>(s, std::forward<F>(f));
    case Family::defect: return with_family_hash<Family::defect>(s, std::forward<F>(f));
    case Family::plugin: return with_family_hash<Family::plugin>(s, std::forward<F>(f));
    case Family::mt19937: break;
  }
  throw_not_keyed_hash(s.name);
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
