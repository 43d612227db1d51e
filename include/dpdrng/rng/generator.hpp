#pragma once
// What a keyed-hash generator family provides, and the family enumeration built from the one list of families
// (cmake/families.cmake writes dpdrng/rng/families.hpp from it). Naming a family here compiles none of them: a
// family's generator and traits are in its own header.
#include <concepts>
#include <cstdint>
#include <string_view>
#include <utility>

#include "dpdrng/rng/families.hpp"
#include "dpdrng/rng/key.hpp"

namespace dpdrng::rng {

// The listed families, then plugin, a user's keyed hash loaded at run time (`ext:PATH`, plugin.hpp), and mt19937,
// the reference stream, which is not a keyed hash.
#define DPDRNG_ENUMERATOR(fam) fam,
enum class Family { DPDRNG_KEYED_FAMILIES(DPDRNG_ENUMERATOR) plugin, mt19937 };
#undef DPDRNG_ENUMERATOR

template <int... R>
using Rounds = std::integer_sequence<int, R...>;

struct GeneratorInfo {
  std::string_view name;
  Family family;
  int default_rounds = 1;
  int min_rounds = 1, max_rounds = 1;  // 1..1: no round parameter
  std::string_view safe_rounds;        // what the generator's authors call safe, with the source
  std::string_view description;
  bool keyed_hash = true;       // false: a sequential stream (mt19937), not usable as pair-keyed noise
  bool takes_key = true;        // false: --key would change nothing, and is refused
  bool counter_stream = true;   // stream(start, i) hashes the counter start + i (false: a stream seeded by start)
};

// A keyed hash: a stateless function from an input to a block of kWords 64-bit words.
//   stream(start, i)          call i of the standalone stream of counter start (usually the hash of start + i)
//   distance(dx, dy, dz)      the block of a pair whose separation r_j − r_i is (dx, dy, dz), i < j
//   pair_step(i, j, step, s)  the block of the pair i < j at a step under the user seed s
//   key                       the 128-bit key the user sets (--key); a family whose numbers ignore it says so in
//                             its traits (takes_key = false)
// Every call depends on its arguments and the generator's fields only (no state between calls), so that any thread
// and any owner of a pair computes the same block; the caller orders the pair (i < j, canonical() in seeding.hpp),
// which is what makes ζ_ij = ζ_ji. Block is indexable and iterable over its kWords words.
template <class G>
concept KeyedHash = requires(const G g, std::uint64_t u, std::uint32_t w, double d) {
  requires G::kWords >= 1;
  typename G::Block;
  { g.stream(u, u) } -> std::same_as<typename G::Block>;
  { g.distance(d, d, d) } -> std::same_as<typename G::Block>;
  { g.pair_step(w, w, u, u) } -> std::same_as<typename G::Block>;
  { g.key } -> std::convertible_to<TeaKey>;
};

// A listed family's traits, defined in its generator's header beside the generator:
//   template <int R> using Gen    the generator with R rounds fixed at compile time (R = 0: the `rounds` field,
//                                 set at run time); a family without a round parameter ignores R
//   using CompiledRounds          the round counts compiled as constants (Rounds<> for none); any other count
//                                 runs Gen<0>. A fixed count unrolls the round loop, which the hot loops pay for.
//   static constexpr GeneratorInfo kInfo   the registry's entry (name, rounds, description, key use)
template <Family F>
struct FamilyTraits;

// A family's traits as the registry needs them.
template <class T>
concept FamilyTraitsOf = requires {
  typename T::CompiledRounds;
  { T::kInfo } -> std::convertible_to<GeneratorInfo>;
  requires KeyedHash<typename T::template Gen<0>>;
};

}  // namespace dpdrng::rng
