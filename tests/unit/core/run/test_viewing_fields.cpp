// What a snapshot carries for viewing (run/viewing_fields.hpp): each phase's cell-centred velocity
// vector, the mean of the two staggered faces along each axis, and the face velocities on the
// boundary openings, equal to the staggered values stored for those faces. Run on 1, 2 and 3
// ranks: each compares the file with values computed here from the formula.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "src/io/snapshot.hpp"
#include "src/io/snapshot_check.hpp"
#include "src/run/viewing_fields.hpp"
#include "tests/support/deck_domain.hpp"
#include "tests/support/test_decks.hpp"

namespace bagnold::tests {
namespace {

// A 4 × 3 × 5 cm box with three openings: a 2 cm strip of the floor (pressure outflow, the
// ring cells own the faces), the whole top (pressure outflow, the fluid cells own them) and the
// x- side (a mass inflow, the ring cells own them).
const std::string box_with_openings = box_deck(
    4, 3, 5,
    "[[boundary]]\nname = \"orifice\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
    "min = [0.0, 0.0, -1.0]\nmax = [0.02, 0.03, 0.0]\n"
    "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n"
    "[[boundary]]\nname = \"inlet\"\ntype = \"mass_inflow\"\nface = \"x-\"\n"
    "gas_velocity = [0.5, 0.0, 0.0]\n");
constexpr std::size_t orifice_faces = 2 * 3, top_faces = 4 * 3, inlet_faces = 3 * 5;

// A linear velocity field per phase, component d at point x: Σ_b a[d][b] x_b + c[d].
struct LinearField {
  double a[3][3];
  double c[3];
  double at(int d, const std::array<double, 3>& x) const {
    double v = c[d];
    for (int b = 0; b < 3; ++b) v += a[d][b] * x[static_cast<std::size_t>(b)];
    return v;
  }
};
const LinearField gas_field{{{0.5, -1.0, 2.0}, {0.3, -0.2, 0.7}, {-1.5, 0.4, 0.9}}, {0.1, -0.2, 0.3}};
const LinearField solids_field{{{-2.0, 0.6, 1.0}, {1.1, 0.0, -0.4}, {0.2, -0.7, 3.0}}, {-0.05, 0.0, -0.3}};

// Where component d of a staggered field owned by cell ijk sits: the cell's + face along d.
std::array<double, 3> face_position(const grid::StructuredGrid& g, const grid::Index3& ijk, int d) {
  auto x = g.centre(ijk);
  x[static_cast<std::size_t>(d)] = g.axis(d).upper_face(ijk[static_cast<std::size_t>(d)]);
  return x;
}

std::string file_name(const std::string& stem) {
  return stem + "_np" + std::to_string(parallel::Communicator().size()) + ".h5";
}

struct Written : DeckAndDomain {
  run::FlowState state;
  run::ViewingFields viewing;
  explicit Written(const std::string& path)
      : DeckAndDomain(box_with_openings), state(domain.layout.local_count()), viewing(domain) {
    const auto& layout = domain.layout;
    for (int l = 0; l < layout.local_count(); ++l)
      for (int d = 0; d < 3; ++d) {
        const auto x = face_position(domain.grid, layout.index3(l), d);
        state.gas_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] = gas_field.at(d, x);
        state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] = solids_field.at(d, x);
      }
    io::write_snapshot(path, layout, domain.flags, state.views(), {0.5, 3, 1e-3, "viewing", 1e-3, {}, {}},
                       viewing.of(state));
  }
};

// The whole dataset as doubles, and its shape.
std::vector<double> read_doubles(hid_t file, const std::string& path, std::vector<hsize_t>* shape = nullptr) {
  const hid_t ds = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(ds, 0) << path;
  const hid_t space = H5Dget_space(ds);
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (shape) {
    shape->assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
    H5Sget_simple_extent_dims(space, shape->data(), nullptr);
  }
  H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(ds);
  return values;
}

