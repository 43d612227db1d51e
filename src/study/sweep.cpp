#include "dpdrng/study/sweep.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/rng/splitmix.hpp"

namespace dpdrng::study {

std::string noise_name(rng::Distribution d, rng::Feed f) {
  const std::string name(rng::to_string(d));
  return f == rng::Feed::halves ? name : name + "-" + std::string(rng::to_string(f));
}

std::string seeding_name(rng::Seeding s, bool reference) {
  return reference ? "stream" : std::string(rng::to_string(s));
}

std::string Cell::noise() const { return noise_name(distribution, feed); }
std::string Cell::seeding_name() const { return study::seeding_name(seeding, reference); }

IntegratorSpec parse_integrator_spec(const std::string& text) {
  if (text == "shardlow") return {dpd::Integrator::shardlow, 0.5};
  if (text.rfind("mvv:", 0) == 0) {
    const double lambda = parse_real(std::string_view(text).substr(4), "the lambda of " + quote_input(text));
    if (!(lambda >= 0 && lambda <= 1))
      throw InputError("the lambda of " + quote_input(text) + " must lie in [0, 1] (Groot-Warren's MVV)");
    return {dpd::Integrator::mvv, lambda};
  }
  if (text.rfind("scmvv:", 0) == 0 || text.rfind("pnhln:", 0) == 0) {
    dpd::WaterConfig w;
    dpd::set_integrator(w, text, "integrator " + quote_input(text));
    IntegratorSpec spec;
    spec.kind = w.integrator;
    spec.iterations = w.scmvv_iterations;
    spec.mu = w.pnhln_mu;
    return spec;
  }
  throw InputError("unknown integrator " + quote_input(text) +
                   " (known: mvv:<lambda>, e.g. mvv:0.65, shardlow, scmvv:<K>, e.g. scmvv:5, and pnhln:<mu>, e.g. "
                   "pnhln:10)");
}

IntegratorSpec integrator_of(const std::string& name, const SceneParams& scene) {
  if (name.empty()) return {dpd::Integrator::mvv, scene.lambda};
  return parse_integrator_spec(name);
}

// The feed enters the id only when it is not halves, the integrator only when the sweep names one: cells of
// stores written without them keep their ids.
std::string generator_tag(const std::string& generator) {
  if (!rng::is_plugin(generator)) return generator;
  std::string stem = std::filesystem::path(generator.substr(rng::kPluginPrefix.size())).stem().string();
  for (char& ch : stem)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '.') ch = '_';
  return "ext-" + stem.substr(0, 64);
}

std::string Cell::id() const {
  char buf[400];
  const std::string tag = generator_tag(generator);
  const std::string n = noise();
  // Exact: two Δt that differ in any bit get two ids (the %g form where that is exact, so stores keep names).
  std::string dt_part = "dt" + exact_decimal(dt);
  if (!integrator.empty()) {
    std::string tag = integrator;
    tag.erase(std::remove(tag.begin(), tag.end(), ':'), tag.end());
    dt_part += "-" + tag;
  }
  if (gamma > 0) dt_part += "-gamma" + exact_decimal(gamma);
  if (reference)
    std::snprintf(buf, sizeof buf, "%s-%s-%s-rep%02d", tag.c_str(), n.c_str(), dt_part.c_str(), replica);
  else
    std::snprintf(buf, sizeof buf, "%s-r%02d-%s-%s-%s-rep%02d", tag.c_str(), rounds, n.c_str(),
                  seeding_name().c_str(), dt_part.c_str(), replica);
  return buf;
}

std::string Cell::label() const {
  if (reference) return generator;
  return rng::describe(rng::GeneratorSpec{generator, rounds, rng::kPaperTeaKey});
}

namespace {

// The reference's cell of one noise, Δt, integrator and replica.
Cell reference_cell(const StudyConfig& config, rng::Distribution dist, rng::Feed feed, double dt,
                    const std::string& integrator, int replica, std::uint64_t seed) {
  Cell ref;
  ref.generator = config.reference;
  ref.rounds = 1;
  ref.distribution = dist;
  ref.feed = feed;
  ref.dt = dt;
  ref.integrator = integrator;
  ref.replica = replica;
  ref.reference = true;
  ref.seed = seed;
  return ref;
}

}  // namespace

