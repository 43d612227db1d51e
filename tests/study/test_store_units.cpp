// What the store writes beside the numbers: every dataset's unit, counts and seeds as integers, the scalars' units
// in study.h5; and a committed cell of the older layout (counts as doubles, the seed as text) read with the same
// numbers, and written again in the new layout with the same numbers.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <limits>

#include "dpdrng/study/h5.hpp"
#include "dpdrng/study/observables.hpp"
#include "dpdrng/study/store.hpp"
#include "fake_measure.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::study_test_store_units {

using namespace dpdrng::study;
namespace fs = std::filesystem;

namespace {

// The HDF5 class of a dataset's values, as h5dump prints it.
H5T_class_t dataset_class(hid_t group, const std::string& name) {
  h5::Handle d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + name);
  h5::Handle t(H5Dget_type(d.id()), H5Tclose, "type of " + name);
  return H5Tget_class(t.id());
}

std::string unit_attribute(hid_t group, const std::string& name) {
  const auto a = h5::read_attributes(group, name);
  const auto it = a.find("unit");
  return it == a.end() ? "(none)" : std::get<std::string>(it->second);
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Two records hold the same numbers, to the bit, and the same cell.
void expect_same_numbers(const CellResult& a, const CellResult& b) {
  EXPECT_EQ(a.cell.id(), b.cell.id());
  EXPECT_EQ(a.cell.seed, b.cell.seed);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.notes, b.notes);
  EXPECT_EQ(a.strings, b.strings);
  ASSERT_EQ(a.scalars.size(), b.scalars.size());
  for (const auto& [k, v] : a.scalars) {
    ASSERT_TRUE(b.scalars.count(k)) << k;
    EXPECT_EQ(bits(v), bits(b.scalars.at(k))) << k;
  }
  ASSERT_EQ(a.series.size(), b.series.size());
  for (const auto& [k, v] : a.series) {
    ASSERT_TRUE(b.series.count(k)) << k;
    const auto& w = b.series.at(k);
    ASSERT_EQ(v.size(), w.size()) << k;
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(bits(v[i]), bits(w[i])) << k << "[" << i << "]";
  }
  ASSERT_EQ(a.matrices.size(), b.matrices.size());
  for (const auto& [k, m] : a.matrices) {
    ASSERT_TRUE(b.matrices.count(k)) << k;
    EXPECT_EQ(m.rows, b.matrices.at(k).rows) << k;
    EXPECT_EQ(m.data, b.matrices.at(k).data) << k;
  }
}

}  // namespace

TEST(StoreUnits, NewCellCarriesUnitsAndIntegerCounts) {
  TempDir tmp;
  const StudyConfig cfg = parse_config(fake::small_config_toml("units", 1), "c.toml");
  Store store(tmp.path);
  store.open_for(cfg);
  CellResult r;
  r.cell = enumerate_cells(cfg)[0];
  r.cell.seed = std::numeric_limits<std::uint64_t>::max();  // beyond int64: an unsigned integer
  r.scalars = {{kinetic_temperature().key, 1.0375}, {"chi2.x.passed", 48}, {"chi2.x.trials", 50},
               {"ttest.x.passed", NAN}, {"steps_done", 1000}, {"chi2.x.fraction", 0.96}};
  r.series = {{"rdf/r", {0.05, 0.15}}, {"rdf/g", {0.0, 0.4}}, {"series/step", {0, 500, 1000}},
              {"series/temperature", {1.01, 1.04, 1.02}}};
  store.save(r);

  {
    std::lock_guard lock(h5::lock());
    h5::Handle f = h5::open_file(store.cell_path(r.cell).string());
    h5::Handle g = h5::open_group(f.id(), "cell");
    const auto a = h5::read_attributes(g.id());
    EXPECT_EQ(std::get<std::int64_t>(a.at("chi2.x.passed")), 48);
    EXPECT_EQ(std::get<std::int64_t>(a.at("steps_done")), 1000);
    EXPECT_EQ(std::get<std::uint64_t>(a.at("cell.seed")), std::numeric_limits<std::uint64_t>::max());
    EXPECT_TRUE(std::holds_alternative<double>(a.at(kinetic_temperature().key)));
    EXPECT_TRUE(std::holds_alternative<double>(a.at("chi2.x.fraction")));
    // A count that could not be counted stays NaN: a double, never a made-up integer.
    EXPECT_TRUE(std::holds_alternative<double>(a.at("ttest.x.passed")));
    EXPECT_EQ(unit_attribute(g.id(), "rdf/r"), "r_c");
    EXPECT_EQ(unit_attribute(g.id(), "rdf/g"), "1");
    EXPECT_EQ(unit_attribute(g.id(), "series/temperature"), "k_BT");
    EXPECT_EQ(unit_attribute(g.id(), "series/step"), "1");
    EXPECT_EQ(dataset_class(g.id(), "series/step"), H5T_INTEGER);
    EXPECT_EQ(dataset_class(g.id(), "series/temperature"), H5T_FLOAT);
  }
  const CellResult back = store.load(r.cell);
  expect_same_numbers(r, back);

  ASSERT_EQ(store.assemble(cfg), 1u);
  std::lock_guard lock(h5::lock());
  h5::Handle f = h5::open_file(store.study_file().string());
  h5::Handle units = h5::open_group(f.id(), "units");
  const auto u = h5::read_attributes(units.id());
  EXPECT_EQ(std::get<std::string>(u.at(kinetic_temperature().key)), "k_BT");
  EXPECT_EQ(std::get<std::string>(u.at("chi2.x.passed")), "1");
  EXPECT_EQ(u.count("cell.id"), 0u);
}

