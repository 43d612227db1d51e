#include "dpdrng/rng/registry.hpp"

#include <array>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/defect.hpp"

namespace dpdrng::rng {

namespace {
constexpr std::array kGenerators{
    GeneratorInfo{"tea32", Family::tea32, 32, 1, 64,
                  "Wheeler & Needham (1994) recommend 32 cycles (64 Feistel rounds); the paper asks whether 1 will do",
                  "32TEA(n): 64-bit seed split into two 32-bit words (low -> x0), n TEA cycles, joined (x1'<<32)|x0'",
                  true},
    GeneratorInfo{"tea64", Family::tea64, 32, 1, 64, "no published analysis; the paper's 64-bit variant of TEA's cycle",
                  "64TEA(n): TEA's cycle on 64-bit words, inputs (x0, x1), outputs a and b", true},
    GeneratorInfo{"philox4x32", Family::philox4x32, 10, 1, 16,
                  "Salmon et al. (SC'11): 7 rounds pass BigCrush, 10 (the default) adds a safety margin",
                  "Philox4x32-R from Random123: 128-bit counter, 64-bit key, 128-bit output", true},
    GeneratorInfo{"threefry2x64", Family::threefry2x64, 20, 1, 32,
                  "Salmon et al. (SC'11): 13 rounds pass BigCrush, 20 (the default) adds a safety margin",
                  "Threefry2x64-R from Random123: 128-bit counter, 128-bit key, 128-bit output", true},
    GeneratorInfo{"splitmix64", Family::splitmix64, 1, 1, 1, "fixed finaliser, no round parameter; passes BigCrush (Steele et al. 2014)",
                  "SplitMix64: Weyl sequence (gamma 0x9e3779b97f4a7c15) through Stafford's mix13 finaliser", true},
    GeneratorInfo{"saru", Family::saru, 1, 1, 1,
                  "fixed, no round parameter; its author reports the stream passes BigCrush (Afshar et al. 2013)",
                  "Saru (Worley 2008), HOOMD-blue v2's DPD noise: 1-3 seed words hashed to (LCG, Weyl) state, "
                  "2 outputs per word",
                  true},
    GeneratorInfo{"defect", Family::defect, 1, 1, 1, "a test article with a known defect, not for production",
                  "Philox4x32-10 with an injected defect at the level of zeta (variance, lag-1 correlation or "
                  "mean shift); its words are Philox's. Name: defect:variance=E,lag1=R,mean=M,base=philox4x32",
                  true},
    GeneratorInfo{"mt19937", Family::mt19937, 1, 1, 1, "the reference; no round parameter",
                  "MT19937 (32-bit, std::mt19937 = gsl_rng_mt19937); two draws make a 64-bit word, high first",
                  false},
};
}  // namespace

std::span<const GeneratorInfo> generator_table() { return kGenerators; }

namespace {
constexpr GeneratorInfo kPlugin{"ext", Family::plugin, 1, 1, 1, "a user's plug-in: no published analysis",
                                "a keyed hash loaded from a shared library (dpdrng/plugin.h); name: ext:PATH", true};
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
