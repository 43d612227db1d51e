#pragma once
// Internal to the CLI: what every run's JSON document carries besides its results: the tool's version, the
// document's schema, and every setting that changes its numbers. The noise, pairing and seed settings are common
// to the scenes' configs (dpd::WaterConfig, dpd::BilayerConfig); each scene adds its own physics.
#include <nlohmann/json.hpp>

#include "dpdrng/dpd/config.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/version.hpp"

namespace dpdrng::cli {

template <class SceneConfig>
nlohmann::json noise_inputs(const SceneConfig& c) {
  return {{"pairs", dpd::to_string(c.pairs)},
          {"generator", c.generator.name},
          {"rounds", c.generator.rounds},
          {"key", c.generator.key},
          {"seeding", rng::to_string(c.seeding)},
          {"distribution", rng::to_string(c.distribution)},
          {"feed", rng::to_string(c.feed)},
          {"seed", c.seed},
          {"init_seed", c.init_seed},
          {"sample_every", c.sample_every},
          {"threads", c.threads}};
}

// j with its version, schema and inputs (the scene's physics merged into noise_inputs).
template <class SceneConfig>
nlohmann::json stamped(nlohmann::json j, const char* schema, const SceneConfig& c, const nlohmann::json& physics) {
  nlohmann::json inputs = noise_inputs(c);
  inputs.update(physics);
  j["dpdrng_version"] = dpdrng::kVersion;
  j["schema"] = schema;
  j["inputs"] = std::move(inputs);
  return j;
}

}  // namespace dpdrng::cli