std::vector<Cell> enumerate_cells(const StudyConfig& config) {
  std::vector<Cell> cells;
  // The battery reads the pair's first block, whatever the feed: only the first feed's cells run it.
  const auto wants_nist = [&](const std::string& gen, rng::Distribution dist, rng::Feed feed, int replica) {
    const auto& t = config.tests;
    return std::find(t.nist_generators.begin(), t.nist_generators.end(), gen) != t.nist_generators.end() &&
           std::find(t.nist_distributions.begin(), t.nist_distributions.end(), dist) != t.nist_distributions.end() &&
           replica < t.nist_replicas && (feed == rng::Feed::halves || feed == config.feeds.front());
  };
  // Shardlow's sweep draws its numbers outside the pair loop's taps and pnhln draws no pair noise: their cells
  // measure physics only.
  const auto tapped = [&](const std::string& integ) { return integrator_of(integ, config.scene).tapped(); };
  // pnhln's result does not depend on the pair noise: it runs the first noise's reference cell only.
  const auto reference_only = [&](const std::string& integ) {
    return integrator_of(integ, config.scene).kind == dpd::Integrator::pnhln;
  };
  const std::vector<rng::Feed> halves_only{rng::Feed::halves};
  const std::vector<std::string> scene_integrator{""};
  for (double dt : config.scene.dt)
    for (const auto& integ : config.integrators.empty() ? scene_integrator : config.integrators) {
      for (int rep = 0; rep < config.reference_replicas_at(dt); ++rep) {
        const bool reference_alone = rep >= config.replicas_at(dt);  // the reference's extra replicas
        // A replica's seed sets the initial state (and the reference's stream); distinct per replica, shared
        // across generators.
        const std::uint64_t seed = rng::splitmix64_mix(config.seed * 0x9e3779b97f4a7c15ull + std::uint64_t(rep));
        bool first_noise = true;
        for (const rng::Distribution dist : config.distributions)
          for (const rng::Feed feed : dist == rng::Distribution::gauss ? config.feeds : halves_only) {
            if (reference_only(integ) && !first_noise) continue;
            first_noise = false;
            // Each feed has its own reference: MT19937 under that feed (a control of the feed itself).
            Cell ref = reference_cell(config, dist, feed, dt, integ, rep, seed);
            ref.nist = wants_nist(ref.generator, dist, feed, rep) && tapped(integ);
            cells.push_back(ref);
            if (reference_only(integ) || reference_alone) continue;
            for (const auto& g : config.generators)
              for (const rng::Seeding seeding : g.seedings.empty() ? config.seedings : g.seedings)
                for (int r : g.rounds) {
                  Cell c = ref;
                  c.generator = g.name;
                  c.rounds = r;
                  c.seeding = seeding;
                  c.reference = false;
                  c.nist = wants_nist(g.name, dist, feed, rep) && tapped(integ);
                  cells.push_back(c);
                }
          }
        // The friction series: the reference under the first noise, as pnhln runs.
        for (const double gamma : config.reference_gammas) {
          const rng::Distribution dist = config.distributions.front();
          Cell ref = reference_cell(config, dist, dist == rng::Distribution::gauss ? config.feeds.front()
                                                                                  : rng::Feed::halves,
                                    dt, integ, rep, seed);
          ref.gamma = gamma;
          cells.push_back(ref);
        }
      }
    }
  return cells;
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) throw InputError("--shard: " + quote_input(text) + " is not k/N (e.g. 3/16)");
  Shard s;
  s.count = parse_number<int>(std::string_view(text).substr(slash + 1), "--shard: N", {1, 1'000'000});
  s.index = parse_number<int>(std::string_view(text).substr(0, slash), "--shard: k",
                              {1, static_cast<std::uint64_t>(s.count)});
  return s;
}

bool in_shard(std::size_t i, Shard shard) { return static_cast<int>(i % std::size_t(shard.count)) == shard.index - 1; }

std::vector<Cell> select_shard(const std::vector<Cell>& cells, Shard shard) {
  std::vector<Cell> out;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (in_shard(i, shard)) out.push_back(cells[i]);
  return out;
}

}  // namespace dpdrng::study
