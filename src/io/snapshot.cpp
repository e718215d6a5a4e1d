#include "src/io/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "src/io/agree.hpp"
#include "src/io/disk_reservation.hpp"
#include "src/io/failed_file.hpp"
#include "src/io/hdf5_handle.hpp"
#include "src/io/snapshot_check.hpp"
#include "src/util/build_info.hpp"

namespace bagnold::io {

namespace {

constexpr int format_version = 1;

// One step of a parallel write, run on every rank and agreed on (agree.hpp) before any rank goes
// on: a full disk fails the write of whichever rank reaches it (HDF5's metadata is written by
// rank 0 alone), and a rank that has failed must not be waited for in the next collective call.
// Each step holds at most one HDF5 call that communicates between the ranks (a collective
// transfer, a dataset created with its fill written, the flush), and it comes first: a rank
// whose call failed skips only calls that are its own.
class Steps {
 public:
  explicit Steps(const parallel::Communicator& comm) : m_comm(comm) {}
  void operator()(const std::function<void()>& step) const { agree(m_comm, step); }

 private:
  const parallel::Communicator& m_comm;
};

File open_parallel(const std::string& path, MPI_Comm comm, bool create) {
  // Errors are reported by exceptions with a message; HDF5's own stack dump would only add noise.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  PropertyList access(check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate(file access)"));
  check_status(H5Pset_fapl_mpio(access.get(), comm, MPI_INFO_NULL), "H5Pset_fapl_mpio");
  if (create) {
    // Rank 0 writes all the metadata. With HDF5 1.10's default (the ranks share the metadata
    // writes), a write that fails makes its rank skip the barrier that ends the flush, and the
    // others wait there for good; with rank 0 alone, HDF5 reports the failure after the barrier.
    H5AC_cache_config_t cache;
    cache.version = H5AC__CURR_CACHE_CONFIG_VERSION;
    check_status(H5Pget_mdc_config(access.get(), &cache), "H5Pget_mdc_config");
    cache.metadata_write_strategy = H5AC_METADATA_WRITE_STRATEGY__PROCESS_0_ONLY;
    check_status(H5Pset_mdc_config(access.get(), &cache), "H5Pset_mdc_config");
  }
  if (create)
    return File(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
  return File(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()));
}

void write_attribute(hid_t object, const char* name, double value) {
  Dataspace space(check(H5Screate(H5S_SCALAR), "H5Screate"));
  Attribute a(check(H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                               H5P_DEFAULT), "H5Acreate"));
  check_status(H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &value), "H5Awrite");
}

void write_attribute(hid_t object, const char* name, long value) {
  Dataspace space(check(H5Screate(H5S_SCALAR), "H5Screate"));
  Attribute a(check(H5Acreate2(object, name, H5T_NATIVE_LONG, space.get(), H5P_DEFAULT,
                               H5P_DEFAULT), "H5Acreate"));
  check_status(H5Awrite(a.get(), H5T_NATIVE_LONG, &value), "H5Awrite");
}

// A variable-length UTF-8 string (h5py reads it as str): every text attribute.
void write_utf8_attribute(hid_t object, const char* name, const std::string& value) {
  Datatype type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"));
  check_status(H5Tset_size(type.get(), H5T_VARIABLE), "H5Tset_size");
  check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "H5Tset_cset");
  Dataspace space(check(H5Screate(H5S_SCALAR), "H5Screate"));
  Attribute a(check(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                    "H5Acreate"));
  const char* text = value.c_str();
  check_status(H5Awrite(a.get(), type.get(), &text), "H5Awrite");
}

// A one-dimensional array of variable-length UTF-8 strings (h5py reads it as an array of str).
void write_utf8_array_attribute(hid_t object, const char* name, const std::vector<std::string>& values) {
  Datatype type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"));
  check_status(H5Tset_size(type.get(), H5T_VARIABLE), "H5Tset_size");
  check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "H5Tset_cset");
  const hsize_t n = values.size();
  Dataspace space(check(H5Screate_simple(1, &n, nullptr), "H5Screate_simple"));
  Attribute a(check(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                    "H5Acreate"));
  std::vector<const char*> texts;
  for (const auto& v : values) texts.push_back(v.c_str());
  if (!texts.empty()) check_status(H5Awrite(a.get(), type.get(), texts.data()), "H5Awrite");
}

void write_checksum_attribute(hid_t object, std::uint64_t value) {
  Dataspace space(check(H5Screate(H5S_SCALAR), "H5Screate"));
  Attribute a(check(H5Acreate2(object, "checksum", H5T_NATIVE_UINT64, space.get(), H5P_DEFAULT,
                               H5P_DEFAULT), "H5Acreate checksum"));
  check_status(H5Awrite(a.get(), H5T_NATIVE_UINT64, &value), "H5Awrite checksum");
}

