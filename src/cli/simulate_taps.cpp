// dpdrng simulate's taps: the words and ζ of the pairs inside r_c, step by step, into files with JSON sidecars.
#include "simulate_taps.hpp"

#include <unistd.h>

#include <bit>
#include <filesystem>
#include <stdexcept>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/rng/registry.hpp"
#include "dpdrng/rng/stream.hpp"

namespace dpdrng::cli {
namespace simulate_taps {
namespace {

namespace fs = std::filesystem;

std::string sidecar_name(const std::string& file) { return file + ".json"; }

// Every file the taps write, with what names it ("--tap-zeta", "--tap-zeta's sidecar").
std::vector<std::pair<std::string, std::string>> tap_files(const TapOptions& o) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& [flag, file] : {std::pair{"--tap-words", &o.words}, std::pair{"--tap-zeta", &o.zeta}})
    if (!file->empty())
      files.push_back({flag, *file}), files.push_back({std::string(flag) + "'s sidecar", sidecar_name(*file)});
  return files;
}

// "A:B" into the production steps to tap; InputError naming --tap-steps.
std::pair<std::int64_t, std::int64_t> parse_steps(const std::string& text, const dpd::WaterConfig& cfg) {
  const std::string production = std::to_string(cfg.equilibrate + 1) + ":" + std::to_string(cfg.steps);
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError("--tap-steps: " + quote_input(text) + " is not A:B (e.g. " + production + ")");
  const IntRange range{0, static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())};
  const auto a = parse_number<std::int64_t>(std::string_view(text).substr(0, colon), "--tap-steps", range);
  const auto b = parse_number<std::int64_t>(std::string_view(text).substr(colon + 1), "--tap-steps", range);
  if (a > b) throw InputError("--tap-steps " + quote_input(text) + ": the first step is after the last");
  if (a <= cfg.equilibrate || b > cfg.steps)
    throw InputError("--tap-steps " + quote_input(text) + ": outside the production steps " + production +
                     " (the steps whose zeta the run reports)");
  return {a, b};
}

void check_file(const std::string& flag, const std::string& file) {
  const fs::path p(file);
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw InputError(flag + " " + quote_input(file) + ": is a directory");
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (!fs::is_directory(dir, ec))
    throw InputError(flag + " " + quote_input(file) + ": no directory " + quote_input(dir.string()));
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(flag + " " + quote_input(file) + ": cannot write in " + quote_input(dir.string()));
}

}  // namespace
}  // namespace simulate_taps

using namespace simulate_taps;

void TapOptions::add_to(CLI::App& app) {
  app.add_option("--tap-words", words,
                 "write the generator words of the pairs inside r_c (raw little-endian uint64, step-major, pairs "
                 "in order (i, j), i < j; see below) and FILE.json")
      ->check(non_empty_path());
  app.add_option("--tap-zeta", zeta,
                 "write the zeta of the pairs inside r_c (raw little-endian float64, the same order) and FILE.json")
      ->check(non_empty_path());
  app.add_option("--tap-steps", steps, "production steps A:B to tap (default: every production step)");
}

std::string TapOptions::given() const {
  return !words.empty() ? "--tap-words" : !zeta.empty() ? "--tap-zeta" : !steps.empty() ? "--tap-steps" : "";
}

void TapOptions::apply(dpd::WaterConfig& cfg) const {
  if (!steps.empty() && !any()) throw InputError("--tap-steps: needs --tap-words or --tap-zeta (nothing to tap)");
  if (!any()) return;
  const auto files = tap_files(*this);
  for (std::size_t k = 0; k < files.size(); ++k) {
    for (std::size_t m = 0; m < k; ++m)
      if (fs::path(files[k].second).lexically_normal() == fs::path(files[m].second).lexically_normal())
        throw InputError(files[k].first + " " + quote_input(files[k].second) + " is also " + files[m].first +
                         ": name files whose names and .json sidecars differ");
  }
  if (cfg.integrator == dpd::Integrator::shardlow || cfg.integrator == dpd::Integrator::pnhln)
    throw InputError(given() + ": --integrator " +
                     cfg.integrator_name() +
                     " draws no zeta in the pair loop; the taps need mvv or scmvv");
  const auto [a, b] = steps.empty() ? std::pair{cfg.equilibrate + 1, cfg.steps} : parse_steps(steps, cfg);
  cfg.taps.in_range_first = a, cfg.taps.in_range_last = b;
}

