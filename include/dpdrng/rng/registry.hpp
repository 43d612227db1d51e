#pragma once
// Generator names, their round ranges, and the one place where a runtime choice becomes a compile-time type.
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/random123.hpp"
#include "dpdrng/rng/saru.hpp"
#include "dpdrng/rng/seeding.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng::rng {

struct GeneratorInfo {
  std::string_view name;
  int default_rounds;
  int min_rounds, max_rounds;
  std::string_view safe_rounds;  // what the generator's authors call safe, with the source
  std::string_view description;
  bool keyed_hash;               // false: a sequential stream (mt19937), not usable as pair-keyed noise
};

std::span<const GeneratorInfo> generator_table();
// throws InputError naming the known generators; "defect:..." (defect.hpp) is checked and gives the "defect" entry
const GeneratorInfo& find_generator(std::string_view name);

struct GeneratorSpec {
  std::string name = "tea32";
  int rounds = 0;  // 0 = the generator's default
  TeaKey key = kPaperTeaKey;
};

// Fills the default round count and checks the range; throws InputError with the reason.
GeneratorSpec validated(GeneratorSpec spec);
std::string describe(const GeneratorSpec& spec);  // e.g. "tea32(1)"

[[noreturn]] void throw_not_keyed_hash(std::string_view name);
[[noreturn]] void throw_counter_not_pair_seeding();
// A lag-1 defect needs the step in the hash input: InputError for a lag-1 defect under distance seeding.
void check_defect_seeding(const GeneratorSpec& spec, Seeding seeding);

namespace detail {
template <template <int> class G, int R0, int... Rs, class F>
decltype(auto) dispatch_rounds(const GeneratorSpec& s, F&& f) {
  if (s.rounds == R0) {
    G<R0> g;
    g.key = s.key;
    return f(g);
  }
  if constexpr (sizeof...(Rs) > 0) {
    return dispatch_rounds<G, Rs...>(s, std::forward<F>(f));
  } else {
    G<0> g;
    g.key = s.key;
    g.rounds = s.rounds;
    return f(g);
  }
}
}  // namespace detail

// Calls f(generator) with a concrete keyed-hash type; the study's round counts are compile-time constants,
// any other count runs the runtime-rounds instantiation. mt19937 is not a keyed hash: InputError.
template <class F>
decltype(auto) with_hash(const GeneratorSpec& s, F&& f) {
  if (s.name == "tea32") return detail::dispatch_rounds<Tea32, 1, 2, 3, 4, 5, 6, 8, 16, 32>(s, std::forward<F>(f));
  if (s.name == "tea64") return detail::dispatch_rounds<Tea64, 1, 2, 3, 4, 5, 6, 8, 16, 32>(s, std::forward<F>(f));
  if (s.name == "philox4x32") return detail::dispatch_rounds<Philox4x32, 7, 10>(s, std::forward<F>(f));
  if (s.name == "threefry2x64") return detail::dispatch_rounds<Threefry2x64, 13, 20>(s, std::forward<F>(f));
  if (s.name == "splitmix64") return detail::dispatch_rounds<SplitMix64, 1>(s, std::forward<F>(f));
  if (s.name == "saru") return detail::dispatch_rounds<Saru, 1>(s, std::forward<F>(f));
  if (is_defect(s.name)) {
    Defect g;
    g.key = s.key;
    g.p = parse_defect(s.name);
    return f(g);
  }
  throw_not_keyed_hash(s.name);
}


// Calls f(PairNoise<G, S, D>) for a keyed hash, a pair seeding and a distribution chosen at run time; the feed
// is the noise's run-time field.
template <class F>
decltype(auto) with_pair_noise(const GeneratorSpec& s, Seeding seeding, Distribution dist, std::uint64_t seed,
                               F&& f, Feed feed = Feed::halves) {
  check_feed(dist, feed);
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
