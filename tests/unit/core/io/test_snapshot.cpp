// Snapshots written from any number of ranks hold the same global arrays, and read back onto
// any number of ranks. Run on 1, 2 and 3 ranks: each run compares the file with values computed
// here, so the three runs produce bit-identical datasets or one of them fails.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "src/deck/load.hpp"
#include "src/io/snapshot.hpp"
#include "src/io/snapshot_check.hpp"
#include "src/parallel/domain.hpp"
#include "tests/support/test_decks.hpp"

namespace bagnold::tests {
namespace {

const std::string hopper = box_deck(
    7, 5, 9,
    "[[geometry.block]]\nshape = \"cone\"\nbase = [0.035, 0.025, 0.0]\naxis = [0.0, 0.0, 1.0]\n"
    "length = 0.09\nradius = 0.01\ntop_radius = 0.05\nblocks = \"outside\"\n");

double value_at(grid::Natural n) { return 1.0 + 0.001 * static_cast<double>(n); }

std::string file_name(const std::string& stem) {
  return stem + "_np" + std::to_string(parallel::Communicator().size()) + ".h5";
}

struct Written {
  deck::Deck deck = deck::load_deck_text(hopper, "hopper.toml");
  parallel::Domain domain{deck, parallel::Communicator()};
  std::vector<double> values;