// A committed cell of the older layout: read as it is, with the numbers its attributes hold; saved again, the new
// layout holds the same numbers, now with integer counts and an integer seed.
TEST(StoreUnits, CommittedOlderCellIsReadWithTheSameNumbers) {
  const fs::path committed = fs::path(DPDRNG_SOURCE_DIR) / "results" / "bilayer";
  const std::string id = "tea32-r01-gauss-distance-dt0.01-rep00";
  TempDir tmp;
  const fs::path old_dir = tmp.path / "old", new_dir = tmp.path / "new";
  for (const fs::path& d : {old_dir, new_dir}) {
    fs::create_directories(d / "cells");
    fs::copy_file(committed / "study.toml", d / "study.toml");
    fs::copy_file(committed / "config.hash", d / "config.hash");
  }
  fs::copy_file(committed / "cells" / (id + ".h5"), old_dir / "cells" / (id + ".h5"));
  Store old_store(old_dir), new_store(new_dir);
  std::vector<UnreadableCell> unreadable;
  const auto cells = old_store.load_all(&unreadable);
  ASSERT_TRUE(unreadable.empty()) << unreadable.front().reason;
  ASSERT_EQ(cells.size(), 1u);
  const CellResult& old = cells.front();
  {
    // The older layout, as committed: counts as doubles, the seed as its decimal text.
    std::lock_guard lock(h5::lock());
    h5::Handle f = h5::open_file((old_dir / "cells" / (id + ".h5")).string());
    h5::Handle g = h5::open_group(f.id(), "cell");
    const auto a = h5::read_attributes(g.id());
    ASSERT_TRUE(std::holds_alternative<std::string>(a.at("cell.seed")));
    EXPECT_EQ(std::get<std::string>(a.at("cell.seed")), std::to_string(old.cell.seed));
    ASSERT_TRUE(std::holds_alternative<double>(a.at("steps_done")));
    for (const auto& [k, v] : old.scalars) EXPECT_EQ(bits(v), bits(std::get<double>(a.at(k)))) << k;
  }
  new_store.save(old);
  expect_same_numbers(old, new_store.load(old.cell));
  std::lock_guard lock(h5::lock());
  h5::Handle f = h5::open_file(new_store.cell_path(old.cell).string());
  h5::Handle g = h5::open_group(f.id(), "cell");
  const auto a = h5::read_attributes(g.id());
  EXPECT_EQ(std::get<std::uint64_t>(a.at("cell.seed")), old.cell.seed);
  EXPECT_EQ(static_cast<double>(std::get<std::int64_t>(a.at("steps_done"))), old.scalars.at("steps_done"));
  EXPECT_EQ(unit_attribute(g.id(), "profile/z"), "r_c");
}

TEST(ObservableTable, EveryRowIsComplete) {
  for (const auto& o : observables()) {
    SCOPED_TRACE(o.name);
    EXPECT_NE(std::string(o.key), "");
    EXPECT_NE(std::string(o.unit), "");
    EXPECT_NE(std::string(o.label), "");
    EXPECT_NE(o.scenes, 0u);
    EXPECT_EQ(unit_of(o.key), o.unit);
    if (o.sem) {
      EXPECT_EQ(unit_of(o.sem), o.unit);
    }
    if (o.rule == Rule::shift) {
      EXPECT_NE(std::string(o.margin_key), "");
    }
    if (o.rule == Rule::paired) {
      EXPECT_NE(std::string(o.what), "");
    }
    if (o.rule == Rule::curve) {
      EXPECT_EQ(o.sem, nullptr);
    }
  }
}

TEST(ObservableTable, KineticTemperatureIsOneCellScalarUnderTwoComparisons) {
  const Observable& t = kinetic_temperature();
  EXPECT_EQ(std::string(t.unit), "k_BT");
  EXPECT_TRUE(is_kinetic_temperature(t.name));
  EXPECT_TRUE(is_kinetic_temperature(bilayer_observables().front().name));
  EXPECT_EQ(std::string(bilayer_observables().front().key), t.key);
  EXPECT_FALSE(is_kinetic_temperature("temperature_conf_mean"));
  EXPECT_FALSE(is_kinetic_temperature("pressure_mean"));
  EXPECT_THROW(observable_row("no_such_observable"), std::out_of_range);
}

TEST(ObservableTable, UnitsAndCountsOfStoredNames) {
  EXPECT_EQ(unit_of("pressure_xx_minus_yy_std"), "k_BT/r_c³");
  EXPECT_EQ(unit_of("temperature_sem_dof"), "1");
  EXPECT_EQ(unit_of("msd/tau"), "τ");
  EXPECT_EQ(unit_of("msd/jackknife"), "r_c²");
  EXPECT_EQ(unit_of("vpdf/v"), "√(k_BT/m)");
  EXPECT_EQ(unit_of("cost.step_seconds"), "s");
  EXPECT_EQ(unit_of("no_such_quantity"), "");
  for (const char* c : {"chi2.a.trials", "ttest.x.passed", "zeta_n", "corr.pair.n", "steps_done", "nist/passed"})
    EXPECT_TRUE(is_count(c)) << c;
  for (const char* c : {"chi2.x.fraction", "temperature_sem_dof", "zeta_mean", "nist/p_uniformity"})
    EXPECT_FALSE(is_count(c)) << c;
}

}  // namespace dpdrng_test::study_test_store_units
