#include "dpdrng/study/decomposition_store.hpp"

#include <bit>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/config.hpp"
#include "dpdrng/study/decomposition_sweep.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/store.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
using nlohmann::json;
using namespace dpdrng::dpd;

std::string DecompCell::id() const {
  char rounds[16];
  std::snprintf(rounds, sizeof rounds, "-r%02d-", generator.rounds);
  std::string s = to_string(seeding);
  std::erase(s, ':');
  return generator.name + rounds + s + "-" + std::string(rng::to_string(distribution));
}

std::vector<DecompCell> decomp_cells(const DecompSweep& sw) {
  std::vector<DecompCell> out;
  for (const auto& g : sw.generators)
    for (const auto& s : sw.seedings)
      for (auto d : sw.distributions) out.push_back({g, s, d});
  return out;
}

namespace {

// JSON numbers carry every finite double exactly (shortest round-trip digits); NaN and ±inf have no JSON
// number, so they go as their bit pattern, which also keeps a NaN's sign and payload.
json real(double x) {
  if (std::isfinite(x)) return x;
  char bits[24];
  std::snprintf(bits, sizeof bits, "0x%016llx", static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(x)));
  return std::string(bits);
}

double real_of(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s.size() != 18 || s.rfind("0x", 0) != 0) throw std::runtime_error("'" + s + "' is not a number");
  return std::bit_cast<double>(static_cast<std::uint64_t>(std::stoull(s.substr(2), nullptr, 16)));
}

json boundary_record(const BoundaryStats& b) {
  return {{"evaluations", b.evaluations},
          {"in_range", b.in_range},
          {"boundary", b.boundary},
          {"shifted", b.shifted},
          {"separation_mismatch", b.separation_mismatch},
          {"range_mismatch", b.range_mismatch},
          {"zeta_mismatch", b.zeta_mismatch},
          {"zeta_diff_sum", real(b.zeta_diff_sum)},
          {"zeta_diff_sum2", real(b.zeta_diff_sum2)},
          {"zeta_diff_max", real(b.zeta_diff_max)},
          {"force_mismatch_max", real(b.force_mismatch_max)},
          {"net_force_max", real(b.net_force_max)},
          {"net_force_sum2", real(b.net_force_sum2)},
          {"grid_straddle_expected", real(b.grid_straddle_expected)}};
}

BoundaryStats boundary_of(const json& j) {
  BoundaryStats b;
  b.evaluations = j.at("evaluations").get<std::uint64_t>();
  b.in_range = j.at("in_range").get<std::uint64_t>();
  b.boundary = j.at("boundary").get<std::uint64_t>();
  b.shifted = j.at("shifted").get<std::uint64_t>();
  b.separation_mismatch = j.at("separation_mismatch").get<std::uint64_t>();
  b.range_mismatch = j.at("range_mismatch").get<std::uint64_t>();
  b.zeta_mismatch = j.at("zeta_mismatch").get<std::uint64_t>();
  b.zeta_diff_sum = real_of(j.at("zeta_diff_sum"));
  b.zeta_diff_sum2 = real_of(j.at("zeta_diff_sum2"));
  b.zeta_diff_max = real_of(j.at("zeta_diff_max"));
  b.force_mismatch_max = real_of(j.at("force_mismatch_max"));
  b.net_force_max = real_of(j.at("net_force_max"));
  b.net_force_sum2 = real_of(j.at("net_force_sum2"));
  b.grid_straddle_expected = real_of(j.at("grid_straddle_expected"));
  return b;
}

json stat_record(const Stat& s) {
  return {{"mean", real(s.mean)},       {"std", real(s.std)},         {"sem", real(s.sem)},
          {"sem_dof", real(s.sem_dof)}, {"std_sem", real(s.std_sem)}, {"std_sem_dof", real(s.std_sem_dof)},
          {"n", s.n}};
}

Stat stat_of(const json& j) {
  Stat s;
  s.mean = real_of(j.at("mean"));
  s.std = real_of(j.at("std"));
  s.sem = real_of(j.at("sem"));
  s.sem_dof = real_of(j.at("sem_dof"));
  s.std_sem = real_of(j.at("std_sem"));
  s.std_sem_dof = real_of(j.at("std_sem_dof"));
  s.n = j.at("n").get<std::size_t>();
  return s;
}

// A run's status as its three parts, so that reading it back gives the same RunStatus.
json status_record(const dpd::RunStatus& s) {
  return {{"state", dpd::to_string(s.state)}, {"step", s.step}, {"detail", s.detail}};
}

dpd::RunStatus status_of(const json& j) {
  dpd::RunStatus s;
  s.state = dpd::parse_run_state(j.at("state").get<std::string>());
  s.step = j.at("step").get<std::int64_t>();
  s.detail = j.at("detail").get<std::string>();
  return s;
}

json run_record(const DecompRun& r) {
  return {{"status", status_record(r.status)},
          {"steps_done", r.steps_done},
          {"temperature", stat_record(r.temperature)},
          {"pressure", stat_record(r.pressure)},
          {"diffusion", real(r.diffusion)},
          {"diffusion_sem", real(r.diffusion_sem)},
          {"momentum_drift", real(r.momentum_drift)},
          {"momentum_final", real(r.momentum_final)},
          {"com_kinetic_share", real(r.com_kinetic_share)},
          {"boundary", boundary_record(r.boundary)},
          {"seconds", real(r.seconds)}};
}