void write_attribute(hid_t object, const char* name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  Dataspace space(check(H5Screate_simple(1, &n, nullptr), "H5Screate_simple"));
  Attribute a(check(H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                               H5P_DEFAULT), "H5Acreate"));
  check_status(H5Awrite(a.get(), H5T_NATIVE_DOUBLE, values.data()), "H5Awrite");
}

std::vector<double> read_double_array_attribute(hid_t object, const char* name) {
  Attribute a(check(H5Aopen(object, name, H5P_DEFAULT), name));
  Dataspace space(check(H5Aget_space(a.get()), "H5Aget_space"));
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!values.empty()) check_status(H5Aread(a.get(), H5T_NATIVE_DOUBLE, values.data()), "H5Aread");
  return values;
}

double read_double_attribute(hid_t object, const char* name) {
  Attribute a(check(H5Aopen(object, name, H5P_DEFAULT), name));
  double value = 0;
  check_status(H5Aread(a.get(), H5T_NATIVE_DOUBLE, &value), "H5Aread");
  return value;
}

long read_long_attribute(hid_t object, const char* name) {
  Attribute a(check(H5Aopen(object, name, H5P_DEFAULT), name));
  long value = 0;
  check_status(H5Aread(a.get(), H5T_NATIVE_LONG, &value), "H5Aread");
  return value;
}

// A dataset of the given shape with `fill` as its declared fill value. HDF5 never writes the
// fill: the writer writes every element itself (rank 0 the elements no rank owns). In parallel
// HDF5 1.10 a fill written at creation is written by rank 0 alone, followed by a barrier that
// rank 0 skips when its write fails (a full disk), and the other ranks then wait there for good.
Dataset create_dataset(hid_t parent, const std::string& name, hid_t type,
                       const std::vector<hsize_t>& dims, const void* fill) {
  Dataspace space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                        "H5Screate_simple"));
  PropertyList create(check(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate(dataset)"));
  if (fill) {
    check_status(H5Pset_fill_value(create.get(), type, fill), "H5Pset_fill_value");
    check_status(H5Pset_alloc_time(create.get(), H5D_ALLOC_TIME_EARLY), "H5Pset_alloc_time");
    check_status(H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER), "H5Pset_fill_time");
  }
  return Dataset(check(H5Dcreate2(parent, name.c_str(), type, space.get(), H5P_DEFAULT,
                                  create.get(), H5P_DEFAULT), ("H5Dcreate " + name).c_str()));
}

