#include "dpdrng/dpd/config.hpp"
#include "dpdrng/common/numbers.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "validate.hpp"

namespace dpdrng::dpd {

PairMode parse_pair_mode(std::string_view name) {
  if (name == "all") return PairMode::all;
  if (name == "cells") return PairMode::cells;
  throw InputError("unknown pair mode '" + std::string(name) + "' (known: all, cells)");
}

std::string_view to_string(PairMode m) { return m == PairMode::all ? "all" : "cells"; }

Integrator parse_integrator(std::string_view name) {
  if (name == "mvv") return Integrator::mvv;
  if (name == "shardlow") return Integrator::shardlow;
  if (name == "scmvv") return Integrator::scmvv;
  if (name == "pnhln") return Integrator::pnhln;
  throw InputError("unknown integrator '" + std::string(name) + "' (known: mvv, shardlow, scmvv[:K], pnhln[:mu])");
}

std::string_view to_string(Integrator i) {
  switch (i) {
    case Integrator::mvv: return "mvv";
    case Integrator::shardlow: return "shardlow";
    case Integrator::scmvv: return "scmvv";
    case Integrator::pnhln: return "pnhln";
  }
  return "mvv";
}

void set_integrator(WaterConfig& cfg, std::string_view text, const std::string& what) {
  const std::size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  Integrator kind;
  try {
    kind = parse_integrator(name);
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
  cfg.integrator = kind;
  if (colon == std::string_view::npos) {
    if (kind == Integrator::scmvv) cfg.scmvv_iterations = kScmvvIterations;
    if (kind == Integrator::pnhln) cfg.pnhln_mu = kPnhlnMu;
    return;
  }
  const std::string param(text.substr(colon + 1));
  const std::string quoted = "'" + std::string(text) + "'";
  if (kind == Integrator::scmvv) {
    cfg.scmvv_iterations =
        static_cast<int>(parse_number<std::int64_t>(param, what + ": the iterations K of " + quoted,
                                                    {1, static_cast<std::uint64_t>(kScmvvMaxIterations)}));
    return;
  }
  if (kind == Integrator::pnhln) {
    cfg.pnhln_mu = parse_real(param, what + ": the coupling mu of " + quoted,
                              RealRange{0.0, std::numeric_limits<double>::infinity(), true, false});
    return;
  }
  throw InputError(what + ": " + quoted + ": " + std::string(name) + " takes no parameter" +
                   (kind == Integrator::mvv ? " (its lambda is --lambda)" : ""));
}

std::string WaterConfig::integrator_name() const {
  if (integrator == Integrator::scmvv) return "scmvv:" + std::to_string(scmvv_iterations);
  if (integrator == Integrator::pnhln) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "pnhln:%g", pnhln_mu);
    return buf;
  }
  return std::string(to_string(integrator));
}

double WaterConfig::box_length() const { return std::cbrt(particles / density); }

namespace {
using validate::bad;
using validate::positive;
void finite(double v, const char* field) {
  if (!std::isfinite(v)) bad(field, "must be finite");
}
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}
}  // namespace

void check_step_resolves(double dt, double kT, double box_length, const std::string& field) {
  const double least = std::ldexp(box_length, -32) / std::sqrt(kT);
  if (dt < least)
    bad(field, num(dt) + ": a bead at the thermal speed would move " + num(dt * std::sqrt(kT)) +
                   " a step, less than 2^-32 of the box length " + num(box_length) +
                   ", which its coordinates cannot resolve (dt must be at least " + num(least) + ")");
}

void check_box_resolves(double box_length, double rc, const std::string& field) {
  if (box_length > std::ldexp(rc, 24))
    bad(field, "the box length " + num(box_length) + " is more than 2^24 cut-offs r_c = " + num(rc) +
                   ": its coordinates could not resolve distances of order r_c (raise the density)");
}

