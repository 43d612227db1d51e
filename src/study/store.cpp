#include "dpdrng/study/store.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/version.hpp"

namespace dpdrng::study {
namespace fs = std::filesystem;
namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(p.string() + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The cell files present (hidden temporaries left by a killed run excluded), in name order.
std::vector<fs::path> cell_files(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::exists(dir / "cells"))
    for (const auto& e : fs::directory_iterator(dir / "cells"))
      if (e.path().extension() == ".h5" && e.path().filename().string()[0] != '.') files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
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

// Reads a whole cell file, checking its checksum and that it belongs to the config with `hash`; throws with the
// reason.
CellResult read_cell_file(const fs::path& p, const std::string& hash) {
  check_seal(p);
  h5::Handle f = h5::open_file(p.string());
  const auto attrs = h5::read_attributes(f.id());
  const auto it = attrs.find("config_hash");
  const std::string* stored = it == attrs.end() ? nullptr : std::get_if<std::string>(&it->second);
  if (!stored) throw std::runtime_error("no config_hash attribute");
  if (*stored != hash) throw std::runtime_error("written by another config (hash " + *stored + ")");
  h5::Handle g = h5::open_group(f.id(), "cell");
  return read_cell(g.id());
}

}  // namespace

std::string read_whole_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open it");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path Store::cell_path(const Cell& cell) const { return dir_ / "cells" / (cell.id() + ".h5"); }

std::string read_store_hash(const fs::path& dir) {
  const fs::path p = dir / "config.hash";
  if (!fs::exists(p)) return "";
  std::string h = read_text(p);
  while (!h.empty() && (h.back() == '\n' || h.back() == ' ')) h.pop_back();
  return h;
}

void open_store_directory(const fs::path& dir, const std::string& config_file, const std::string& source_text,
                          const std::string& hash) {
  const std::string existing = read_store_hash(dir);
  if (!existing.empty() && existing != hash)
    throw InputError(dir.string() + " holds results of a different config (hash " + existing + ", this config " +
                     hash + "): choose another --out, or delete the directory to start afresh");
  fs::create_directories(dir / "cells");
  if (existing.empty()) {
    write_file_atomically(dir / config_file, source_text);
    write_file_atomically(dir / "config.hash", hash + "\n");
  }
}

std::string Store::stored_hash() const { return read_store_hash(dir_); }

void Store::open_for(const StudyConfig& config) {
  open_store_directory(dir_, "study.toml", config.source_text, config.hash);
}

StudyConfig Store::stored_config() const {
  const fs::path p = dir_ / "study.toml";
  if (!fs::exists(p)) throw InputError(dir_.string() + " is not a study directory (no study.toml)");
  StudyConfig c = parse_config(read_text(p), p.string());
  const std::string h = stored_hash();
  if (!h.empty() && h != c.hash)
    throw InputError(p.string() + " does not match " + (dir_ / "config.hash").string() +
                     " (edited after the run?)");
  return c;
}

Store::State Store::state(const Cell& cell, std::string* reason) const {
  const fs::path p = cell_path(cell);
  if (!fs::exists(p)) return State::missing;
  // The whole record is read: a file cut short by hand or a full disk must not pass for a finished cell.
  try {
    std::lock_guard lk(h5::lock());
    const CellResult r = read_cell_file(p, stored_hash());
    if (r.cell.id() != cell.id()) throw std::runtime_error("holds cell " + r.cell.id());
    return State::stored;
  } catch (const std::exception& e) {
    if (reason) *reason = e.what();
    return State::unreadable;
  }
}

void Store::save(const CellResult& r) {
  const fs::path p = cell_path(r.cell);
  std::string bytes;
  try {
    std::lock_guard lk(h5::lock());
    h5::Handle f = h5::create_memory_file(kSealBytes);
    h5::write_attribute(f.id(), "config_hash", stored_hash());
    h5::Handle g = h5::create_group(f.id(), "cell");
    write_cell(g.id(), r);
    bytes = h5::image(f.id());
    seal_image(bytes);
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const OutputError*>(&e)) throw;
    throw OutputError(p.string() + ": " + e.what());
  }
  write_file_atomically(p, bytes);
}

