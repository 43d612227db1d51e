#include "dpdrng/study/cell_result.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dpdrng/common/numbers.hpp"
#include "dpdrng/study/observables.hpp"

namespace dpdrng::study {
namespace cell_record {

// A number stored as an integer must come back as the same double: whole, within 2^53, and not −0.
bool whole(double v) {
  return std::isfinite(v) && v == std::trunc(v) && std::abs(v) <= 9007199254740992.0 && !(v == 0 && std::signbit(v));
}

bool all_whole(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return whole(x); });
}

// A count as an integer; any other number, or a count that is not a whole number (NaN where it could not be
// counted), as a double.
h5::Attribute number(const std::string& key, double v) {
  if (is_count(key) && whole(v)) return static_cast<std::int64_t>(v);
  return v;
}

// A dataset of numbers with its unit, integers when it is a count.
void write_numbers(hid_t g, const std::string& key, const h5::Matrix& m) {
  h5::write_matrix(g, key, m, is_count(key) && all_whole(m.data));
  if (const std::string unit = unit_of(key); !unit.empty()) h5::write_attribute(g, key, "unit", unit);
}

// Seeds are unsigned 64-bit integers; a record may hold one as its decimal text.
std::uint64_t read_seed(const std::map<std::string, h5::Attribute>& a) {
  const auto it = a.find("cell.seed");
  if (it == a.end()) throw std::runtime_error("cell record lacks attribute cell.seed");
  if (const auto* u = std::get_if<std::uint64_t>(&it->second)) return *u;
  if (const auto* s = std::get_if<std::string>(&it->second)) return parse_number<std::uint64_t>(*s, "cell.seed");
  throw std::runtime_error("cell record attribute cell.seed has the wrong type");
}

// Scalars with '/' in their name stay flat attributes on the cell group: one place to read them all.
void read_datasets(hid_t group, const std::string& prefix, CellResult& r) {
  for (const auto& name : h5::list(group)) {
    if (h5::is_group(group, name)) {
      h5::Handle sub = h5::open_group(group, name);
      read_datasets(sub.id(), prefix + name + "/", r);
      continue;
    }
    const std::string key = prefix + name;
    if (h5::is_string_dataset(group, name)) {
      r.strings[key] = h5::read_strings(group, name);
      continue;
    }
    const auto dims = h5::shape(group, name);
    auto data = h5::read_doubles(group, name);
    if (dims.size() == 2)
      r.matrices[key] = h5::Matrix{dims[0], dims[1], std::move(data)};
    else
      r.series[key] = std::move(data);
  }
}

template <class T>
T get(const std::map<std::string, h5::Attribute>& a, const std::string& name) {
  auto it = a.find(name);
  if (it == a.end()) throw std::runtime_error("cell record lacks attribute " + name);
  if (const T* v = std::get_if<T>(&it->second)) return *v;
  throw std::runtime_error("cell record attribute " + name + " has the wrong type");
}

// "stream" belongs to the reference and only to it; a hash cell names its pair seeding.
rng::Seeding read_seeding(const std::string& text, bool reference) {
  if (reference != (text == "stream"))
    throw std::runtime_error("cell record has seeding '" + text + "' for a " +
                             (reference ? "reference" : "hash") + " cell");
  return reference ? rng::Seeding::distance : rng::parse_seeding(text);
}

}  // namespace cell_record

std::string_view to_string(CellStatus s) {
  switch (s) {
    case CellStatus::ok: return "ok";
    case CellStatus::unstable: return "unstable";
    case CellStatus::disrupted: return "disrupted";
    case CellStatus::failed: return "failed";
  }
  return "?";
}

CellStatus parse_cell_status(std::string_view text) {
  for (const CellStatus s : {CellStatus::ok, CellStatus::unstable, CellStatus::disrupted, CellStatus::failed})
    if (text == to_string(s)) return s;
  throw std::runtime_error("cell record has an unknown status '" + std::string(text) + "'");
}

