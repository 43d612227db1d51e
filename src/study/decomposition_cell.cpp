#include "dpdrng/study/decomposition_cell.hpp"

#include <cstdio>
#include <stdexcept>

#include "dpdrng/study/decomposition_sweep.hpp"
#include "dpdrng/study/h5.hpp"

namespace dpdrng::study {
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

namespace decomp_record {

// Every field of a row, listed once for writing and reading: `v(name, field)` for a value, `v.sub(name, field)`
// for a structure (a subgroup). S is the structure, const when written.
template <class V, class S>
void boundary_fields(V& v, S& b) {
  v("evaluations", b.evaluations), v("in_range", b.in_range), v("boundary", b.boundary), v("shifted", b.shifted);
  v("separation_mismatch", b.separation_mismatch), v("range_mismatch", b.range_mismatch);
  v("zeta_mismatch", b.zeta_mismatch), v("zeta_diff_sum", b.zeta_diff_sum), v("zeta_diff_sum2", b.zeta_diff_sum2);
  v("zeta_diff_max", b.zeta_diff_max), v("force_mismatch_max", b.force_mismatch_max);
  v("net_force_max", b.net_force_max), v("net_force_sum2", b.net_force_sum2);
  v("grid_straddle_expected", b.grid_straddle_expected);
}

template <class V, class S>
void stat_fields(V& v, S& s) {
  v("mean", s.mean), v("std", s.std), v("sem", s.sem), v("sem_dof", s.sem_dof), v("std_sem", s.std_sem);
  v("std_sem_dof", s.std_sem_dof), v("n", s.n);
}

template <class V, class S>
void run_fields(V& v, S& r) {
  v("status.state", r.status.state), v("status.step", r.status.step), v("status.detail", r.status.detail);
  v("steps_done", r.steps_done), v.sub("temperature", r.temperature), v.sub("pressure", r.pressure);
  v("diffusion", r.diffusion), v("diffusion_sem", r.diffusion_sem), v("momentum_drift", r.momentum_drift);
  v("momentum_final", r.momentum_final), v("com_kinetic_share", r.com_kinetic_share);
  v.sub("boundary", r.boundary), v("seconds", r.seconds);
}

template <class V, class S>
void randomness_fields(V& v, S& c) {
  v("chi2_tests", c.chi2_tests), v("chi2_pass", c.chi2_pass), v("chi2_min_p", c.chi2_min_p);
  v("lag1_tests", c.lag1_tests), v("lag1_pass", c.lag1_pass), v("lag1_max_abs_r", c.lag1_max_abs_r);
  v("cross_pair_r", c.cross_pair_r), v("cross_pair_p", c.cross_pair_p);
  v("cross_pair_verdict", c.cross_pair_verdict), v("duplicates_per_step", c.duplicates_per_step);
}

template <class V, class S>
void row_fields(V& v, S& r) {
  v("generator", r.generator), v("seeding", r.seeding), v("distribution", r.distribution);
  v("domains", r.domains), v("feed", r.feed), v("particles", r.particles), v("box_length", r.box_length);
  v.sub("snapshot", r.snapshot), v.sub("decomposed", r.decomposed), v("has_reference", r.has_reference);
  if (r.has_reference) v.sub("reference", r.reference), v.sub("randomness", r.randomness);
}

template <class V>
void fields(V& v, const BoundaryStats& b) { boundary_fields(v, b); }
template <class V>
void fields(V& v, BoundaryStats& b) { boundary_fields(v, b); }
template <class V>
void fields(V& v, const Stat& s) { stat_fields(v, s); }
template <class V>
void fields(V& v, Stat& s) { stat_fields(v, s); }
template <class V>
void fields(V& v, const DecompRun& r) { run_fields(v, r); }
template <class V>
void fields(V& v, DecompRun& r) { run_fields(v, r); }
template <class V>
void fields(V& v, const RandomnessCost& c) { randomness_fields(v, c); }
template <class V>
void fields(V& v, RandomnessCost& c) { randomness_fields(v, c); }

struct Put {
  hid_t g;
  void operator()(const char* n, double x) const { h5::write_attribute(g, n, x); }
  void operator()(const char* n, std::uint64_t x) const { h5::write_attribute(g, n, x); }
  void operator()(const char* n, std::int64_t x) const { h5::write_attribute(g, n, x); }
  void operator()(const char* n, bool x) const { h5::write_attribute(g, n, std::int64_t{x}); }
  void operator()(const char* n, const std::string& x) const { h5::write_attribute(g, n, x); }
  void operator()(const char* n, RunState x) const { h5::write_attribute(g, n, std::string(to_string(x))); }
  template <class T>
  void sub(const char* n, const T& x) const {
    h5::Handle s = h5::create_group(g, n);
    Put p{s.id()};
    fields(p, x);
  }
};

struct Get {
  hid_t g;
  std::map<std::string, h5::Attribute> attrs = h5::read_attributes(g);

