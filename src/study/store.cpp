#include "dpdrng/study/store.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/observables.hpp"
#include "dpdrng/version.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;

std::string read_whole_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open it");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

namespace store_files {

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(p.string() + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every cell file starts with a 512-byte HDF5 user block holding a checksum of the rest, written after HDF5 has
// closed the file: "dpdrng-cell 1 fnv1a64 <16 hex digits> <bytes>\n", then zeros. HDF5 skips the block (h5py and
// h5dump read the file as usual). A file is handed to HDF5 only once its bytes match: HDF5's own parser is not
// robust against damaged files (a flipped length in a string heap made it copy 21 GB), and a file damaged on
// disk must be "unreadable", not a crash.
constexpr std::size_t kSealBytes = 512;
constexpr std::string_view kSealMagic = "dpdrng-cell 1 fnv1a64 ";

std::string seal_of(std::string_view payload) {
  std::string seal = std::string(kSealMagic) + fnv1a64_hex(std::string(payload)) + " " +
                     std::to_string(payload.size()) + "\n";
  seal.resize(kSealBytes, '\0');
  return seal;
}

// Fills the image's block with the checksum of the rest.
void seal_image(std::string& bytes) {
  if (bytes.size() <= kSealBytes) throw std::runtime_error("HDF5 wrote no data after the checksum block");
  const std::string seal = seal_of(std::string_view(bytes).substr(kSealBytes));
  bytes.replace(0, kSealBytes, seal);
}

// Throws with the reason when the file's bytes do not match its checksum block.
void check_seal(const fs::path& p) {
  const std::string bytes = read_whole_file(p);
  if (bytes.size() < kSealBytes || bytes.compare(0, kSealMagic.size(), kSealMagic) != 0)
    throw std::runtime_error(bytes.size() >= 8 && bytes.compare(0, 4, "\x89HDF") == 0
                                 ? "no checksum block: written by an older dpdrng, or not by dpdrng"
                                 : "not a dpdrng cell file");
  const std::string_view payload = std::string_view(bytes).substr(kSealBytes);
  if (bytes.compare(0, kSealBytes, seal_of(payload)) != 0)
    throw std::runtime_error("its bytes do not match its checksum (cut short, extended or altered after it was "
                             "written)");
}

// Opens a cell file after checking its checksum and that it belongs to the config with `hash`; throws with the
// reason.
h5::Handle open_cell_file(const fs::path& p, const std::string& hash) {
  check_seal(p);
  h5::Handle f = h5::open_file(p.string());
  const auto attrs = h5::read_attributes(f.id());
  const auto it = attrs.find("config_hash");
  const std::string* stored = it == attrs.end() ? nullptr : std::get_if<std::string>(&it->second);
  if (!stored) throw std::runtime_error("no config_hash attribute");
  if (*stored != hash) throw std::runtime_error("written by another config (hash " + *stored + ")");
  return f;
}

// A checked cell file whose record `read` has read whole, open for copying; throws with the reason.
h5::Handle open_record(const fs::path& p, const std::string& hash, const CellStore::Reader& read) {
  h5::Handle f = open_cell_file(p, hash);
  h5::Handle g = h5::open_group(f.id(), "cell");
  const std::string held = read(g.id());
  if (held != p.stem().string()) throw std::runtime_error("holds cell " + held);
  return f;
}

// The unit of every number among a record's attributes (its datasets carry their own).
void collect_units(hid_t cell, std::map<std::string, std::string>& units) {
  for (const auto& [name, value] : h5::read_attributes(cell))
    if (!std::holds_alternative<std::string>(value))
      if (const std::string u = unit_of(name); !u.empty()) units[name] = u;
}

std::string read_store_hash(const fs::path& dir) {
  const fs::path p = dir / "config.hash";
  if (!fs::exists(p)) return "";
  std::string h = read_text(p);
  while (!h.empty() && (h.back() == '\n' || h.back() == ' ')) h.pop_back();
  return h;
}

}  // namespace store_files

std::string CellStore::hash() const { return store_files::read_store_hash(dir_); }

void CellStore::open(const std::string& config_file, const std::string& source_text, const std::string& hash) const {
  const std::string existing = this->hash();
  if (!existing.empty() && existing != hash)
    throw InputError(dir_.string() + " holds results of a different config (hash " + existing + ", this config " +
                     hash + "): choose another --out, or delete the directory to start afresh");
  fs::create_directories(dir_ / "cells");
  if (existing.empty()) {
    write_file_atomically(dir_ / config_file, source_text);
    write_file_atomically(dir_ / "config.hash", hash + "\n");
  }
}

std::vector<fs::path> CellStore::files() const {
  std::vector<fs::path> files;
  if (fs::exists(dir_ / "cells"))
    for (const auto& e : fs::directory_iterator(dir_ / "cells"))
      if (e.path().extension() == ".h5" && e.path().filename().string()[0] != '.') files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

void CellStore::read(const fs::path& p, const Reader& read) const { store_files::open_record(p, hash(), read); }

CellStore::State CellStore::state(const std::string& id, const Reader& read, std::string* reason) const {
  const fs::path p = cell_path(id);
  if (!fs::exists(p)) return State::missing;
  // The whole record is read: a file cut short by hand or a full disk must not pass for a finished cell.
  try {
    std::lock_guard lk(h5::lock());
    this->read(p, read);
    return State::stored;
  } catch (const std::exception& e) {
    if (reason) *reason = e.what();
    return State::unreadable;
  }
}

void CellStore::save(const std::string& id, const Writer& write) const {
  const fs::path p = cell_path(id);
  std::string bytes;
  try {
    std::lock_guard lk(h5::lock());
    h5::Handle f = h5::create_memory_file(store_files::kSealBytes);
    h5::write_attribute(f.id(), "config_hash", hash());
    h5::Handle g = h5::create_group(f.id(), "cell");
    write(g.id());
    bytes = h5::image(f.id());
    store_files::seal_image(bytes);
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const OutputError*>(&e)) throw;
    throw OutputError(p.string() + ": " + e.what());
  }
  write_file_atomically(p, bytes);
}

std::size_t CellStore::assemble(const StoreIdentity& identity, const Reader& read) const {
  const std::map<std::string, h5::Attribute> attributes{{"study", identity.study},
                                                        {"description", identity.description},
                                                        {"config_toml", identity.config_toml},
                                                        {"config_canonical_json", identity.config_canonical_json},
                                                        {"config_hash", identity.config_hash},
                                                        {"dpdrng_version", std::string(dpdrng::kVersion)}};
  std::size_t n = 0;
  std::string bytes;
  {
    std::lock_guard lk(h5::lock());
    h5::Handle dst = h5::create_memory_file();
    for (const auto& [name, value] : attributes) h5::write_attribute(dst.id(), name, value);
    h5::Handle cells = h5::create_group(dst.id(), "cells");
    std::map<std::string, std::string> units;
    const std::string config_hash = hash();
    for (const auto& p : files()) {
      try {
        // Only a whole cell of this config, filed under its own id, is part of the store.
        h5::Handle src = store_files::open_record(p, config_hash, read);
        h5::copy(src.id(), "cell", cells.id(), p.stem().string());
        h5::Handle g = h5::open_group(src.id(), "cell");
        store_files::collect_units(g.id(), units);
        ++n;
      } catch (const std::exception&) {
        continue;  // unreadable: not part of the store
      }
    }
    h5::write_attribute(dst.id(), "cells_stored", static_cast<std::int64_t>(n));
    h5::Handle u = h5::create_group(dst.id(), "units");
    for (const auto& [name, unit] : units) h5::write_attribute(u.id(), name, unit);
    bytes = h5::image(dst.id());
  }
  write_file_atomically(study_file(), bytes);
  return n;
}

std::size_t CellStore::merge_from(const CellStore& other, const Reader& read,
                                  std::vector<UnreadableCell>* refused) const {
  if (other.hash() != hash())
    throw InputError(other.dir().string() + " was made with a different config than " + dir_.string() +
                     " (hash " + other.hash() + " vs " + hash() + ")");
  std::size_t n = 0;
  for (const fs::path& src : other.files()) {
    const fs::path dst = dir_ / "cells" / src.filename();
    if (fs::exists(dst)) continue;
    // Only a whole cell of this config, filed under its own id, is copied.
    try {
      std::lock_guard lk(h5::lock());
      this->read(src, read);
    } catch (const std::exception& e) {
      if (refused) refused->push_back({src, e.what()});
      continue;
    }
    std::string bytes;
    try {
      bytes = read_whole_file(src);
    } catch (const std::exception& e) {
      throw InputError(src.string() + ": " + e.what());
    }
    write_file_atomically(dst, bytes);
    ++n;
  }
  return n;
}

namespace store_files {

// A study cell's record, returning the id it holds.
std::string read_study_cell(hid_t g, CellResult* out) {
  CellResult r = read_cell(g);
  std::string id = r.cell.id();
  if (out) *out = std::move(r);
  return id;
}

}  // namespace store_files

void Store::open_for(const StudyConfig& config) { cells_.open("study.toml", config.source_text, config.hash); }

StudyConfig Store::stored_config() const {
  const fs::path p = dir() / "study.toml";
  if (!fs::exists(p)) throw InputError(dir().string() + " is not a study directory (no study.toml)");
  StudyConfig c = parse_config(store_files::read_text(p), p.string());
  const std::string h = cells_.hash();
  if (!h.empty() && h != c.hash)
    throw InputError(p.string() + " does not match " + (dir() / "config.hash").string() +
                     " (edited after the run?)");
  return c;
}

Store::State Store::state(const Cell& cell, std::string* reason) const {
  return cells_.state(cell.id(), [](hid_t g) { return store_files::read_study_cell(g, nullptr); }, reason);
}

void Store::save(const CellResult& r) {
  cells_.save(r.cell.id(), [&r](hid_t g) { write_cell(g, r); });
}

CellResult Store::load(const Cell& cell) const {
  CellResult r;
  std::lock_guard lk(h5::lock());
  cells_.read(cells_.cell_path(cell.id()), [&r](hid_t g) { return store_files::read_study_cell(g, &r); });
  return r;
}

std::vector<CellResult> Store::load_all(std::vector<UnreadableCell>* unreadable) const {
  std::vector<CellResult> out;
  std::lock_guard lk(h5::lock());
  for (const auto& p : cells_.files()) {
    try {
      CellResult r;
      cells_.read(p, [&r](hid_t g) { return store_files::read_study_cell(g, &r); });
      out.push_back(std::move(r));
    } catch (const std::exception& e) {
      // `study run` recomputes these; the report lists them by name.
      if (unreadable) unreadable->push_back({p, e.what()});
    }
  }
  return out;
}

std::size_t Store::assemble(const StudyConfig& config) const {
  return cells_.assemble({config.name, config.description, config.source_text, config.canonical().dump(), config.hash},
                         [](hid_t g) { return store_files::read_study_cell(g, nullptr); });
}

std::size_t Store::merge_from(const Store& other, std::vector<UnreadableCell>* refused) {
  return cells_.merge_from(other.cells_, [](hid_t g) { return store_files::read_study_cell(g, nullptr); }, refused);
}

}  // namespace dpdrng::study
