#pragma once
// Generator families, their names and round ranges, and the one place where a runtime choice becomes a
// compile-time type.
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "dpdrng/rng/generator.hpp"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/plugin.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::rng {

// The round counts a family compiles as constants (its traits' CompiledRounds; none for the families without a
// round parameter, plugin and mt19937), at run time.
std::span<const int> compiled_round_list(Family f);

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

// Calls fn.template operator()<F>() with the keyed-hash family f as a constant (the listed families and plugin);
// mt19937, not a keyed hash, is InputError naming `name`. The one switch over the families: the code that needs a
// family's type at compile time goes through it.
template <class Fn>
decltype(auto) visit_keyed_family(Family f, std::string_view name, Fn&& fn) {
  switch (f) {
#define DPDRNG_VISIT(fam) \
  case Family::fam: return fn.template operator()<Family::fam>();
    DPDRNG_KEYED_FAMILIES(DPDRNG_VISIT)
#undef DPDRNG_VISIT
    case Family::plugin: return fn.template operator()<Family::plugin>();
    case Family::mt19937: break;
  }
  throw_not_keyed_hash(name);
}

namespace detail {
// A generator of the spec's key, its run-time round count (for Gen<0>) and, for the defect, the parameters in
// its name.
template <class G>
G make_generator(const GeneratorSpec& s, bool runtime_rounds) {
  G g;
  g.key = s.key;
  if constexpr (requires { g.rounds; })
    if (runtime_rounds) g.rounds = s.rounds;
  if constexpr (requires { g.p; }) g.p = G::params(s.name);
  return g;
}

template <class T, int R0, int... Rs, class F>
decltype(auto) dispatch_rounds(const GeneratorSpec& s, F&& f) {
  if (s.rounds == R0) return f(make_generator<typename T::template Gen<R0>>(s, false));
  if constexpr (sizeof...(Rs) > 0)
    return dispatch_rounds<T, Rs...>(s, std::forward<F>(f));
  else
    return f(make_generator<typename T::template Gen<0>>(s, true));
}

template <class T, int... Rs, class F>
decltype(auto) dispatch_rounds(const GeneratorSpec& s, Rounds<Rs...>, F&& f) {
  if constexpr (sizeof...(Rs) > 0)
    return dispatch_rounds<T, Rs...>(s, std::forward<F>(f));
  else
    return f(make_generator<typename T::template Gen<0>>(s, true));
}

template <Family Fam, class Compiled, class F>
decltype(auto) family_hash(const GeneratorSpec& s, F&& f) {
  static_assert(Fam != Family::mt19937, "mt19937 is not a keyed hash");
  if constexpr (Fam == Family::plugin)
    return with_plugin_hash(s.name, std::forward<F>(f));
  else
    return dispatch_rounds<FamilyTraits<Fam>>(s, Compiled{}, std::forward<F>(f));
}
}  // namespace detail

// Calls f(generator) with a concrete keyed-hash type of the family (whose generator header the caller includes);
// its compiled round counts are compile-time constants, any other count runs the runtime-rounds instantiation.
template <Family Fam, class F>
decltype(auto) with_family_hash(const GeneratorSpec& s, F&& f) {
  if constexpr (Fam == Family::plugin)
    return detail::family_hash<Fam, Rounds<>>(s, std::forward<F>(f));
  else
    return detail::family_hash<Fam, typename FamilyTraits<Fam>::CompiledRounds>(s, std::forward<F>(f));
}

// The same with one instantiation per family, the runtime-rounds one, for every count: for code whose time is
// not spent in the hash, where a copy per compiled count would cost compile time and buy nothing. The values are
// those of with_family_hash (the rounds are the same integer operations, unrolled or not).
template <Family Fam, class F>
decltype(auto) with_family_hash_any_rounds(const GeneratorSpec& s, F&& f) {
  return detail::family_hash<Fam, Rounds<>>(s, std::forward<F>(f));
}

}  // namespace dpdrng::rng