void TapOptions::check_paths() const {
  for (const auto& [what, file] : tap_files(*this)) check_file(what, file);
}

struct TapWriter::Output {
  std::string flag;
  bool zeta;
  AtomicFile data;
  AtomicFile side;
  std::uint64_t count = 0;  // values written
  Output(std::string f, bool z, const std::string& file)
      : flag(std::move(f)), zeta(z), data(file), side(sidecar_name(file)) {}
};

TapWriter::TapWriter(const TapOptions& o, const dpd::WaterConfig& cfg) : cfg_(cfg) {
  if (!o.words.empty()) outputs_.push_back(std::make_unique<Output>("--tap-words", false, o.words));
  if (!o.zeta.empty()) outputs_.push_back(std::make_unique<Output>("--tap-zeta", true, o.zeta));
  const int blocks = cfg.feed == rng::Feed::blocks ? 2 : 1;
  words_per_pair_ = rng::words_per_call(cfg.generator) * blocks;
}

TapWriter::~TapWriter() = default;

void TapWriter::step(const dpd::InRangeTap& tap) {
  // Raw little-endian values: this machine's byte order, checked at compile time.
  static_assert(std::endian::native == std::endian::little);
  if (tap.words_per_pair != words_per_pair_)
    throw std::logic_error("the pair loop used " + std::to_string(tap.words_per_pair) + " words a pair, not " +
                           std::to_string(words_per_pair_));
  for (auto& o : outputs_) {
    if (o->zeta)
      o->data.write(tap.zeta.data(), tap.zeta.size() * sizeof(double)), o->count += tap.zeta.size();
    else
      o->data.write(tap.words.data(), tap.words.size() * sizeof(std::uint64_t)), o->count += tap.words.size();
  }
  pairs_per_step_.push_back(tap.size());
  last_step_ = tap.step;
}

nlohmann::json TapWriter::sidecar(const dpd::RunResult& r, const Output& o) const {
  std::uint64_t pairs = 0;
  for (const std::uint64_t n : pairs_per_step_) pairs += n;
  nlohmann::json j;
  j["file"] = o.data.path().filename().string();
  j["content"] = o.zeta ? "zeta" : "words";
  j["dtype"] = o.zeta ? "float64" : "uint64";
  j["byte_order"] = "little";
  j["values_per_pair"] = o.zeta ? 1 : words_per_pair_;
  j["words_per_pair"] = words_per_pair_;
  if (!o.zeta)
    j["words"] = words_per_pair_ > rng::words_per_call(cfg_.generator)
                     ? "the block's words, then the second block's (the blocks feed)"
                     : "the block's words";
  j["generator"] = r.generator;
  j["key"] = cfg_.generator.key;
  j["seeding"] = r.seeding;
  j["seed"] = cfg_.seed;
  j["distribution"] = r.distribution;
  j["feed"] = r.feed;
  j["steps"] = {{"first", cfg_.taps.in_range_first},
                {"last", last_step_ >= 0 ? nlohmann::json(last_step_) : nlohmann::json(nullptr)},
                {"requested_last", cfg_.taps.in_range_last}};
  j["pairs_per_step"] = pairs_per_step_;
  j["pairs"] = pairs;
  j["count"] = o.count;
  j["order"] = "step-major; within a step the pairs in order (i, j), i < j, ascending by bead index";
  j["included"] = "the pairs inside r_c (r < rc), whose zeta entered the force; a step that blew up is left out";
  j["run"] = {{"scene", "water"},       {"particles", r.particles},     {"pairs", r.pairs},
              {"integrator", r.integrator}, {"dt", cfg_.dt},          {"init_seed", cfg_.init_seed},
              {"steps", cfg_.steps},     {"equilibrate", cfg_.equilibrate}, {"status", r.status.text()}};
  return j;
}

void TapWriter::commit(const dpd::RunResult& r) {
  for (auto& o : outputs_) {
    const std::string text = sidecar(r, *o).dump(2) + "\n";
    o->side.write(text.data(), text.size());
    o->data.finish(), o->side.finish();
  }
  for (auto& o : outputs_) o->data.commit(), o->side.commit();
}

}  // namespace dpdrng::cli