// Writes (or reads) values at scattered points; collective transfer, ranks with no points
// select none.
void transfer_points(hid_t dataset, hid_t type, const std::vector<hsize_t>& coordinates, int rank,
                     void* buffer, bool write) {
  Dataspace file_space(check(H5Dget_space(dataset), "H5Dget_space"));
  const hsize_t count = coordinates.size() / static_cast<std::size_t>(rank);
  if (count > 0) {
    check_status(H5Sselect_elements(file_space.get(), H5S_SELECT_SET, count, coordinates.data()),
                 "H5Sselect_elements");
  } else {
    check_status(H5Sselect_none(file_space.get()), "H5Sselect_none");
  }
  const hsize_t memory_count = std::max<hsize_t>(count, 1);
  Dataspace memory_space(check(H5Screate_simple(1, &memory_count, nullptr), "H5Screate_simple"));
  if (count == 0) check_status(H5Sselect_none(memory_space.get()), "H5Sselect_none");
  PropertyList transfer(check(H5Pcreate(H5P_DATASET_XFER), "H5Pcreate(xfer)"));
  check_status(H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio");
  double dummy = 0;
  void* data = count > 0 ? buffer : &dummy;
  if (write) {
    check_status(H5Dwrite(dataset, type, memory_space.get(), file_space.get(), transfer.get(), data),
                 "H5Dwrite");
  } else {
    check_status(H5Dread(dataset, type, memory_space.get(), file_space.get(), transfer.get(), data),
                 "H5Dread");
  }
}

// Which owned cells go where: fluid cells to (k, j, i) of the 3-D arrays, boundary cells to
// their ordinal among all boundary cells in natural order. For writing, rank 0 also has the
// elements no rank owns (the box's cells that are not fluid; the one element of an empty
// boundary list), which it writes as the fill (create_dataset says why HDF5 does not).
struct Placement {
  std::vector<int> fluid_locals;
  std::vector<hsize_t> fluid_coordinates;  // 3 per point
  std::vector<int> boundary_locals;
  std::vector<hsize_t> boundary_coordinates;  // 1 per point
  std::vector<std::int64_t> boundary_naturals;  // all boundary cells, natural order
  std::vector<hsize_t> unowned_coordinates;  // 3 per point
  std::vector<hsize_t> unowned_boundary;     // 1 per point
};

std::vector<std::int64_t> all_boundary_naturals(const grid::CellFlags& flags) {
  std::vector<std::int64_t> out;
  out.reserve(static_cast<std::size_t>(flags.boundary_count));
  for (std::size_t c = 0; c < flags.kind.size(); ++c)
    if (flags.kind[c] == grid::CellKind::boundary) out.push_back(static_cast<std::int64_t>(c));
  return out;
}

void add_fluid_point(Placement& p, const grid::Index3& ijk, int local) {
  p.fluid_locals.push_back(local);
  p.fluid_coordinates.push_back(static_cast<hsize_t>(ijk[2]));
  p.fluid_coordinates.push_back(static_cast<hsize_t>(ijk[1]));
  p.fluid_coordinates.push_back(static_cast<hsize_t>(ijk[0]));
}

void add_boundary_point(Placement& p, std::int64_t natural, int local) {
  const auto it = std::lower_bound(p.boundary_naturals.begin(), p.boundary_naturals.end(), natural);
  p.boundary_locals.push_back(local);
  p.boundary_coordinates.push_back(static_cast<hsize_t>(it - p.boundary_naturals.begin()));
}

// Owned cells (for writing) or every local cell (for reading).
Placement place_cells(const parallel::Layout& layout, const grid::CellFlags& flags, bool all_local) {
  Placement p;
  p.boundary_naturals = all_boundary_naturals(flags);
  const int end = all_local ? layout.local_count() : layout.owned_count();
  for (int l = 0; l < end; ++l) {
    if (layout.kind(l) == grid::CellKind::fluid) {
      add_fluid_point(p, layout.index3(l), l);
    } else {
      add_boundary_point(p, layout.natural(l), l);
    }
  }
  if (all_local || !layout.comm().is_root()) return p;
  const auto& g = layout.grid();
  for (int k = 0; k < g.cells(2); ++k)
    for (int j = 0; j < g.cells(1); ++j)
      for (int i = 0; i < g.cells(0); ++i)
        if (flags.kind[static_cast<std::size_t>(g.natural({i, j, k}))] != grid::CellKind::fluid)
          p.unowned_coordinates.insert(p.unowned_coordinates.end(),
                                       {static_cast<hsize_t>(k), static_cast<hsize_t>(j),
                                        static_cast<hsize_t>(i)});
  if (p.boundary_naturals.empty()) p.unowned_boundary.push_back(0);
  return p;
}

// The points a rank writes a dataset at: its own, then (rank 0) those no rank owns, where it
// writes the fill.
std::vector<hsize_t> with_unowned(std::vector<hsize_t> coordinates, const std::vector<hsize_t>& unowned) {
  coordinates.insert(coordinates.end(), unowned.begin(), unowned.end());
  return coordinates;
}

std::vector<hsize_t> domain_dims(const grid::StructuredGrid& g) {
  return {static_cast<hsize_t>(g.cells(2)), static_cast<hsize_t>(g.cells(1)),
          static_cast<hsize_t>(g.cells(0))};
}

void write_grid(hid_t file, const parallel::Layout& layout, const grid::CellFlags& flags,
                const Steps& step) {
  const auto& g = layout.grid();
  const bool root = layout.comm().is_root();
  Group group;
  step([&] {
    group = Group(check(H5Gcreate2(file, "grid", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "H5Gcreate grid"));
  });
  const char* names[] = {"x_faces", "y_faces", "z_faces"};
  for (int d = 0; d < 3; ++d) {
    const auto& faces = g.axis(d).faces();
    // Small datasets: rank 0 writes them whole (independent transfer).
    step([&] {
      Dataset ds = create_dataset(group.get(), names[d], H5T_NATIVE_DOUBLE, {faces.size()}, nullptr);
      if (root)
        check_status(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, faces.data()),
                     "H5Dwrite faces");
    });
  }
  const std::uint8_t blocked = 0;
  step([&] {
    Dataset ds = create_dataset(group.get(), "cell_flags", H5T_NATIVE_UINT8, domain_dims(g), &blocked);
    if (!root) return;
    std::vector<std::uint8_t> domain;
    domain.reserve(static_cast<std::size_t>(g.domain_cell_count()));
    for (int k = 0; k < g.cells(2); ++k)
      for (int j = 0; j < g.cells(1); ++j)
        for (int i = 0; i < g.cells(0); ++i)
          domain.push_back(static_cast<std::uint8_t>(
              flags.kind[static_cast<std::size_t>(g.natural({i, j, k}))]));
    check_status(H5Dwrite(ds.get(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, domain.data()),
                 "H5Dwrite cell_flags");
  });
}

// The cell vectors, /fields/NAME of shape (nz, ny, nx, 3): this rank's fluid cells, NaN elsewhere,
// each with its checksum (component fastest in the element index).
void write_cell_vectors(hid_t field_group, const parallel::Layout& layout, const Placement& placement,
                        const std::vector<CellVectorView>& vectors, const Steps& step) {
  if (vectors.empty()) return;
  auto dims = domain_dims(layout.grid());
  dims.push_back(3);
  const double fill = std::numeric_limits<double>::quiet_NaN();
  const std::size_t points = placement.fluid_locals.size();
  std::vector<hsize_t> coordinates;
  coordinates.reserve(12 * points);
  const auto cells = with_unowned(placement.fluid_coordinates, placement.unowned_coordinates);
  for (std::size_t p = 0; p < cells.size() / 3; ++p)
    for (hsize_t c = 0; c < 3; ++c) {
      const hsize_t* at = &cells[3 * p];
      coordinates.insert(coordinates.end(), {at[0], at[1], at[2], c});
    }
  std::vector<std::uint64_t> checksums(vectors.size(), 0);
  std::vector<std::vector<double>> buffers(vectors.size());
  for (std::size_t v = 0; v < vectors.size(); ++v) {
    auto& buffer = buffers[v];
    buffer.reserve(3 * points);
    for (std::size_t p = 0; p < points; ++p) {
      const auto l = static_cast<std::size_t>(placement.fluid_locals[p]);
      const hsize_t* at = &placement.fluid_coordinates[3 * p];
      for (std::size_t c = 0; c < 3; ++c) {
        const double value = vectors[v].values[3 * l + c];
        const std::uint64_t e = ((at[0] * dims[1] + at[1]) * dims[2] + at[2]) * 3 + c;
        checksums[v] += element_hash(e, value) - element_hash(e, fill);
        buffer.push_back(value);
      }
    }
    buffer.resize(coordinates.size() / 4, fill);
  }
  MPI_Allreduce(MPI_IN_PLACE, checksums.data(), static_cast<int>(checksums.size()), MPI_UINT64_T,
                MPI_SUM, layout.comm().get());
  const std::uint64_t base = uniform_checksum(dims[0] * dims[1] * dims[2] * 3, fill);
  for (std::size_t v = 0; v < vectors.size(); ++v) {
    Dataset ds;
    step([&] {
      ds = create_dataset(field_group, vectors[v].name, H5T_NATIVE_DOUBLE, dims, &fill);
      write_utf8_attribute(ds.get(), "centering", centering_name(Centering::cell));
      if (!vectors[v].units.empty()) write_utf8_attribute(ds.get(), "units", vectors[v].units);
    });
    step([&] {
      transfer_points(ds.get(), H5T_NATIVE_DOUBLE, coordinates, 4, buffers[v].data(), true);
      write_checksum_attribute(ds.get(), base + checksums[v]);
    });
  }
}

// The opening faces, /openings: their geometry (rank 0 writes it whole: it is the same on every
// rank) and each field's values on the faces each rank owns, with a checksum.
void write_openings(hid_t file, const parallel::Communicator& comm, const OpeningsView& openings,
                    const Steps& step) {
  const auto& faces = openings.faces;
  if (faces.empty()) return;
  const hsize_t n = faces.size();
  Group group;
  Dataset points, quads, region;
  step([&] {
    group = Group(check(H5Gcreate2(file, "openings", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        "H5Gcreate openings"));
    write_utf8_array_attribute(group.get(), "region_names", openings.region_names);
    points = create_dataset(group.get(), "points", H5T_NATIVE_DOUBLE, {4 * n, 3}, nullptr);
    write_utf8_attribute(points.get(), "units", "m");
    quads = create_dataset(group.get(), "quads", H5T_NATIVE_INT32, {n, 4}, nullptr);
    region = create_dataset(group.get(), "region", H5T_NATIVE_INT32, {n}, nullptr);
  });
  step([&] {
    if (!comm.is_root()) return;
    std::vector<double> xyz;
    std::vector<std::int32_t> corners, regions;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      for (const auto& corner : faces[f].corners) xyz.insert(xyz.end(), corner.begin(), corner.end());
      for (int c = 0; c < 4; ++c) corners.push_back(static_cast<std::int32_t>(4 * f) + c);
      regions.push_back(faces[f].region);
    }
    check_status(H5Dwrite(points.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, xyz.data()),
                 "H5Dwrite openings/points");
    check_status(H5Dwrite(quads.get(), H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, corners.data()),
                 "H5Dwrite openings/quads");
    check_status(H5Dwrite(region.get(), H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, regions.data()),
                 "H5Dwrite openings/region");
  });
  const double fill = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint64_t> checksums(openings.fields.size(), 0);
  for (std::size_t v = 0; v < openings.fields.size(); ++v) {
    const auto& field = openings.fields[v];
    const auto width = static_cast<std::size_t>(field.width);
    for (std::size_t p = 0; p < openings.owned.size(); ++p)
      for (std::size_t c = 0; c < width; ++c) {
        const std::uint64_t e = openings.owned[p] * width + c;
        checksums[v] += element_hash(e, field.values[p * width + c]) - element_hash(e, fill);
      }
  }
  MPI_Allreduce(MPI_IN_PLACE, checksums.data(), static_cast<int>(checksums.size()), MPI_UINT64_T,
                MPI_SUM, comm.get());
  for (std::size_t v = 0; v < openings.fields.size(); ++v) {
    const auto& field = openings.fields[v];
    const auto width = static_cast<hsize_t>(field.width);
    const bool scalar = width == 1;
    std::vector<hsize_t> dims = {n};
    if (!scalar) dims.push_back(width);
    std::vector<hsize_t> coordinates;
    for (const std::size_t f : openings.owned)
      for (hsize_t c = 0; c < width; ++c) {
        coordinates.push_back(f);
        if (!scalar) coordinates.push_back(c);
      }
    Dataset ds;
    step([&] {
      ds = create_dataset(group.get(), field.name, H5T_NATIVE_DOUBLE, dims, &fill);
      if (!field.units.empty()) write_utf8_attribute(ds.get(), "units", field.units);
    });
    step([&] {
      transfer_points(ds.get(), H5T_NATIVE_DOUBLE, coordinates, scalar ? 1 : 2,
                      const_cast<double*>(field.values.data()), true);
      write_checksum_attribute(ds.get(), uniform_checksum(n * width, fill) + checksums[v]);
    });
  }
}

// After an agreed failure: the file is left open (failed_file.hpp says why).
void abandon_after_failed_write(File& file) { leave_failed_file_open(file.release()); }

// Whether the open snapshot has the dataset /fields/NAME.
bool has_field(hid_t file, const std::string& name) {
  return H5Lexists(file, "fields", H5P_DEFAULT) > 0 &&
         H5Lexists(file, ("fields/" + name).c_str(), H5P_DEFAULT) > 0;
}

}  // namespace

SnapshotHeader read_snapshot_header(const std::string& path, const std::vector<std::string>& names) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (file.get() < 0) throw Hdf5Error("cannot open snapshot " + path);
  SnapshotHeader header;
  header.time = read_double_attribute(file.get(), "time");
  for (const auto& name : names)
    if (!has_field(file.get(), name)) header.absent_fields.push_back(name);
  if (H5Lexists(file.get(), "openings", H5P_DEFAULT) > 0 &&
      H5Lexists(file.get(), "openings/region", H5P_DEFAULT) > 0) {
    Dataset ds(check(H5Dopen2(file.get(), "openings/region", H5P_DEFAULT), "openings/region"));
    Dataspace space(check(H5Dget_space(ds.get()), "H5Dget_space"));
    header.opening_faces = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
  }
  return header;
}