  template <class T>
  T value(const char* n) const {
    const auto it = attrs.find(n);
    if (it == attrs.end()) throw std::runtime_error(std::string("decomposition record lacks ") + n);
    if (const T* v = std::get_if<T>(&it->second)) return *v;
    throw std::runtime_error(std::string("decomposition record field ") + n + " has the wrong type");
  }
  void operator()(const char* n, double& x) const { x = value<double>(n); }
  void operator()(const char* n, std::uint64_t& x) const { x = value<std::uint64_t>(n); }
  void operator()(const char* n, std::int64_t& x) const { x = value<std::int64_t>(n); }
  void operator()(const char* n, bool& x) const { x = value<std::int64_t>(n) != 0; }
  void operator()(const char* n, std::string& x) const { x = value<std::string>(n); }
  void operator()(const char* n, RunState& x) const { x = parse_run_state(value<std::string>(n)); }
  template <class T>
  void sub(const char* n, T& x) const {
    if (!h5::exists(g, n)) throw std::runtime_error(std::string("decomposition record lacks ") + n);
    h5::Handle s = h5::open_group(g, n);
    Get q{s.id()};
    fields(q, x);
  }
};

std::string row_name(std::size_t k) { return "row" + std::to_string(k); }

std::string read_rows(hid_t g, std::vector<DecompResult>* rows) {
  const Get cell{g};
  const auto n = cell.value<std::int64_t>("rows");
  if (n < 0) throw std::runtime_error("decomposition record has a negative row count");
  for (std::int64_t k = 0; k < n; ++k) {
    const std::string name = row_name(static_cast<std::size_t>(k));
    if (!h5::exists(g, name)) throw std::runtime_error("decomposition record lacks " + name);
    h5::Handle s = h5::open_group(g, name);
    const Get get{s.id()};
    DecompResult r;
    row_fields(get, r);
    if (rows) rows->push_back(std::move(r));
  }
  return cell.value<std::string>("cell.id");
}

}  // namespace decomp_record

void write_decomp_rows(hid_t g, const std::string& id, const std::vector<DecompResult>& rows) {
  h5::write_attribute(g, "cell.id", id);
  h5::write_attribute(g, "rows", static_cast<std::int64_t>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    h5::Handle s = h5::create_group(g, decomp_record::row_name(k));
    const decomp_record::Put put{s.id()};
    decomp_record::row_fields(put, rows[k]);
  }
}

std::string read_decomp_rows(hid_t g, std::vector<DecompResult>* rows) { return decomp_record::read_rows(g, rows); }

void open_decomp_store(const CellStore& store, const DecompSweep& sweep) {
  store.open("decomposition.toml", sweep.source_text, sweep.hash);
}

CellStore::State decomp_cell_state(const CellStore& store, const DecompCell& cell, std::string* reason) {
  return store.state(cell.id(), [](hid_t g) { return read_decomp_rows(g, nullptr); }, reason);
}

void save_decomp_cell(const CellStore& store, const DecompCell& cell, const std::vector<DecompResult>& rows) {
  const std::string id = cell.id();
  store.save(id, [&](hid_t g) { write_decomp_rows(g, id, rows); });
}

std::vector<DecompResult> load_decomp_cell(const CellStore& store, const DecompCell& cell) {
  std::vector<DecompResult> rows;
  std::lock_guard lk(h5::lock());
  store.read(store.cell_path(cell.id()), [&rows](hid_t g) { return read_decomp_rows(g, &rows); });
  return rows;
}

std::size_t assemble_decomp_store(const CellStore& store, const DecompSweep& sweep) {
  return store.assemble({sweep.name, sweep.description, sweep.source_text, sweep.canonical().dump(), sweep.hash},
                        [](hid_t g) { return read_decomp_rows(g, nullptr); });
}

}  // namespace dpdrng::study