  explicit Written(const std::string& path) {
    const auto& layout = domain.layout;
    values.resize(static_cast<std::size_t>(layout.local_count()));
    for (int l = 0; l < layout.local_count(); ++l)
      values[static_cast<std::size_t>(l)] = value_at(layout.natural(l));
    io::write_snapshot(path, layout, domain.flags,
                       {{"solids_fraction", io::Centering::cell, values, "1"},
                        {"solids_velocity_x", io::Centering::x_face, values, "m/s"}},
                       {0.25, 12, 1e-3, "test", 2e-3, {1e-3, 8000.0, 11.0}, record});
  }
  // The run's record (src/run/provenance.hpp), with text beyond ASCII.
  static inline const std::vector<io::RecordAttribute> record = {
      {"deck", std::string("[solids]\ndiameter = 0.001  # d_p [m], ε_s ≤ 0.6\n")}, {"ranks", 3L}};
};

TEST(Snapshot, GlobalArrayHoldsFluidValuesAndNaNElsewhere) {
  const std::string path = file_name("snapshot_global");
  Written w(path);
  if (!parallel::Communicator().is_root()) return;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t ds = H5Dopen2(file, "fields/solids_fraction", H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  const auto& g = w.domain.grid;
  std::vector<double> data(static_cast<std::size_t>(g.domain_cell_count()));
  ASSERT_GE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0);
  std::size_t p = 0;
  int fluid = 0;
  for (int k = 0; k < g.cells(2); ++k)
    for (int j = 0; j < g.cells(1); ++j)
      for (int i = 0; i < g.cells(0); ++i, ++p) {
        const auto n = g.natural({i, j, k});
        if (w.domain.flags.kind[static_cast<std::size_t>(n)] == grid::CellKind::fluid) {
          EXPECT_EQ(data[p], value_at(n));
          ++fluid;
        } else {
          EXPECT_TRUE(std::isnan(data[p])) << "blocked cell (" << i << "," << j << "," << k << ")";
        }
      }
  EXPECT_EQ(fluid, w.domain.flags.fluid_count);
  EXPECT_GT(g.domain_cell_count(), fluid);  // the cone really blocks cells
  H5Dclose(ds);
  H5Fclose(file);
}

TEST(Snapshot, NoTemporaryFileIsLeftBehind) {
  const std::string path = file_name("snapshot_tmp");
  Written w(path);
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(Snapshot, ReadBackGivesEveryLocalCellIncludingHaloAndBoundary) {
  const std::string path = file_name("snapshot_roundtrip");
  Written w(path);
  std::vector<std::vector<double>> fields;
  const auto contents =
      io::read_snapshot(path, w.domain.layout, {"solids_fraction", "solids_velocity_x"}, fields);
  EXPECT_EQ(contents.info.time, 0.25);
  EXPECT_EQ(contents.info.step, 12);
  EXPECT_EQ(contents.info.dt_next, 2e-3);
  EXPECT_EQ(contents.info.time_step_memory, (std::vector<double>{1e-3, 8000.0, 11.0}));
  ASSERT_EQ(fields.size(), 2u);
  for (int l = 0; l < w.domain.layout.local_count(); ++l) {
    EXPECT_EQ(fields[0][static_cast<std::size_t>(l)], w.values[static_cast<std::size_t>(l)]);
    EXPECT_EQ(fields[1][static_cast<std::size_t>(l)], w.values[static_cast<std::size_t>(l)]);
  }
}

// Record attributes are variable-length UTF-8 strings (h5py reads them as str) or int64, on the
// root; read_text_attribute gives them back, and the older fixed-length ones too.
TEST(Snapshot, RecordAttributesAreUtf8StringsOrIntegers) {
  const std::string path = file_name("snapshot_record");
  Written w(path);
  EXPECT_EQ(io::read_text_attribute(path, "deck"), std::get<std::string>(Written::record[0].value));
  EXPECT_EQ(io::read_text_attribute(path, "title"), std::string("test"));
  EXPECT_FALSE(io::read_text_attribute(path, "no_such_attribute"));
  EXPECT_THROW(io::read_text_attribute(path + ".missing", "deck"), io::Hdf5Error);
  if (!parallel::Communicator().is_root()) return;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t deck = H5Aopen(file, "deck", H5P_DEFAULT);
  const hid_t type = H5Aget_type(deck);
  EXPECT_GT(H5Tis_variable_str(type), 0);
  EXPECT_EQ(H5Tget_cset(type), H5T_CSET_UTF8);
  const hid_t ranks = H5Aopen(file, "ranks", H5P_DEFAULT);
  const hid_t ranks_type = H5Aget_type(ranks);
  EXPECT_EQ(H5Tget_class(ranks_type), H5T_INTEGER);
  long value = 0;
  ASSERT_GE(H5Aread(ranks, H5T_NATIVE_LONG, &value), 0);
  EXPECT_EQ(value, 3);
  H5Tclose(ranks_type);
  H5Aclose(ranks);
  H5Tclose(type);
  H5Aclose(deck);
  // Every text attribute is variable-length UTF-8 (h5py gives str, so attrs["centering"] ==
  // "x_face" holds), and each field carries its units.
  auto text_of = [&](const char* object, const char* name) {
    const hid_t holder = H5Oopen(file, object, H5P_DEFAULT);
    const hid_t a = H5Aopen(holder, name, H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    EXPECT_GT(H5Tis_variable_str(t), 0) << object << " " << name;
    EXPECT_EQ(H5Tget_cset(t), H5T_CSET_UTF8) << object << " " << name;
    char* text = nullptr;
    H5Aread(a, t, &text);
    std::string out = text ? text : "";
    H5free_memory(text);
    H5Tclose(t);
    H5Aclose(a);
    H5Oclose(holder);
    return out;
  };
  EXPECT_EQ(text_of("/", "title"), "test");
  EXPECT_FALSE(text_of("/", "bagnold_version").empty());
  EXPECT_EQ(text_of("fields/solids_velocity_x", "centering"), "x_face");
  EXPECT_EQ(text_of("fields/solids_fraction", "centering"), "cell");
  EXPECT_EQ(text_of("fields/solids_velocity_x", "units"), "m/s");
  EXPECT_EQ(text_of("fields/solids_fraction", "units"), "1");
  H5Fclose(file);
}

// The estimate the writer checks the free disk space against covers the file, without asking for
// much more than it takes (the hopper: 2 fields, a 3 kB deck in the record).
TEST(Snapshot, SizeEstimateCoversTheFile) {
  const std::string path = file_name("snapshot_size");
  Written w(path);
  io::SnapshotInfo info{0.25, 12, 1e-3, "test", 2e-3, {1e-3, 8000.0, 11.0}, Written::record};
  const auto estimate = io::snapshot_size_estimate(w.domain.layout, w.domain.flags, 2, info);
  const auto size = std::filesystem::file_size(path);
  EXPECT_GE(estimate, size);
  EXPECT_LE(estimate, 2 * size);
}

TEST(Snapshot, ReadOntoAnotherRankCountFromASerialFile) {
  // Written on one rank (rank 0 alone, with its own communicator), read on all ranks.
  const std::string path = file_name("snapshot_serial_source");
  const parallel::Communicator world;
  if (world.is_root()) {
    const auto d = deck::load_deck_text(hopper, "hopper.toml");
    parallel::Domain serial(d, parallel::Communicator(MPI_COMM_SELF));
    std::vector<double> v(static_cast<std::size_t>(serial.layout.local_count()));
    for (int l = 0; l < serial.layout.local_count(); ++l)
      v[static_cast<std::size_t>(l)] = value_at(serial.layout.natural(l));
    io::write_snapshot(path, serial.layout, serial.flags, {{"p", io::Centering::cell, v, "Pa"}}, {});
  }
  world.barrier();
  const auto d = deck::load_deck_text(hopper, "hopper.toml");
  parallel::Domain domain(d, world);
  std::vector<std::vector<double>> fields;
  io::read_snapshot(path, domain.layout, {"p"}, fields);
  for (int l = 0; l < domain.layout.local_count(); ++l)
    EXPECT_EQ(fields[0][static_cast<std::size_t>(l)], value_at(domain.layout.natural(l)));
}

TEST(Snapshot, RefusesASnapshotFromAnotherGrid) {
  const std::string path = file_name("snapshot_other_grid");
  Written w(path);
  const auto other = deck::load_deck_text(box_deck(7, 5, 10), "other.toml");
  parallel::Domain domain(other, parallel::Communicator());
  std::vector<std::vector<double>> fields;
  try {
    io::read_snapshot(path, domain.layout, {"solids_fraction"}, fields);
    FAIL() << "expected an error";
  } catch (const io::Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find("another grid"), std::string::npos) << e.what();
  }
}

TEST(Snapshot, MissingFieldIsReportedByName) {
  const std::string path = file_name("snapshot_missing");
  Written w(path);
  std::vector<std::vector<double>> fields;
  try {
    io::read_snapshot(path, w.domain.layout, {"granular_temperature"}, fields);
    FAIL() << "expected an error";
  } catch (const io::Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find("granular_temperature"), std::string::npos);
  }
}

// A field named optional that the file lacks (a snapshot from before the field existed) reads
// as NaN everywhere and is left out of field_names; the fields the file has read as before.
TEST(Snapshot, MissingOptionalFieldReadsAsNaN) {
  const std::string path = file_name("snapshot_optional");
  Written w(path);
  std::vector<std::vector<double>> fields;
  const auto contents = io::read_snapshot(path, w.domain.layout,
                                          {"solids_fraction", "pressure_shear_rate"}, fields,
                                          {"pressure_shear_rate"});
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(contents.field_names, std::vector<std::string>{"solids_fraction"});
  for (const double v : fields[1]) EXPECT_TRUE(std::isnan(v));
  const auto& layout = w.domain.layout;
  for (int l = 0; l < layout.local_count(); ++l)
    if (layout.kind(l) == grid::CellKind::fluid) {
      EXPECT_EQ(fields[0][static_cast<std::size_t>(l)], w.values[static_cast<std::size_t>(l)]);
    }
}

TEST(Snapshot, ChecksumsWrittenFromAnyRankCountMatchTheDataAndCatchAChangedValue) {
  const std::string path = file_name("snapshot_checksum");
  Written w(path);
  if (!parallel::Communicator().is_root()) return;  // the checks are serial
  // The ranks' partial sums equal the serial sum over the file's elements.
  EXPECT_FALSE(io::verify_snapshot(path, {{"solids_fraction"}, {"solids_velocity_x"}}));
  // The values are 1 + 0.001 n: above a fraction's range.
  const auto range = io::verify_snapshot(path, {{"solids_fraction", 0.0, 1.0}});
  ASSERT_TRUE(range);
  EXPECT_NE(range->find("dataset fields/solids_fraction holds 1."), std::string::npos) << *range;
  EXPECT_NE(range->find("in fluid cell (i, j, k) = ("), std::string::npos) << *range;
  // One element changed behind the writer's back (the last bit of one value).
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t ds = H5Dopen2(file, "boundary/solids_velocity_x", H5P_DEFAULT);
    std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(H5Dget_space(ds))));
    H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    values[values.size() / 2] = std::nextafter(values[values.size() / 2], 10.0);
    H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(ds);
    H5Fclose(file);
  }
  const auto changed = io::verify_snapshot(path, {{"solids_fraction"}, {"solids_velocity_x"}});
  ASSERT_TRUE(changed);
  EXPECT_EQ(*changed, "dataset boundary/solids_velocity_x does not match its checksum (corrupted)");
  EXPECT_EQ(*io::verify_snapshot(path + ".missing", {}), "cannot open it as HDF5 (truncated or not a snapshot)");
}

}  // namespace
}  // namespace bagnold::tests