std::optional<std::string> read_text_attribute(const std::string& path, const std::string& name) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (file.get() < 0) throw Hdf5Error("cannot open snapshot " + path);
  if (H5Aexists(file.get(), name.c_str()) <= 0) return std::nullopt;
  Attribute a(check(H5Aopen(file.get(), name.c_str(), H5P_DEFAULT), name.c_str()));
  Datatype stored(check(H5Aget_type(a.get()), "H5Aget_type"));
  if (H5Tget_class(stored.get()) != H5T_STRING)
    throw Hdf5Error("snapshot " + path + ": attribute '" + name + "' is not a string");
  Datatype type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"));
  if (H5Tis_variable_str(stored.get()) > 0) {
    check_status(H5Tset_size(type.get(), H5T_VARIABLE), "H5Tset_size");
    check_status(H5Tset_cset(type.get(), H5Tget_cset(stored.get())), "H5Tset_cset");
    char* text = nullptr;
    check_status(H5Aread(a.get(), type.get(), &text), "H5Aread");
    std::string value = text ? text : "";
    H5free_memory(text);  // HDF5 allocated it
    return value;
  }
  const std::size_t size = H5Tget_size(stored.get());
  check_status(H5Tset_size(type.get(), size + 1), "H5Tset_size");
  std::string value(size + 1, '\0');
  check_status(H5Aread(a.get(), type.get(), value.data()), "H5Aread");
  value.resize(value.find('\0') == std::string::npos ? size : value.find('\0'));
  return value;
}

