#pragma once
// Generator families, their names and round ranges, and the one place where a runtime choice becomes a
// compile-time type.
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/plugin.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::rng {

// The keyed hashes, declared only: naming a family here compiles none of them. A caller of with_family_hash<F>
// includes F's generator header; with_hash (dispatch.hpp) includes them all.
template <int R>
struct Tea32;
template <int R>
struct Tea64;
template <int R>
struct Philox4x32;
template <int R>
struct Threefry2x64;
struct SplitMix64;
struct Saru;
struct Defect;

// The generator families. mt19937 is the reference stream, not a keyed hash; plugin is a user's keyed hash loaded
// at run time (`ext:PATH`, plugin.hpp).
enum class Family { tea32, tea64, philox4x32, threefry2x64, splitmix64, saru, defect, plugin, mt19937 };

template <int... R>
using Rounds = std::integer_sequence<int, R...>;

// The round counts compiled as constants (the studies' counts), one list per family: the registry's dispatch,
// the pair forces, the streams and bench rng all take them from here. Any other count of a family with a round
// parameter runs its run-time-rounds instantiation (G<0>); the other families have no round parameter.
template <Family F>
constexpr auto compiled_rounds() {
  if constexpr (F == Family::tea32 || F == Family::tea64)
    return Rounds<1, 2, 3, 4, 5, 6, 8, 16, 32>{};
  else if constexpr (F == Family::philox4x32)
    return Rounds<7, 10>{};
  else if constexpr (F == Family::threefry2x64)
    return Rounds<13, 20>{};
  else
    return Rounds<>{};
}

namespace detail {
template <int... R>
constexpr std::array<int, sizeof...(R)> as_array(Rounds<R...>) {
  return {R...};
}
template <Family F>
inline constexpr auto kCompiledRounds = as_array(compiled_rounds<F>());
}  // namespace detail

// The same lists at run time.
constexpr std::span<const int> compiled_round_list(Family f) {
  switch (f) {
    case Family::tea32: return detail::kCompiledRounds<Family::tea32>;
    case Family::tea64: return detail::kCompiledRounds<Family::tea64>;
    case Family::philox4x32: return detail::kCompiledRounds<Family::philox4x32>;
    case Family::threefry2x64: return detail::kCompiledRounds<Family::threefry2x64>;
    default: return {};
  }
}

struct GeneratorInfo {
  std::string_view name;
  Family family;
  int default_rounds;
  int min_rounds, max_rounds;
  std::string_view safe_rounds;  // what the generator's authors call safe, with the source
  std::string_view description;
  bool keyed_hash;               // false: a sequential stream (mt19937), not usable as pair-keyed noise
};

// The built-in generators; a plug-in (`ext:PATH`) is not listed.
std::span<const GeneratorInfo> generator_table();
// throws InputError naming the known generators; "defect:..." (defect.hpp) is checked and gives the "defect"
// entry; "ext:PATH" loads the plug-in (load_plugin) and gives the plug-ins' entry
const GeneratorInfo& find_generator(std::string_view name);
inline Family family_of(std::string_view name) { return find_generator(name).family; }

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
// What a generator cannot do under a seeding, as InputError: a lag-1 defect without the step, a plug-in without
// the seeding's entry. Every path that runs a generator under a seeding calls it before the hot loop.
void check_seeding(const GeneratorSpec& spec, Seeding seeding);

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

template <template <int> class G, int... Rs, class F>
decltype(auto) dispatch_rounds(const GeneratorSpec& s, Rounds<Rs...>, F&& f) {
  return dispatch_rounds<G, Rs...>(s, std::forward<F>(f));
}

// No compiled counts: every count runs the runtime-rounds instantiation.
template <template <int> class G, class F>
decltype(auto) dispatch_rounds(const GeneratorSpec& s, Rounds<>, F&& f) {
  G<0> g;
  g.key = s.key;
  g.rounds = s.rounds;
  return f(g);
}

// The defect's parameters are in its name.
template <class G, class F>
decltype(auto) keyed(const GeneratorSpec& s, F&& f) {
  G g;
  g.key = s.key;
  if constexpr (requires { g.p; }) g.p = G::params(s.name);
  return f(g);
}
}  // namespace detail

namespace detail {
template <Family Fam, int... Rs, class F>
decltype(auto) family_hash(const GeneratorSpec& s, Rounds<Rs...> compiled, F&& f) {
  if constexpr (Fam == Family::tea32)
    return dispatch_rounds<Tea32>(s, compiled, std::forward<F>(f));
  else if constexpr (Fam == Family::tea64)
    return dispatch_rounds<Tea64>(s, compiled, std::forward<F>(f));
  else if constexpr (Fam == Family::philox4x32)
    return dispatch_rounds<Philox4x32>(s, compiled, std::forward<F>(f));
  else if constexpr (Fam == Family::threefry2x64)
    return dispatch_rounds<Threefry2x64>(s, compiled, std::forward<F>(f));
  else if constexpr (Fam == Family::splitmix64)
    return keyed<SplitMix64>(s, std::forward<F>(f));
  else if constexpr (Fam == Family::saru)
    return keyed<Saru>(s, std::forward<F>(f));
  else if constexpr (Fam == Family::plugin)
    return with_plugin_hash(s.name, std::forward<F>(f));
  else {
    static_assert(Fam == Family::defect, "mt19937 is not a keyed hash");
    return keyed<Defect>(s, std::forward<F>(f));
  }
}
}  // namespace detail

// Calls f(generator) with a concrete keyed-hash type of the family (whose generator header the caller includes);
// its compiled round counts are compile-time constants, any other count runs the runtime-rounds instantiation.
template <Family Fam, class F>
decltype(auto) with_family_hash(const GeneratorSpec& s, F&& f) {
  return detail::family_hash<Fam>(s, compiled_rounds<Fam>(), std::forward<F>(f));
}

// The same with one instantiation per family, the runtime-rounds one, for every count: for code whose time is
// not spent in the hash, where a copy per compiled count would cost compile time and buy nothing. The values are
// those of with_family_hash (the rounds are the same integer operations, unrolled or not).
template <Family Fam, class F>
decltype(auto) with_family_hash_any_rounds(const GeneratorSpec& s, F&& f) {
  return detail::family_hash<Fam>(s, Rounds<>{}, std::forward<F>(f));
}

}  // namespace dpdrng::rng