std::string text_attribute(hid_t file, const std::string& object, const char* name) {
  const hid_t holder = H5Oopen(file, object.c_str(), H5P_DEFAULT);
  if (holder < 0 || H5Aexists(holder, name) <= 0) {
    if (holder >= 0) H5Oclose(holder);
    return "(none)";
  }
  const hid_t a = H5Aopen(holder, name, H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  char* text = nullptr;
  H5Aread(a, t, &text);
  std::string out = text ? text : "";
  H5free_memory(text);
  H5Tclose(t);
  H5Aclose(a);
  H5Oclose(holder);
  return out;
}

std::uint64_t stored_checksum(hid_t file, const std::string& path) {
  const hid_t ds = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  const hid_t a = H5Aopen(ds, "checksum", H5P_DEFAULT);
  std::uint64_t value = 0;
  H5Aread(a, H5T_NATIVE_UINT64, &value);
  H5Aclose(a);
  H5Dclose(ds);
  return value;
}

std::uint64_t checksum_of(const std::vector<double>& values) {
  std::uint64_t sum = 0;
  for (std::size_t e = 0; e < values.size(); ++e) sum += io::element_hash(e, values[e]);
  return sum;
}

TEST(ViewingFields, CellVectorIsTheMeanOfTheTwoFacesOfALinearField) {
  const std::string path = file_name("viewing_vectors");
  const Written w(path);
  if (!parallel::Communicator().is_root()) return;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const auto& g = w.domain.grid;
  const std::map<std::string, const LinearField*> phases = {{"gas_velocity", &gas_field},
                                                            {"solids_velocity", &solids_field}};
  for (const auto& [name, field] : phases) {
    std::vector<hsize_t> shape;
    const auto vector = read_doubles(file, "fields/" + name, &shape);
    ASSERT_EQ(shape, (std::vector<hsize_t>{5, 3, 4, 3})) << name;
    EXPECT_EQ(text_attribute(file, "fields/" + name, "units"), "m/s");
    EXPECT_EQ(text_attribute(file, "fields/" + name, "centering"), "cell");
    const std::string axes = "xyz";
    std::size_t e = 0;
    for (int k = 0; k < g.cells(2); ++k)
      for (int j = 0; j < g.cells(1); ++j)
        for (int i = 0; i < g.cells(0); ++i)
          for (int d = 0; d < 3; ++d, ++e) {
            const grid::Index3 ijk{i, j, k};
            grid::Index3 minus = ijk;
            --minus[static_cast<std::size_t>(d)];
            // The mean of the cell's + face and its − neighbour's + face (a wall's or an
            // opening's face included: the ring cells own those); for a linear field, the
            // value at the centre.
            const double mean = 0.5 * (field->at(d, face_position(g, ijk, d)) +
                                       field->at(d, face_position(g, minus, d)));
            EXPECT_NEAR(vector[e], mean, 1e-14) << name << " at (" << i << "," << j << "," << k << ") " << axes[d];
            EXPECT_NEAR(vector[e], field->at(d, g.centre(ijk)), 1e-14);
          }
    // Non-fluid cells hold the fill value; the checksum covers the dataset as every other.
    EXPECT_EQ(stored_checksum(file, "fields/" + name), checksum_of(vector)) << name;
  }
  H5Fclose(file);
}

TEST(ViewingFields, OpeningFacesCarryTheStaggeredFaceVelocity) {
  const std::string path = file_name("viewing_openings");
  const Written w(path);
  EXPECT_EQ(w.viewing.opening_face_count(), orifice_faces + top_faces + inlet_faces);
  if (!parallel::Communicator().is_root()) return;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::size_t n = orifice_faces + top_faces + inlet_faces;
  std::vector<hsize_t> shape;
  const auto points = read_doubles(file, "openings/points", &shape);
  ASSERT_EQ(shape, (std::vector<hsize_t>{4 * n, 3}));
  const auto region = read_doubles(file, "openings/region");  // converted from int32
  ASSERT_EQ(region.size(), n);
  const auto solids = read_doubles(file, "openings/solids_velocity", &shape);
  ASSERT_EQ(shape, (std::vector<hsize_t>{n, 3}));
  const auto gas = read_doubles(file, "openings/gas_velocity");
  const auto solids_out = read_doubles(file, "openings/solids_outflow_velocity");
  const auto gas_out = read_doubles(file, "openings/gas_outflow_velocity");
  for (const char* name : {"gas_velocity", "solids_velocity", "gas_outflow_velocity", "solids_outflow_velocity"})
    EXPECT_EQ(text_attribute(file, std::string("openings/") + name, "units"), "m/s") << name;
  // The region index names a region of the deck: 0 orifice, 1 top, 2 inlet.
  std::map<int, std::size_t> per_region;
  for (std::size_t f = 0; f < n; ++f) {
    // The face's centre and normal from its corners: one coordinate shared by all four.
    std::array<double, 3> centre{0, 0, 0};
    for (int c = 0; c < 4; ++c)
      for (int b = 0; b < 3; ++b) centre[static_cast<std::size_t>(b)] += 0.25 * points[3 * (4 * f + c) + b];
    int normal = -1;
    for (int b = 0; b < 3; ++b)
      if (points[3 * (4 * f) + b] == points[3 * (4 * f + 2) + b]) normal = b;
    ASSERT_GE(normal, 0);
    const int r = static_cast<int>(region[f]);
    ++per_region[r];
    const int expected_normal = r == 2 ? 0 : 2;
    EXPECT_EQ(normal, expected_normal) << "face " << f;
    // Outward: down through the floor, up through the top, −x through the inlet.
    const double outward = r == 1 ? 1.0 : -1.0;
    for (int b = 0; b < 3; ++b) {
      const double s = b == normal ? solids_field.at(b, centre) : 0.0;
      const double g = b == normal ? gas_field.at(b, centre) : 0.0;
      EXPECT_NEAR(solids[3 * f + b], s, 1e-14) << "face " << f << " component " << b;
      EXPECT_NEAR(gas[3 * f + b], g, 1e-14) << "face " << f << " component " << b;
    }
    EXPECT_NEAR(solids_out[f], outward * solids_field.at(normal, centre), 1e-14);
    EXPECT_NEAR(gas_out[f], outward * gas_field.at(normal, centre), 1e-14);
  }
  EXPECT_EQ(per_region[0], orifice_faces);
  EXPECT_EQ(per_region[1], top_faces);
  EXPECT_EQ(per_region[2], inlet_faces);

  // The orifice's face velocities are the staggered W stored at its ring cells (/boundary).
  const auto boundary_w = read_doubles(file, "boundary/solids_velocity_z");
  std::vector<std::int64_t> naturals(boundary_w.size());
  const hid_t ds = H5Dopen2(file, "boundary/natural", H5P_DEFAULT);
  H5Dread(ds, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, naturals.data());
  H5Dclose(ds);
  const auto& g = w.domain.grid;
  std::size_t matched = 0;
  for (std::size_t f = 0; f < n; ++f) {
    if (region[f] != 0) continue;
    const double x = 0.25 * (points[3 * 4 * f] + points[3 * (4 * f + 1)] + points[3 * (4 * f + 2)] +
                             points[3 * (4 * f + 3)]);
    const double y = 0.25 * (points[3 * 4 * f + 1] + points[3 * (4 * f + 1) + 1] +
                             points[3 * (4 * f + 2) + 1] + points[3 * (4 * f + 3) + 1]);
    const grid::Natural ring = g.natural({static_cast<int>(x / 0.01), static_cast<int>(y / 0.01), -1});
    for (std::size_t b = 0; b < naturals.size(); ++b)
      if (naturals[b] == ring) {
        EXPECT_EQ(solids[3 * f + 2], boundary_w[b]) << "orifice face " << f;
        ++matched;
      }
  }
  EXPECT_EQ(matched, orifice_faces);
  EXPECT_EQ(stored_checksum(file, "openings/solids_velocity"), checksum_of(solids));
  EXPECT_EQ(stored_checksum(file, "openings/gas_outflow_velocity"), checksum_of(gas_out));
  EXPECT_FALSE(io::verify_snapshot(path, {}));
  H5Fclose(file);
}

// The XDMF index shows the vectors as Vector attributes of the cells and the openings as a grid
// of quadrilaterals with their own vectors.
TEST(ViewingFields, XdmfIndexShowsVectorsAndTheOpeningsGrid) {
  const DeckAndDomain d(box_with_openings);
  const std::string text = io::xdmf_text(d.domain.grid, {{"snapshot_000000.h5", 0.0, {}, 33}},
                                         run::ViewingFields::indexed_fields());
  EXPECT_NE(text.find("<Attribute Name=\"solids_velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n"
                      "      <DataItem Dimensions=\"5 3 4 3\""),
            std::string::npos) << text;
  EXPECT_NE(text.find("<Grid Name=\"openings\" GridType=\"Uniform\">"), std::string::npos);
  EXPECT_NE(text.find("TopologyType=\"Quadrilateral\" NumberOfElements=\"33\""), std::string::npos);
  EXPECT_NE(text.find("<DataItem Dimensions=\"132 3\""), std::string::npos);
  EXPECT_NE(text.find("<Attribute Name=\"gas_outflow_velocity\" AttributeType=\"Scalar\""), std::string::npos);
  // An older snapshot without them: no vectors, no openings grid.
  const std::string older = io::xdmf_text(
      d.domain.grid, {{"snapshot_000000.h5", 0.0, run::ViewingFields::cell_vector_names(), 0}},
      run::ViewingFields::indexed_fields());
  EXPECT_EQ(older.find("AttributeType=\"Vector\""), std::string::npos);
  EXPECT_EQ(older.find("openings"), std::string::npos);
  EXPECT_NE(older.find("Name=\"solids_velocity_z\""), std::string::npos);
}

}  // namespace
}  // namespace bagnold::tests