const char* centering_name(Centering c) {
  switch (c) {
    case Centering::cell: return "cell";
    case Centering::x_face: return "x_face";
    case Centering::y_face: return "y_face";
    case Centering::z_face: return "z_face";
  }
  return "cell";
}

std::uintmax_t snapshot_size_estimate(const parallel::Layout& layout, const grid::CellFlags& flags,
                                      std::size_t field_count, const SnapshotInfo& info,
                                      std::size_t vector_count, std::size_t opening_faces,
                                      std::size_t opening_values) {
  const auto& g = layout.grid();
  const auto cells = static_cast<std::uintmax_t>(g.domain_cell_count());
  const auto boundary = static_cast<std::uintmax_t>(std::max<std::int64_t>(flags.boundary_count, 1));
  const std::uintmax_t faces = static_cast<std::uintmax_t>(g.cells(0) + g.cells(1) + g.cells(2) + 3);
  std::uintmax_t attributes = 8 * info.time_step_memory.size() + info.title.size() + 512;
  for (const auto& r : info.record)
    attributes += r.name.size() + 32 +
                  (std::holds_alternative<std::string>(r.value) ? std::get<std::string>(r.value).size() : 8);
  // fields and their boundary values, the grid, the vectors, the openings' geometry and values
  const std::uintmax_t datasets = 2 * field_count + 5 + vector_count + (opening_faces > 0 ? 4 : 0) +
                                  (opening_faces > 0 ? opening_values : 0);
  // per opening face: 4 corners of 3 doubles, 4 corner numbers and a region (int32), its values
  const std::uintmax_t openings = opening_faces * (96 + 20 + 8 * opening_values) + 1024;
  return field_count * (cells + boundary) * 8 + vector_count * cells * 24 + cells + boundary * 8 +
         faces * 8 + attributes + (opening_faces > 0 ? openings : 0) + 2048 * datasets + 4096;
}

