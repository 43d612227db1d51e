// The study store's cell files. Mode 0 (first byte even): arbitrary bytes as a cell file, seeded with real
// ones: every file is either read whole or listed as unreadable with a reason, never a crash (a damaged file
// must not reach HDF5's parser; see the checksum block in store.cpp). Mode 1: a cell record built from the
// bytes (names as the measurements spell them, any doubles, any text without NUL) goes through Store::save and
// back: it must come back equal, bit for bit, or be refused without leaving a file behind.
#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "dpdrng/study/store.hpp"
#include "fuzz_check.hpp"

using namespace dpdrng;
using fuzz::require;
namespace fs = std::filesystem;

namespace {

// The seed cells were written by fuzz/make_cell_seeds.cpp under this config hash and cell id.
constexpr const char* kHash = "fuzz";
constexpr const char* kCellId = "tea32-r01-gauss-distance-dt0.04-rep00";

const fs::path& store_dir() {
  static const fs::path dir = [] {
    // fuzz/run.sh points DPDRNG_FUZZ_TMP at memory (Store::save syncs every file, which a disk makes slow) and
    // removes it afterwards: libFuzzer ends without running exit handlers.
    const char* tmp = std::getenv("DPDRNG_FUZZ_TMP");
    const fs::path d = (tmp ? fs::path(tmp) : fs::temp_directory_path()) / ("cell-" + std::to_string(::getpid()));
    fs::create_directories(d / "cells");
    std::ofstream(d / "config.hash") << kHash << "\n";
    return d;
  }();
  return dir;
}

void clear_cells() {
  for (const auto& e : fs::directory_iterator(store_dir() / "cells")) fs::remove(e.path());
}

void raw_file(const std::uint8_t* data, std::size_t size) {
  const fs::path file = store_dir() / "cells" / (std::string(kCellId) + ".h5");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const study::Store store(store_dir());
  std::vector<study::UnreadableCell> unreadable;
  const auto cells = store.load_all(&unreadable);
  require(cells.size() + unreadable.size() == 1, "a cell file neither read nor listed as unreadable");
  if (!unreadable.empty()) require(!unreadable.front().reason.empty(), "an unreadable cell without a reason");
  if (!cells.empty()) {
    require(cells.front().cell.id() == kCellId, "a cell read under another id");
    require(store.state(cells.front().cell) == study::Store::State::stored, "state() disagrees with load_all");
  }
}

std::string word(FuzzedDataProvider& in, std::size_t max) {
  static constexpr char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789_";
  std::string s(in.ConsumeIntegralInRange<std::size_t>(1, max), 'a');
  for (char& c : s) c = kChars[in.ConsumeIntegralInRange<std::size_t>(0, sizeof kChars - 2)];
  return s;
}

// One to three words joined by `sep`, as "chi2.x.fraction" or "chi2/x/p".
std::string name(FuzzedDataProvider& in, char sep) {
  std::string s = word(in, 8);
  for (int k = in.ConsumeIntegralInRange(0, 2); k > 0; --k) s += sep + word(in, 8);
  return s;
}

std::string text(FuzzedDataProvider& in) {
  std::string s = in.ConsumeRandomLengthString(64);
  for (char& c : s)
    if (c == '\0') c = '?';
  return s;
}

double any_double(FuzzedDataProvider& in) {
  const std::uint64_t bits = in.ConsumeIntegral<std::uint64_t>();
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}

study::CellResult record(FuzzedDataProvider& in) {
  study::CellResult r;
  r.cell.generator = word(in, 12);
  r.cell.rounds = in.ConsumeIntegralInRange(0, 64);
  r.cell.distribution = in.PickValueInArray({rng::Distribution::gauss, rng::Distribution::uniform});
  r.cell.feed = in.PickValueInArray(rng::kFeeds);
  r.cell.seeding = in.PickValueInArray({rng::Seeding::distance, rng::Seeding::pair_step});
  r.cell.dt = in.ConsumeFloatingPointInRange(1e-6, 1.0);
  r.cell.replica = in.ConsumeIntegralInRange(0, 99);
  r.cell.reference = in.ConsumeBool();
  r.cell.nist = in.ConsumeBool();
  r.cell.seed = in.ConsumeIntegral<std::uint64_t>();
  r.status = in.PickValueInArray({study::CellStatus::ok, study::CellStatus::unstable, study::CellStatus::disrupted,
                                   study::CellStatus::failed});
  r.unstable_step = in.ConsumeIntegral<long>();
  r.reason = text(in);
  r.seconds = any_double(in);
  for (int k = in.ConsumeIntegralInRange(0, 6); k > 0; --k) r.scalars[name(in, '.')] = any_double(in);
  for (int k = in.ConsumeIntegralInRange(0, 3); k > 0; --k) r.notes[name(in, '.')] = text(in);
  for (int k = in.ConsumeIntegralInRange(0, 4); k > 0; --k) {
    auto& v = r.series[name(in, '/')];
    for (int n = in.ConsumeIntegralInRange(0, 12); n > 0; --n) v.push_back(any_double(in));
  }
  for (int k = in.ConsumeIntegralInRange(0, 2); k > 0; --k) {
    study::h5::Matrix m;
    m.rows = in.ConsumeIntegralInRange<std::size_t>(1, 4);
    m.cols = in.ConsumeIntegralInRange<std::size_t>(1, 4);
    for (std::size_t n = 0; n < m.rows * m.cols; ++n) m.data.push_back(any_double(in));
    r.matrices[name(in, '/')] = m;
  }
  for (int k = in.ConsumeIntegralInRange(0, 2); k > 0; --k) {
    auto& v = r.strings[name(in, '/')];
    for (int n = in.ConsumeIntegralInRange(0, 4); n > 0; --n) v.push_back(text(in));
  }
  return r;
}

void round_trip(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const study::CellResult r = record(in);
  study::Store store(store_dir());
  try {
    store.save(r);
  } catch (const std::exception&) {
    // Refused (a reserved scalar name, a dataset where another needs a group): nothing may be left behind.
    for (const auto& e : fs::directory_iterator(store_dir() / "cells"))
      fuzz::fail("a refused save left " + e.path().filename().string());
    return;
  }
  std::vector<study::UnreadableCell> unreadable;
  const auto cells = store.load_all(&unreadable);
  require(unreadable.empty(), unreadable.empty() ? "" : "a saved cell is unreadable: " + unreadable[0].reason);
  require(cells.size() == 1, "a saved cell was not read back");
  const study::CellResult& b = cells.front();
  require(b.cell.id() == r.cell.id() && b.cell.generator == r.cell.generator && b.cell.rounds == r.cell.rounds &&
              b.cell.distribution == r.cell.distribution && b.cell.feed == r.cell.feed &&
              b.cell.seeding_name() == r.cell.seeding_name() &&
              same(b.cell.dt, r.cell.dt) && b.cell.replica == r.cell.replica &&
              b.cell.reference == r.cell.reference && b.cell.nist == r.cell.nist && b.cell.seed == r.cell.seed,
          "the cell's description changed on the way");
  require(b.status == r.status && b.unstable_step == r.unstable_step && b.reason == r.reason &&
              same(b.seconds, r.seconds),
          "status, reason or time changed on the way");
  require(b.scalars.size() == r.scalars.size(), "scalars lost or gained");
  for (const auto& [k, v] : r.scalars)
    require(b.scalars.count(k) && same(b.scalars.at(k), v), "scalar " + k + " changed on the way");
  require(b.notes == r.notes, "notes changed on the way");
  require(b.series.size() == r.series.size(), "series lost or gained");
  for (const auto& [k, v] : r.series) require(b.series.count(k) && same(b.series.at(k), v), "series " + k + " changed");
  require(b.matrices.size() == r.matrices.size(), "matrices lost or gained");
  for (const auto& [k, m] : r.matrices)
    require(b.matrices.count(k) && b.matrices.at(k).rows == m.rows && b.matrices.at(k).cols == m.cols &&
                same(b.matrices.at(k).data, m.data),
            "matrix " + k + " changed");
  require(b.strings == r.strings, "string lists changed on the way");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  clear_cells();
  if (size == 0 || data[0] % 2 == 0)
    raw_file(data, size);
  else
    round_trip(data + 1, size - 1);
  return 0;
}