CellResult Store::load(const Cell& cell) const {
  std::lock_guard lk(h5::lock());
  return read_cell_file(cell_path(cell), stored_hash());
}

std::vector<CellResult> Store::load_all(std::vector<UnreadableCell>* unreadable) const {
  std::vector<CellResult> out;
  const std::string hash = stored_hash();
  std::lock_guard lk(h5::lock());
  for (const auto& p : cell_files(dir_)) {
    try {
      out.push_back(read_cell_file(p, hash));
      if (out.back().cell.id() != p.stem().string()) {
        const std::string held = out.back().cell.id();
        out.pop_back();
        throw std::runtime_error("holds cell " + held);
      }
    } catch (const std::exception& e) {
      // `study run` recomputes these; the report lists them by name.
      if (unreadable) unreadable->push_back({p, e.what()});
    }
  }
  return out;
}

std::size_t Store::assemble(const StudyConfig& config) const {
  const std::vector<fs::path> files = cell_files(dir_);
  std::size_t n = 0;
  std::string bytes;
  {
    std::lock_guard lk(h5::lock());
    h5::Handle dst = h5::create_memory_file();
    h5::write_attribute(dst.id(), "study", config.name);
    h5::write_attribute(dst.id(), "description", config.description);
    h5::write_attribute(dst.id(), "config_toml", config.source_text);
    h5::write_attribute(dst.id(), "config_canonical_json", config.canonical().dump());
    h5::write_attribute(dst.id(), "config_hash", config.hash);
    h5::write_attribute(dst.id(), "dpdrng_version", std::string(dpdrng::kVersion));
    h5::Handle cells = h5::create_group(dst.id(), "cells");
    for (const auto& p : files) {
      try {
        // Only a whole cell of this config, filed under its own id, is part of the store.
        check_seal(p);
        h5::Handle src = h5::open_file(p.string());
        const auto attrs = h5::read_attributes(src.id());
        auto it = attrs.find("config_hash");
        if (it == attrs.end() || std::get<std::string>(it->second) != config.hash) continue;
        {
          h5::Handle g = h5::open_group(src.id(), "cell");
          if (read_cell(g.id()).cell.id() != p.stem().string()) continue;
        }
        h5::copy(src.id(), "cell", cells.id(), p.stem().string());
        ++n;
      } catch (const std::exception&) {
        continue;  // unreadable: not part of the store
      }
    }
    h5::write_attribute(dst.id(), "cells_stored", static_cast<std::int64_t>(n));
    bytes = h5::image(dst.id());
  }
  write_file_atomically(study_file(), bytes);
  return n;
}

std::size_t Store::merge_from(const Store& other, std::vector<UnreadableCell>* refused) {
  if (other.stored_hash() != stored_hash())
    throw InputError(other.dir().string() + " was made with a different config than " + dir_.string() +
                     " (hash " + other.stored_hash() + " vs " + stored_hash() + ")");
  std::size_t n = 0;
  if (!fs::exists(other.dir() / "cells")) return 0;
  for (const auto& e : fs::directory_iterator(other.dir() / "cells")) {
    const fs::path& src = e.path();
    if (src.extension() != ".h5" || src.filename().string()[0] == '.') continue;
    const fs::path dst = dir_ / "cells" / src.filename();
    if (fs::exists(dst)) continue;
    // Only a whole cell of this config, filed under its own id, is copied.
    try {
      std::lock_guard lk(h5::lock());
      const CellResult r = read_cell_file(src, stored_hash());
      if (r.cell.id() != src.stem().string()) throw std::runtime_error("holds cell " + r.cell.id());
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

}  // namespace dpdrng::study
