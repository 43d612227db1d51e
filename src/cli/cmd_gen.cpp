// dpdrng gen: a generator's counter-mode stream, for external batteries (dieharder -g 200, PractRand stdin64).
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "dpdrng/cli/options.hpp"
#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/rng/stream.hpp"

namespace dpdrng::cli {
namespace cmd_gen {
namespace {

struct GenArgs {
  GeneratorOptions gen;
  std::string seeding = "counter";
  std::uint64_t start = 0;
  std::string count_text;  // a number of calls, or "inf"
  std::string format = "hex";

  bool endless() const { return count_text == "inf"; }
  std::uint64_t count() const { return endless() ? 0 : parse_number<std::uint64_t>(count_text, "--count"); }
};

// --count: a decimal number of calls through the one number parser, or "inf".
const CLI::Validator& count_or_inf() {
  static const CLI::Validator v(
      [](std::string& text) -> std::string {
        if (text == "inf") return "";
        std::uint64_t n = 0;
        const std::string problem = check_unsigned(text, range_of<std::uint64_t>(), n);
        return problem.empty() ? "" : problem + " or inf";
      },
      "");
  return v;
}

// Returns false when the reader has gone away (closed pipe): a normal end, not an error.
bool write_all(const void* data, std::size_t bytes) {
  if (std::fwrite(data, 1, bytes, stdout) == bytes) return true;
  if (errno == EPIPE) {
    std::clearerr(stdout);
    return false;
  }
  throw OutputError(std::string("standard output: ") + std::strerror(errno));
}

// The stream from counter `start` in blocks of 2^16 words, as long as the reader takes them: `total` words, or
// without end when `endless`. Returns false once the reader has gone away.
bool write_stream(const rng::GeneratorSpec& spec, std::uint64_t start, std::uint64_t total, bool endless, bool raw) {
  std::vector<std::uint64_t> buf(std::size_t{1} << 16);
  std::string text;
  for (std::uint64_t done = 0; endless || done < total;) {
    const std::size_t n =
        endless ? buf.size() : static_cast<std::size_t>(std::min<std::uint64_t>(buf.size(), total - done));
    rng::fill_stream(spec, start, done, std::span(buf.data(), n));
    done += n;
    if (raw) {
      // Little-endian words: this machine's byte order, checked at compile time below.
      static_assert(std::endian::native == std::endian::little);
      if (!write_all(buf.data(), n * sizeof(std::uint64_t))) return false;
      continue;
    }
    text.clear();
    char line[24];
    for (std::size_t k = 0; k < n; ++k) {
      std::snprintf(line, sizeof line, "%016llx\n", static_cast<unsigned long long>(buf[k]));
      text += line;
    }
    if (!write_all(text.data(), text.size())) return false;
  }
  return true;
}

void run_gen(const GenArgs& a) {
  const rng::GeneratorSpec spec = a.gen.spec();
  const std::uint64_t count = a.count();
  if (rng::parse_seeding(a.seeding) != rng::Seeding::counter)
    throw InputError("gen writes standalone streams: --seeding must be 'counter' (pair seedings need a DPD run)");
  // Counter-mode generators hash start+i: past 2^64 - 1 the counter would wrap to 0 and repeat the stream's start.
  if (rng::find_generator(spec.name).counter_stream && count > 0 &&
      a.start > std::numeric_limits<std::uint64_t>::max() - (count - 1))
    throw InputError("--start " + std::to_string(a.start) + " with --count " + std::to_string(count) +
                     ": the counter would pass 2^64 - 1 and wrap to 0");
  const bool raw = a.format == "raw";
  if (raw && isatty(STDOUT_FILENO)) throw InputError("refusing to write raw binary to a terminal; pipe or redirect it");
  const std::uint64_t per_call = rng::words_per_call(spec);
  if (count > std::numeric_limits<std::uint64_t>::max() / per_call)
    throw InputError("--count " + std::to_string(count) + ": " + spec.name + " writes " + std::to_string(per_call) +
                     " words a call, more than 2^64 - 1 words in all");
  begin_work();
  // A closed pipe is the reader's way to say "enough" (`| head`, a battery that has its sample): the write
  // fails with EPIPE and gen ends normally, with exit 0, rather than dying of the signal.
  std::signal(SIGPIPE, SIG_IGN);
  if (!write_stream(spec, a.start, count * per_call, a.endless(), raw)) return;
  if (std::fflush(stdout) != 0 && errno != EPIPE) throw OutputError(std::string("standard output: ") + std::strerror(errno));
}

const bool registered = register_command(10, [](CLI::App& root) {
  auto args = std::make_shared<GenArgs>();
  CLI::App* sub = root.add_subcommand("gen", "write a generator's counter-mode stream (hex lines or raw binary)");
  sub->footer(
      "Call i hashes counter start+i. tea32: low word -> x0, high -> x1, output (x1'<<32)|x0'.\n"
      "tea64: x0 = start+i, x1 = 0, outputs a then b. philox4x32: counter (start+i, 0), key (k0, k1),\n"
      "outputs (c1:c0) then (c3:c2). threefry2x64: counter (start+i, 0), key (k1:k0, k3:k2).\n"
      "splitmix64: the published stream seeded with start. saru: Saru's two-seed constructor on\n"
      "(lo32, hi32) of start+i, output (u2<<32)|u1 from its first two steps. mt19937: std::mt19937 seeded with\n"
      "lo32(start)^hi32(start), two draws a word, high first.\n"
      "raw = little-endian 64-bit words (dieharder -g 200, PractRand stdin64). --count inf streams until the\n"
      "reader closes the pipe (dpdrng gen --count inf --format raw | RNG_test stdin64): a closed pipe ends gen\n"
      "quietly with exit 0.");
  args->gen.add_to(*sub);
  sub->add_option("--seeding", args->seeding, "only 'counter' makes a standalone stream")->capture_default_str();
  // CLI11 reads "-1" into an unsigned as 2^64-1: a negative count would run (almost) forever.
  add_integer(*sub, "--start", args->start, "first counter value (or seed for splitmix64/mt19937)");
  // Endless, the counter would wrap past 2^64 - 1 calls: centuries of output, beyond any reader.
  sub->add_option("--count", args->count_text,
                  "number of generator calls, or inf: write until the reader closes the pipe (then exit 0)")
      ->check(count_or_inf())
      ->required();
  sub->add_option("--format", args->format, "hex (one 16-digit word a line) or raw")
      ->check(CLI::IsMember({"hex", "raw"}))
      ->capture_default_str();
  sub->callback([args] { run_gen(*args); });
});

}  // namespace
}  // namespace cmd_gen
}  // namespace dpdrng::cli
