#include "dpdrng/rng/registry.hpp"

#include <array>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/family_headers.hpp"

namespace dpdrng::rng {

namespace {
// Every listed family satisfies the generator contract (generator.hpp) at each of its compiled round counts and
// at run-time rounds.
template <class T, int... R>
constexpr bool satisfies_contract(Rounds<R...>) {
  return (KeyedHash<typename T::template Gen<R>> && ... && KeyedHash<typename T::template Gen<0>>);
}
#define DPDRNG_CHECK(fam)                                                                          \
  static_assert(FamilyTraitsOf<FamilyTraits<Family::fam>> &&                                       \
                satisfies_contract<FamilyTraits<Family::fam>>(                                    \
                    typename FamilyTraits<Family::fam>::CompiledRounds{}) &&                       \
                FamilyTraits<Family::fam>::kInfo.family == Family::fam);
DPDRNG_KEYED_FAMILIES(DPDRNG_CHECK)
#undef DPDRNG_CHECK

// The listed families in list order, then the reference stream.
#define DPDRNG_INFO(fam) FamilyTraits<Family::fam>::kInfo,
constexpr std::array kGenerators{
    DPDRNG_KEYED_FAMILIES(DPDRNG_INFO) GeneratorInfo{
        .name = "mt19937",
        .family = Family::mt19937,
        .safe_rounds = "the reference; no round parameter",
        .description = "MT19937 (32-bit, std::mt19937 = gsl_rng_mt19937); two draws make a 64-bit word, high first",
        .keyed_hash = false,
        .takes_key = false,
        .counter_stream = false}};
#undef DPDRNG_INFO

template <int... R>
constexpr std::array<int, sizeof...(R)> as_array(Rounds<R...>) {
  return {R...};
}
template <Family F>
constexpr auto kCompiledRounds = as_array(typename FamilyTraits<F>::CompiledRounds{});
}  // namespace

std::span<const int> compiled_round_list(Family f) {
  switch (f) {
#define DPDRNG_ROUNDS(fam) \
  case Family::fam: return kCompiledRounds<Family::fam>;
    DPDRNG_KEYED_FAMILIES(DPDRNG_ROUNDS)
#undef DPDRNG_ROUNDS
    case Family::plugin:
    case Family::mt19937: break;
  }
  return {};
}

std::span<const GeneratorInfo> generator_table() { return kGenerators; }

namespace {
constexpr GeneratorInfo kPlugin{
    .name = "ext",
    .family = Family::plugin,
    .safe_rounds = "a user's plug-in: no published analysis",
    .description = "a keyed hash loaded from a shared library (dpdrng/plugin.h); name: ext:PATH",
    .takes_key = false};
}  // namespace

const GeneratorInfo& find_generator(std::string_view name) {
  if (is_plugin(name)) {
    load_plugin(name);
    return kPlugin;
  }
  if (is_defect(name)) {
    parse_defect(name);
    name = "defect";
  }
  std::string known;
  for (const auto& g : kGenerators) {
    if (g.name == name) return g;
    known += (known.empty() ? "" : ", ") + std::string(g.name);
  }
  throw InputError("unknown generator '" + std::string(name) + "' (known: " + known + ")");
}

GeneratorSpec validated(GeneratorSpec spec) {
  const GeneratorInfo& info = find_generator(spec.name);
  if (spec.rounds == 0) spec.rounds = info.default_rounds;
  if (spec.rounds < info.min_rounds || spec.rounds > info.max_rounds)
    throw InputError("rounds " + std::to_string(spec.rounds) + " out of range for " + spec.name + " (" +
                     std::to_string(info.min_rounds) + ".." + std::to_string(info.max_rounds) + ")");
  return spec;
}

std::string describe(const GeneratorSpec& spec) {
  if (find_generator(spec.name).max_rounds == 1) return spec.name;
  return spec.name + "(" + std::to_string(spec.rounds) + ")";
}

void throw_not_keyed_hash(std::string_view name) {
  find_generator(name);
  throw InputError(std::string(name) + " is a sequential stream, not a keyed hash: it cannot seed per pair");
}

void throw_counter_not_pair_seeding() {
  throw InputError("seeding 'counter' makes standalone streams; pair noise needs 'distance' or 'pair-step'");
}

void check_defect_seeding(const GeneratorSpec& spec, Seeding seeding) {
  if (!is_defect(spec.name)) return;
  const DefectParams p = parse_defect(spec.name);
  if (seeding == Seeding::distance && p.lag1 != 0)
    throw InputError("'" + spec.name + "': a lag-1 defect correlates a pair's steps; use seeding pair-step");
  if (seeding != Seeding::distance && p.aniso != 0)
    throw InputError("'" + spec.name + "': an anisotropic defect reads the pair's separation; use seeding distance");
}

void check_seeding(const GeneratorSpec& spec, Seeding seeding) {
  check_defect_seeding(spec, seeding);
  if (is_plugin(spec.name)) check_plugin_seeding(load_plugin(spec.name), seeding);
}

Seeding parse_seeding(std::string_view name) {
  if (name == "distance") return Seeding::distance;
  if (name == "pair-step") return Seeding::pair_step;
  if (name == "counter") return Seeding::counter;
  throw InputError("unknown seeding '" + std::string(name) + "' (known: distance, pair-step, counter)");
}

std::string_view to_string(Seeding s) {
  switch (s) {
    case Seeding::distance: return "distance";
    case Seeding::pair_step: return "pair-step";
    case Seeding::counter: return "counter";
  }
  return "?";
}

Distribution parse_distribution(std::string_view name) {
  if (name == "gauss") return Distribution::gauss;
  if (name == "uniform") return Distribution::uniform;
  throw InputError("unknown distribution '" + std::string(name) + "' (known: gauss, uniform)");
}

std::string_view to_string(Distribution d) { return d == Distribution::gauss ? "gauss" : "uniform"; }

Feed parse_feed(std::string_view name) {
  for (Feed f : kFeeds)
    if (name == to_string(f)) return f;
  throw InputError("unknown feed '" + std::string(name) + "' (known: halves, blocks, inverse)");
}

std::string_view to_string(Feed f) {
  switch (f) {
    case Feed::halves: return "halves";
    case Feed::blocks: return "blocks";
    case Feed::inverse: return "inverse";
  }
  return "?";
}

void check_feed(Distribution d, Feed f) {
  if (d == Distribution::uniform && f != Feed::halves)
    throw InputError("feed '" + std::string(to_string(f)) +
                     "' applies to Gaussian noise only (uniform noise takes one word per number: feed halves)");
}

}  // namespace dpdrng::rng