void write_snapshot(const std::string& path, const parallel::Layout& layout,
                    const grid::CellFlags& flags, const std::vector<FieldView>& fields,
                    const SnapshotInfo& info, const ViewingData& viewing, std::uintmax_t reserve) {
  const std::string temporary = path + ".tmp";
  const auto& comm = layout.comm();
  const Steps step(comm);
  const Placement placement = place_cells(layout, flags, false);
  File file;
  try {
    step([&] {
      file = open_parallel(temporary, comm.get(), true);
      if (file.get() < 0) throw Hdf5Error("cannot create snapshot file " + temporary);
    });
    step([&] {
      if (comm.is_root() && reserve > 0) reserve_disk_space(temporary, reserve);
    });
    step([&] {
      write_attribute(file.get(), "time", info.time);
      write_attribute(file.get(), "step", info.step);
      write_attribute(file.get(), "dt", info.dt);
      write_attribute(file.get(), "dt_next", info.dt_next > 0 ? info.dt_next : info.dt);
      if (!info.time_step_memory.empty())
        write_attribute(file.get(), "time_step_memory", info.time_step_memory);
      write_attribute(file.get(), "format_version", static_cast<long>(format_version));
      write_utf8_attribute(file.get(), "bagnold_version", version());
      write_utf8_attribute(file.get(), "title", info.title);
      for (const auto& r : info.record) {
        if (const auto* text = std::get_if<std::string>(&r.value))
          write_utf8_attribute(file.get(), r.name.c_str(), *text);
        else
          write_attribute(file.get(), r.name.c_str(), std::get<long>(r.value));
      }
    });
    write_grid(file.get(), layout, flags, step);

    Group field_group, boundary_group;
    const hsize_t boundary_total = placement.boundary_naturals.size();
    step([&] {
      field_group = Group(check(H5Gcreate2(file.get(), "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                "H5Gcreate fields"));
      boundary_group = Group(check(H5Gcreate2(file.get(), "boundary", H5P_DEFAULT, H5P_DEFAULT,
                                              H5P_DEFAULT), "H5Gcreate boundary"));
      Dataset ds = create_dataset(boundary_group.get(), "natural", H5T_NATIVE_INT64,
                                  {std::max<hsize_t>(boundary_total, 1)}, nullptr);
      if (comm.is_root() && boundary_total > 0)
        check_status(H5Dwrite(ds.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                              placement.boundary_naturals.data()), "H5Dwrite natural");
    });
    const double fill = std::numeric_limits<double>::quiet_NaN();
    // Each dataset's checksum (snapshot_check.hpp): this rank's points, summed over the ranks.
    const auto dims = domain_dims(layout.grid());
    const std::uint64_t boundary_elements = std::max<hsize_t>(boundary_total, 1);
    std::vector<std::uint64_t> checksums(2 * fields.size(), 0);
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const auto& values = fields[f].values;
      for (std::size_t p = 0; p < placement.fluid_locals.size(); ++p) {
        const hsize_t* c = &placement.fluid_coordinates[3 * p];
        const std::uint64_t e = (c[0] * dims[1] + c[1]) * dims[2] + c[2];
        checksums[2 * f] += element_hash(e, values[static_cast<std::size_t>(placement.fluid_locals[p])]) -
                            element_hash(e, fill);
      }
      for (std::size_t p = 0; p < placement.boundary_locals.size(); ++p) {
        const std::uint64_t e = placement.boundary_coordinates[p];
        checksums[2 * f + 1] +=
            element_hash(e, values[static_cast<std::size_t>(placement.boundary_locals[p])]) - element_hash(e, fill);
      }
    }
    MPI_Allreduce(MPI_IN_PLACE, checksums.data(), static_cast<int>(checksums.size()), MPI_UINT64_T,
                  MPI_SUM, comm.get());
    const std::uint64_t fluid_base = uniform_checksum(dims[0] * dims[1] * dims[2], fill);
    const std::uint64_t boundary_base = uniform_checksum(boundary_elements, fill);
    const auto field_coordinates = with_unowned(placement.fluid_coordinates, placement.unowned_coordinates);
    const auto boundary_coordinates = with_unowned(placement.boundary_coordinates, placement.unowned_boundary);
    std::vector<double> buffer;
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const auto& field = fields[f];
      Dataset ds, bs;
      step([&] {
        ds = create_dataset(field_group.get(), field.name, H5T_NATIVE_DOUBLE, dims, &fill);
        write_utf8_attribute(ds.get(), "centering", centering_name(field.centering));
        if (!field.units.empty()) write_utf8_attribute(ds.get(), "units", field.units);
      });
      step([&] {
        buffer.clear();
        for (const int l : placement.fluid_locals) buffer.push_back(field.values[static_cast<std::size_t>(l)]);
        buffer.resize(field_coordinates.size() / 3, fill);
        transfer_points(ds.get(), H5T_NATIVE_DOUBLE, field_coordinates, 3, buffer.data(), true);
        write_checksum_attribute(ds.get(), fluid_base + checksums[2 * f]);
      });
      step([&] {
        bs = create_dataset(boundary_group.get(), field.name, H5T_NATIVE_DOUBLE,
                            {boundary_elements}, &fill);
      });
      step([&] {
        buffer.clear();
        for (const int l : placement.boundary_locals) buffer.push_back(field.values[static_cast<std::size_t>(l)]);
        buffer.resize(boundary_coordinates.size(), fill);
        transfer_points(bs.get(), H5T_NATIVE_DOUBLE, boundary_coordinates, 1, buffer.data(), true);
        write_checksum_attribute(bs.get(), boundary_base + checksums[2 * f + 1]);
      });
    }
    write_cell_vectors(field_group.get(), layout, placement, viewing.cell_vectors, step);
    write_openings(file.get(), comm, viewing.openings, step);
    step([&] { check_status(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "H5Fflush"); });
    step([&] {
      field_group.reset();  // H5Fclose refuses a file with open objects (H5F_CLOSE_SEMI)
      boundary_group.reset();
      check_status(H5Fclose(file.release()), "H5Fclose");
    });
  } catch (const Hdf5Error& e) {
    // Every rank is here (each step is agreed on). The final name is never touched: earlier
    // snapshots stay as they were.
    if (comm.is_root()) std::remove(temporary.c_str());
    abandon_after_failed_write(file);
    throw Hdf5Error("cannot write the snapshot " + path + " (" + e.what() + "; disk full?)");
  }
  agree(comm, [&] {
    if (!comm.is_root()) return;
    release_unused_reservation(temporary);
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw Hdf5Error("cannot rename " + temporary + " to " + path);
  });
}

SnapshotContents read_snapshot(const std::string& path, const parallel::Layout& layout,
                               const std::vector<std::string>& names,
                               std::vector<std::vector<double>>& fields,
                               const std::vector<std::string>& optional) {
  const auto& g = layout.grid();
  File file = open_parallel(path, layout.comm().get(), false);
  if (file.get() < 0) throw Hdf5Error("cannot open snapshot " + path);
  SnapshotContents contents;
  contents.info.time = read_double_attribute(file.get(), "time");
  contents.info.dt = read_double_attribute(file.get(), "dt");
  contents.info.step = read_long_attribute(file.get(), "step");
  contents.info.dt_next = H5Aexists(file.get(), "dt_next") > 0
                              ? read_double_attribute(file.get(), "dt_next") : contents.info.dt;
  if (H5Aexists(file.get(), "time_step_memory") > 0)
    contents.info.time_step_memory = read_double_array_attribute(file.get(), "time_step_memory");

  // The grid must be the one this run uses, face by face.
  const char* face_names[] = {"grid/x_faces", "grid/y_faces", "grid/z_faces"};
  for (int d = 0; d < 3; ++d) {
    Dataset ds(check(H5Dopen2(file.get(), face_names[d], H5P_DEFAULT), face_names[d]));
    Dataspace space(check(H5Dget_space(ds.get()), "H5Dget_space"));
    const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
    const auto& faces = g.axis(d).faces();
    std::vector<double> stored(n);
    if (n == faces.size())
      check_status(H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, stored.data()),
                   "H5Dread faces");
    bool same = n == faces.size();
    for (std::size_t i = 0; same && i < n; ++i)
      same = std::abs(stored[i] - faces[i]) <= 1e-12 * (1.0 + std::abs(faces[i]));
    if (!same)
      throw Hdf5Error("snapshot " + path + " was written on another grid (" +
                      std::string("xyz").substr(static_cast<std::size_t>(d), 1) + ": " +
                      std::to_string(static_cast<long>(n) - 1) + " cells in the file, " +
                      std::to_string(g.cells(d)) + " in this deck, or different coordinates)");
  }

  // Boundary ordinals come from the file's list, not from this run's flags.
  Placement placement;
  {
    Dataset ds(check(H5Dopen2(file.get(), "boundary/natural", H5P_DEFAULT), "boundary/natural"));
    Dataspace space(check(H5Dget_space(ds.get()), "H5Dget_space"));
    std::vector<std::int64_t> naturals(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
    check_status(H5Dread(ds.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, naturals.data()),
                 "H5Dread natural");
    placement.boundary_naturals = std::move(naturals);
  }
  for (int l = 0; l < layout.local_count(); ++l) {
    if (layout.kind(l) == grid::CellKind::fluid) {
      add_fluid_point(placement, layout.index3(l), l);
    } else {
      const auto it = std::lower_bound(placement.boundary_naturals.begin(),
                                       placement.boundary_naturals.end(), layout.natural(l));
      if (it == placement.boundary_naturals.end() || *it != layout.natural(l))
        throw Hdf5Error("snapshot " + path + " has different geometry: a boundary cell of this "
                        "deck is not a boundary cell in the file");
      add_boundary_point(placement, layout.natural(l), l);
    }
  }

  fields.assign(names.size(), std::vector<double>(static_cast<std::size_t>(layout.local_count())));
  std::vector<double> buffer;
  for (std::size_t f = 0; f < names.size(); ++f) {
    const std::string field_path = "fields/" + names[f];
    if (!has_field(file.get(), names[f])) {
      if (std::find(optional.begin(), optional.end(), names[f]) == optional.end())
        throw Hdf5Error("snapshot " + path + " has no field '" + names[f] + "'");
      std::fill(fields[f].begin(), fields[f].end(), std::nan(""));
      continue;
    }
    Dataset ds(check(H5Dopen2(file.get(), field_path.c_str(), H5P_DEFAULT), field_path.c_str()));
    buffer.assign(placement.fluid_locals.size(), 0.0);
    transfer_points(ds.get(), H5T_NATIVE_DOUBLE, placement.fluid_coordinates, 3, buffer.data(), false);
    for (std::size_t p = 0; p < buffer.size(); ++p)
      fields[f][static_cast<std::size_t>(placement.fluid_locals[p])] = buffer[p];

    const std::string boundary_path = "boundary/" + names[f];
    Dataset bs(check(H5Dopen2(file.get(), boundary_path.c_str(), H5P_DEFAULT), boundary_path.c_str()));
    buffer.assign(placement.boundary_locals.size(), 0.0);
    transfer_points(bs.get(), H5T_NATIVE_DOUBLE, placement.boundary_coordinates, 1, buffer.data(), false);
    for (std::size_t p = 0; p < buffer.size(); ++p)
      fields[f][static_cast<std::size_t>(placement.boundary_locals[p])] = buffer[p];
    contents.field_names.push_back(names[f]);
  }
  return contents;
}

}  // namespace bagnold::io