void write_cell(hid_t g, const CellResult& r) {
  const Cell& c = r.cell;
  h5::write_attribute(g, "cell.id", c.id());
  h5::write_attribute(g, "cell.generator", c.generator);
  h5::write_attribute(g, "cell.rounds", std::int64_t{c.rounds});
  h5::write_attribute(g, "cell.distribution", std::string(rng::to_string(c.distribution)));
  h5::write_attribute(g, "cell.feed", std::string(rng::to_string(c.feed)));
  h5::write_attribute(g, "cell.seeding", c.seeding_name());
  h5::write_attribute(g, "cell.dt", c.dt);
  // Only when the sweep names one: cells of studies without the factor keep their records byte for byte.
  if (!c.integrator.empty()) h5::write_attribute(g, "cell.integrator", c.integrator);
  if (c.gamma > 0) h5::write_attribute(g, "cell.gamma", c.gamma);
  // A plug-in's identity: the digest of the library that made the cell.
  if (rng::is_plugin(c.generator)) h5::write_attribute(g, "cell.generator_sha256", rng::load_plugin(c.generator).sha256);
  h5::write_attribute(g, "cell.replica", std::int64_t{c.replica});
  h5::write_attribute(g, "cell.reference", std::int64_t{c.reference});
  h5::write_attribute(g, "cell.nist", std::int64_t{c.nist});
  h5::write_attribute(g, "cell.seed", c.seed);
  h5::write_attribute(g, "status", std::string(to_string(r.status)));
  h5::write_attribute(g, "unstable_step", std::int64_t{r.unstable_step});
  h5::write_attribute(g, "reason", r.reason);
  h5::write_attribute(g, "seconds", r.seconds);
  for (const auto& [k, v] : r.scalars) {
    // read_cell takes these names for the record's own fields: a scalar under one would come back as something else.
    if (k.empty() || k.rfind("cell.", 0) == 0 || k.rfind("note.", 0) == 0 || k == "status" || k == "unstable_step" ||
        k == "reason" || k == "seconds")
      throw std::invalid_argument("cell scalar name '" + k + "' is empty or reserved");
    h5::write_attribute(g, k, cell_record::number(k, v));
  }
  for (const auto& [k, v] : r.notes) h5::write_attribute(g, "note." + k, v);
  for (const auto& [k, v] : r.series) cell_record::write_numbers(g, k, h5::Matrix{v.size(), 0, v});
  for (const auto& [k, v] : r.matrices) cell_record::write_numbers(g, k, v);
  for (const auto& [k, v] : r.strings) h5::write_strings(g, k, v);
}

CellResult read_cell(hid_t g) {
  using namespace cell_record;
  const auto a = h5::read_attributes(g);
  CellResult r;
  Cell& c = r.cell;
  c.generator = get<std::string>(a, "cell.generator");
  c.rounds = static_cast<int>(get<std::int64_t>(a, "cell.rounds"));
  c.distribution = rng::parse_distribution(get<std::string>(a, "cell.distribution"));
  // A store written without the feed holds halves cells.
  if (a.count("cell.feed")) c.feed = rng::parse_feed(get<std::string>(a, "cell.feed"));
  c.dt = get<double>(a, "cell.dt");
  if (a.count("cell.integrator")) c.integrator = get<std::string>(a, "cell.integrator");
  if (a.count("cell.gamma")) c.gamma = get<double>(a, "cell.gamma");
  c.replica = static_cast<int>(get<std::int64_t>(a, "cell.replica"));
  c.reference = get<std::int64_t>(a, "cell.reference") != 0;
  c.seeding = read_seeding(get<std::string>(a, "cell.seeding"), c.reference);
  c.nist = get<std::int64_t>(a, "cell.nist") != 0;
  c.seed = cell_record::read_seed(a);
  r.status = parse_cell_status(get<std::string>(a, "status"));
  r.unstable_step = static_cast<long>(get<std::int64_t>(a, "unstable_step"));
  r.reason = get<std::string>(a, "reason");
  r.seconds = get<double>(a, "seconds");
  for (const auto& [k, v] : a) {
    if (k.rfind("cell.", 0) == 0 || k == "status" || k == "unstable_step" || k == "reason" || k == "seconds") continue;
    if (k.rfind("note.", 0) == 0) {
      if (const auto* s = std::get_if<std::string>(&v)) r.notes[k.substr(5)] = *s;
    } else if (const auto* d = std::get_if<double>(&v)) {
      r.scalars[k] = *d;
    } else if (const auto* i = std::get_if<std::int64_t>(&v)) {
      r.scalars[k] = static_cast<double>(*i);
    } else if (const auto* u = std::get_if<std::uint64_t>(&v)) {
      r.scalars[k] = static_cast<double>(*u);
    }
  }
  read_datasets(g, "", r);
  return r;
}

}  // namespace dpdrng::study