void WaterConfig::validate() const {
  if (particles < 2 || particles > 50'000'000) bad("particles", std::to_string(particles) + " (2..5e7)");
  positive(density, "density");
  finite(a, "a");
  positive(rc, "rc");
  positive(kT, "kT");
  finite(gamma, "gamma");
  if (gamma < 0) bad("gamma", "must not be negative");
  finite(lambda, "lambda");
  if (lambda < 0 || lambda > 1) bad("lambda", exact_decimal(lambda) + " (0..1)");
  positive(dt, "dt");
  if (steps < 1) bad("steps", std::to_string(steps) + " (at least 1)");
  if (equilibrate < 0 || equilibrate >= steps)
    bad("equilibrate", std::to_string(equilibrate) + " (0 <= equilibrate < steps = " + std::to_string(steps) + ")");
  // Minimum image gives each pair once only if the box is wider than two cut-offs.
  if (!(box_length() > 2 * rc))
    bad("particles/density", "box length " + format_g(box_length()) + " must exceed 2*rc");
  check_box_resolves(box_length(), rc, "density");
  check_step_resolves(dt, kT, box_length(), "dt");
  // Linked cells allocate every cell of width r_c, empty or not, and sweep them every step: in a dilute box the
  // empty cells cost more than the pairs (2.5 million cells for 256 beads ran at 1 400 particle-steps/s).
  const double cells = std::pow(std::floor(box_length() / rc), 3);
  if (pairs == PairMode::cells && cells > 64.0 * particles)
    bad("density", num(density) + " with pairs = cells: " + num(cells) + " cells of width r_c for " +
                       std::to_string(particles) + " beads, more than 64 a bead: use pairs = all or a higher density");
  rng::validated(generator);  // names the generator and its round range in the error
  if (seeding == rng::Seeding::counter) bad("seeding", "'counter' makes streams; pair noise needs distance or pair-step");
  rng::check_seeding(generator, seeding);
  if (distribution == rng::Distribution::uniform && feed != rng::Feed::halves)
    bad("feed", std::string(rng::to_string(feed)) + " applies to Gaussian noise only (uniform takes feed halves)");
  if (threads < 0) bad("threads", "must not be negative");
  if (sample_every < 1) bad("sample_every", "at least 1");
  if (vpdf_bins < 1) bad("vpdf_bins", "at least 1");
  positive(vpdf_range, "vpdf_range");
  if (rdf_bins < 1) bad("rdf_bins", "at least 1");
  positive(rdf_rmax, "rdf_rmax");
  if (rdf_every < 0) bad("rdf_every", "must not be negative");
  if (msd_every < 0) bad("msd_every", "must not be negative");
  if (zeta_lags < 0 || zeta_lags > 1000) bad("zeta_lags", "must lie in 0..1000");
  positive(max_temperature, "max_temperature");
  finite(min_distance, "min_distance");
  if (min_distance < 0) bad("min_distance", "must not be negative");
  for (auto s : taps.raw_steps)
    if (s < 0 || s > steps) bad("taps.raw_steps", std::to_string(s) + " outside 0..steps");
  for (auto [i, j] : taps.pairs)
    if (!(i < j) || j >= static_cast<std::uint32_t>(particles))
      bad("taps.pairs", "(" + std::to_string(i) + ", " + std::to_string(j) + ") needs i < j < particles");
  const bool sweeps = integrator == Integrator::shardlow || integrator == Integrator::pnhln;
  if (taps.in_range() && (taps.in_range_first <= equilibrate || taps.in_range_last > steps))
    bad("taps.in_range", std::to_string(taps.in_range_first) + ".." + std::to_string(taps.in_range_last) +
                             " outside the production steps " + std::to_string(equilibrate + 1) + ".." +
                             std::to_string(steps));
  if (sweeps && (!taps.raw_steps.empty() || !taps.pairs.empty() || taps.in_range()))
    bad("integrator", std::string(to_string(integrator)) + " draws no numbers in the pair loop; taps need mvv or scmvv");
  if (integrator != Integrator::mvv && noise_override != NoiseOverride::off)
    bad("integrator", std::string(to_string(integrator)) + " has no noise override (a benchmark of the mvv pair loop)");
  if (scmvv_iterations < 1 || scmvv_iterations > kScmvvMaxIterations)
    bad("scmvv_iterations", std::to_string(scmvv_iterations) + " (1.." + std::to_string(kScmvvMaxIterations) + ")");
  if (!(pnhln_mu > 0) || !std::isfinite(pnhln_mu)) bad("pnhln_mu", "must be positive and finite");
  if (!taps.pairs.empty() && generator.name == "mt19937" && pairs == PairMode::cells)
    bad("taps.pairs", "mt19937 gives a pair a number only while it is listed; tap pair series with pairs=all");
}

}  // namespace dpdrng::dpd
