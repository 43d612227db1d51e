#pragma once
// A user's keyed hash from a shared library (dpdrng/plugin.h), named `ext:PATH` wherever a generator is named:
// the loader, and PluginHash<W>, the generator type through which a plug-in runs on the built-ins' code paths.
// The pair loop calls the batch members (a row's pairs per call); the one-block members serve every other path.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "dpdrng/plugin.h"
#include "dpdrng/rng/key.hpp"
#include "dpdrng/rng/seeding.hpp"

namespace dpdrng::rng {

inline constexpr std::string_view kPluginPrefix = "ext:";
constexpr bool is_plugin(std::string_view name) { return name.starts_with(kPluginPrefix); }

struct LoadedPlugin {
  std::string file;    // the canonical path of the library loaded
  std::string sha256;  // of its bytes, lower-case hex
  std::string name;    // the plug-in's own name
  const dpdrng_plugin* api = nullptr;
};

// Loads the library of `ext:PATH` once per process and path (later calls return the same plug-in), checks its
// ABI, words and entries, and says on stderr which library it loaded. InputError with the reason otherwise.
const LoadedPlugin& load_plugin(std::string_view generator_name);
// InputError when the plug-in lacks the seeding's entry.
void check_plugin_seeding(const LoadedPlugin& p, Seeding seeding);

template <int W>
struct PluginHash {
  static_assert(W == 1 || W == 2);
  static constexpr const char* kName = "ext";
  static constexpr int kWords = W;
  using Block = std::array<std::uint64_t, W>;
  static_assert(sizeof(Block) == W * sizeof(std::uint64_t), "blocks are passed to the plug-in as plain words");

  const dpdrng_plugin* api = nullptr;
  TeaKey key = kPaperTeaKey;  // not read: a plug-in keys itself

  Block stream(std::uint64_t start, std::uint64_t i) const {
    Block b;
    api->counter(start + i, 1, b.data());
    return b;
  }
  Block distance(double dx, double dy, double dz) const {
    Block b;
    api->distance(&dx, &dy, &dz, 1, b.data());
    return b;
  }
  Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    Block b;
    api->pair_step(&i, &j, step, seed, 1, b.data());
    return b;
  }

  void stream_words(std::uint64_t first, std::size_t calls, std::uint64_t* out) const {
    api->counter(first, calls, out);
  }
  void distance_batch(const double* dx, const double* dy, const double* dz, std::size_t n, Block* out) const {
    api->distance(dx, dy, dz, n, out->data());
  }
  void pair_step_batch(const std::uint32_t* i, const std::uint32_t* j, std::uint64_t step, std::uint64_t seed,
                       std::size_t n, Block* out) const {
    api->pair_step(i, j, step, seed, n, out->data());
  }
};

// Calls f(PluginHash<W>) with W the plug-in's words.
template <class F>
decltype(auto) with_plugin_hash(std::string_view generator_name, F&& f) {
  const LoadedPlugin& p = load_plugin(generator_name);
  if (p.api->words == 2) return f(PluginHash<2>{p.api});
  return f(PluginHash<1>{p.api});
}

// The counter-mode stream in one call per batch: block c of the output is the plug-in's block of start+first+c.
template <int W>
void stream_batch(const PluginHash<W>& g, std::uint64_t start, std::uint64_t first, std::span<std::uint64_t> out) {
  g.stream_words(start + first, out.size() / W, out.data());
}

}  // namespace dpdrng::rng