DecompRun run_of(const json& j) {
  DecompRun r;
  r.status = status_of(j.at("status"));
  r.steps_done = j.at("steps_done").get<std::int64_t>();
  r.temperature = stat_of(j.at("temperature"));
  r.pressure = stat_of(j.at("pressure"));
  r.diffusion = real_of(j.at("diffusion"));
  r.diffusion_sem = real_of(j.at("diffusion_sem"));
  r.momentum_drift = real_of(j.at("momentum_drift"));
  r.momentum_final = real_of(j.at("momentum_final"));
  r.com_kinetic_share = real_of(j.at("com_kinetic_share"));
  r.boundary = boundary_of(j.at("boundary"));
  r.seconds = real_of(j.at("seconds"));
  return r;
}

json randomness_record(const RandomnessCost& c) {
  return {{"chi2_tests", c.chi2_tests},
          {"chi2_pass", c.chi2_pass},
          {"chi2_min_p", real(c.chi2_min_p)},
          {"lag1_tests", c.lag1_tests},
          {"lag1_pass", c.lag1_pass},
          {"lag1_max_abs_r", real(c.lag1_max_abs_r)},
          {"cross_pair_r", real(c.cross_pair_r)},
          {"cross_pair_p", real(c.cross_pair_p)},
          {"cross_pair_verdict", c.cross_pair_verdict},
          {"duplicates_per_step", real(c.duplicates_per_step)}};
}

RandomnessCost randomness_of(const json& j) {
  RandomnessCost c;
  c.chi2_tests = j.at("chi2_tests").get<std::size_t>();
  c.chi2_pass = j.at("chi2_pass").get<std::size_t>();
  c.chi2_min_p = real_of(j.at("chi2_min_p"));
  c.lag1_tests = j.at("lag1_tests").get<std::size_t>();
  c.lag1_pass = j.at("lag1_pass").get<std::size_t>();
  c.lag1_max_abs_r = real_of(j.at("lag1_max_abs_r"));
  c.cross_pair_r = real_of(j.at("cross_pair_r"));
  c.cross_pair_p = real_of(j.at("cross_pair_p"));
  c.cross_pair_verdict = j.at("cross_pair_verdict").get<std::string>();
  c.duplicates_per_step = real_of(j.at("duplicates_per_step"));
  return c;
}

// The rows of a cell file, after checking its checksum, config hash and cell id; throws with the reason.
std::vector<DecompResult> read_cell_file(const fs::path& p, const std::string& hash, const std::string& id) {
  json j;
  try {
    j = json::parse(read_whole_file(p));
  } catch (const json::parse_error&) {
    throw std::runtime_error("not whole JSON (cut short or altered after it was written)");
  }
  const json& rows = j.at("rows");
  if (j.at("rows_fnv1a64").get<std::string>() != fnv1a64_hex(rows.dump()))
    throw std::runtime_error("its rows do not match their checksum (altered after it was written)");
  const std::string stored = j.at("config_hash").get<std::string>();
  if (stored != hash) throw std::runtime_error("written by another config (hash " + stored + ")");
  if (j.at("cell").get<std::string>() != id) throw std::runtime_error("holds cell " + j.at("cell").get<std::string>());
  std::vector<DecompResult> out;
  for (const auto& r : rows) out.push_back(decomp_from_record(r));
  return out;
}

}  // namespace

json decomp_record(const DecompResult& r) {
  json j = {{"generator", r.generator},
            {"seeding", r.seeding},
            {"distribution", r.distribution},
            {"domains", r.domains},
            {"feed", r.feed},
            {"particles", r.particles},
            {"box_length", real(r.box_length)},
            {"snapshot", boundary_record(r.snapshot)},
            {"decomposed", run_record(r.decomposed)},
            {"has_reference", r.has_reference}};
  if (r.has_reference) j["reference"] = run_record(r.reference), j["randomness"] = randomness_record(r.randomness);
  return j;
}

DecompResult decomp_from_record(const json& j) {
  DecompResult r;
  r.generator = j.at("generator").get<std::string>();
  r.seeding = j.at("seeding").get<std::string>();
  r.distribution = j.at("distribution").get<std::string>();
  r.domains = j.at("domains").get<std::string>();
  r.feed = j.at("feed").get<std::string>();
  r.particles = j.at("particles").get<std::size_t>();
  r.box_length = real_of(j.at("box_length"));
  r.snapshot = boundary_of(j.at("snapshot"));
  r.decomposed = run_of(j.at("decomposed"));
  r.has_reference = j.at("has_reference").get<bool>();
  if (r.has_reference) r.reference = run_of(j.at("reference")), r.randomness = randomness_of(j.at("randomness"));
  return r;
}

void DecompStore::open_for(const DecompSweep& sweep) {
  open_store_directory(dir_, "decomposition.toml", sweep.source_text, sweep.hash);
}

fs::path DecompStore::cell_path(const DecompCell& cell) const { return dir_ / "cells" / (cell.id() + ".json"); }

DecompStore::State DecompStore::state(const DecompCell& cell, std::string* reason) const {
  const fs::path p = cell_path(cell);
  if (!fs::exists(p)) return State::missing;
  try {
    read_cell_file(p, read_store_hash(dir_), cell.id());
    return State::stored;
  } catch (const std::exception& e) {
    if (reason) *reason = e.what();
    return State::unreadable;
  }
}

void DecompStore::save(const DecompCell& cell, const std::vector<DecompResult>& rows) {
  json records = json::array();
  for (const auto& r : rows) records.push_back(decomp_record(r));
  const json j = {{"cell", cell.id()},
                  {"config_hash", read_store_hash(dir_)},
                  {"rows_fnv1a64", fnv1a64_hex(records.dump())},
                  {"rows", records}};
  write_file_atomically(cell_path(cell), j.dump(1) + "\n");
}

std::vector<DecompResult> DecompStore::load(const DecompCell& cell) const {
  return read_cell_file(cell_path(cell), read_store_hash(dir_), cell.id());
}

}  // namespace dpdrng::study
