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
#include "src/io/hdf5_read.hpp"
#include "src/io/root_gather.hpp"
#include "src/io/snapshot_check.hpp"
#include "src/util/build_info.hpp"

namespace bagnold::io {

namespace {

constexpr int format_version = 1;

// Rank 0 writes the snapshot alone, with HDF5's default (serial) driver, from the values every
// rank sends it (root_gather.hpp): no HDF5 call of the write involves another rank, so a failure
// anywhere inside HDF5 (a full disk, in the data or in its metadata flush) cannot leave the ranks
// in different collective calls. Each step runs on rank 0, and its outcome is agreed on by every
// rank (agree.hpp) before any rank goes on to the next gather.
class RootSteps {
 public:
  explicit RootSteps(const parallel::Communicator& comm) : m_comm(comm) {}
  void operator()(const std::function<void()>& step) const {
    agree(m_comm, [&] {
      if (m_comm.is_root()) step();
    });
  }

 private:
  const parallel::Communicator& m_comm;
};

File create_file(const std::string& path) {
  // Errors are reported by exceptions with a message; HDF5's own stack dump would only add noise.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  File file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  if (file.get() < 0) throw Hdf5Error("cannot create snapshot file " + path);
  return file;
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

// A dataset of the given shape, with `fill` (if any) as its declared fill value. The writer
// writes every element itself (`fill` where no rank owns one), so HDF5 is told never to write the
// fill. The space is allocated at creation, as parallel HDF5 requires: these creation properties
// are stored in the file, and a snapshot's are the same whichever driver wrote it.
Dataset create_dataset(hid_t parent, const std::string& name, hid_t type,
                       const std::vector<hsize_t>& dims, const void* fill) {
  Dataspace space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                        "H5Screate_simple"));
  PropertyList create(check(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate(dataset)"));
  check_status(H5Pset_alloc_time(create.get(), H5D_ALLOC_TIME_EARLY), "H5Pset_alloc_time");
  if (fill) {
    check_status(H5Pset_fill_value(create.get(), type, fill), "H5Pset_fill_value");
    check_status(H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER), "H5Pset_fill_time");
  }
  return Dataset(check(H5Dcreate2(parent, name.c_str(), type, space.get(), H5P_DEFAULT,
                                  create.get(), H5P_DEFAULT), ("H5Dcreate " + name).c_str()));
}

std::vector<hsize_t> domain_dims(const grid::StructuredGrid& g) {
  return {static_cast<hsize_t>(g.cells(2)), static_cast<hsize_t>(g.cells(1)),
          static_cast<hsize_t>(g.cells(0))};
}

// The element of cell (i, j, k) in a (nz, ny, nx) array, row-major.
std::uint64_t domain_element(const grid::StructuredGrid& g, const grid::Index3& ijk) {
  return (static_cast<std::uint64_t>(ijk[2]) * static_cast<std::uint64_t>(g.cells(1)) +
          static_cast<std::uint64_t>(ijk[1])) * static_cast<std::uint64_t>(g.cells(0)) +
         static_cast<std::uint64_t>(ijk[0]);
}

std::uint64_t product(const std::vector<hsize_t>& dims) {
  std::uint64_t n = 1;
  for (const auto d : dims) n *= d;
  return n;
}

// Which cells go where: fluid cells to their element of the (nz, ny, nx) arrays, boundary cells
// to their ordinal in the snapshot's list of boundary cells (natural order).
struct Placement {
  std::vector<int> fluid_locals;
  std::vector<std::uint64_t> fluid_elements;
  std::vector<int> boundary_locals;
  std::vector<std::uint64_t> boundary_elements;
};

std::vector<std::int64_t> all_boundary_naturals(const grid::CellFlags& flags) {
  std::vector<std::int64_t> out;
  out.reserve(static_cast<std::size_t>(flags.boundary_count));
  for (std::size_t c = 0; c < flags.kind.size(); ++c)
    if (flags.kind[c] == grid::CellKind::boundary) out.push_back(static_cast<std::int64_t>(c));
  return out;
}

// The first `count` local cells (the owned ones, for writing; all, halo included, for reading).
// Throws when a boundary cell is not in `boundary_naturals` (a snapshot of other geometry).
Placement place_cells(const parallel::Layout& layout, int count,
                      const std::vector<std::int64_t>& boundary_naturals, const std::string& path) {
  Placement p;
  for (int l = 0; l < count; ++l) {
    if (layout.kind(l) == grid::CellKind::fluid) {
      p.fluid_locals.push_back(l);
      p.fluid_elements.push_back(domain_element(layout.grid(), layout.index3(l)));
      continue;
    }
    const auto it = std::lower_bound(boundary_naturals.begin(), boundary_naturals.end(), layout.natural(l));
    if (it == boundary_naturals.end() || *it != layout.natural(l))
      throw Hdf5Error("snapshot " + path + " has different geometry: a boundary cell of this "
                      "deck is not a boundary cell in the file");
    p.boundary_locals.push_back(l);
    p.boundary_elements.push_back(static_cast<std::uint64_t>(it - boundary_naturals.begin()));
  }
  return p;
}

// `width` values per listed local cell, in the order listed.
std::vector<double> values_at(std::span<const double> values, const std::vector<int>& locals, int width) {
  const auto w = static_cast<std::size_t>(width);
  std::vector<double> out;
  out.reserve(locals.size() * w);
  for (const int l : locals)
    for (std::size_t c = 0; c < w; ++c) out.push_back(values[static_cast<std::size_t>(l) * w + c]);
  return out;
}

// The whole of dataset `ds` from `whole`, and its checksum (snapshot_check.hpp).
void write_array(const Dataset& ds, const std::vector<double>& whole) {
  check_status(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, whole.data()),
               "H5Dwrite");
  write_checksum_attribute(ds.get(), checksum(whole));
}

void write_grid(hid_t file, const grid::StructuredGrid& g, const grid::CellFlags& flags,
                const RootSteps& step) {
  step([&] {
    Group group(check(H5Gcreate2(file, "grid", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "H5Gcreate grid"));
    const char* names[] = {"x_faces", "y_faces", "z_faces"};
    for (int d = 0; d < 3; ++d) {
      const auto& faces = g.axis(d).faces();
      Dataset ds = create_dataset(group.get(), names[d], H5T_NATIVE_DOUBLE, {faces.size()}, nullptr);
      check_status(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, faces.data()),
                   "H5Dwrite faces");
    }
    const std::uint8_t blocked = 0;
    Dataset ds = create_dataset(group.get(), "cell_flags", H5T_NATIVE_UINT8, domain_dims(g), &blocked);
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

// The cell vectors, /fields/NAME of shape (nz, ny, nx, 3): the fluid cells' values, NaN
// elsewhere, each with its checksum (component fastest in the element index).
void write_cell_vectors(hid_t field_group, const grid::StructuredGrid& g, const Placement& placement,
                        const RootGather& fluid, const std::vector<CellVectorView>& vectors,
                        const RootSteps& step) {
  auto dims = domain_dims(g);
  dims.push_back(3);
  const double fill = std::numeric_limits<double>::quiet_NaN();
  for (const auto& vector : vectors) {
    const auto whole = fluid.gather(values_at(vector.values, placement.fluid_locals, 3), 3, fill);
    step([&] {
      Dataset ds = create_dataset(field_group, vector.name, H5T_NATIVE_DOUBLE, dims, &fill);
      write_utf8_attribute(ds.get(), "centering", centering_name(Centering::cell));
      if (!vector.units.empty()) write_utf8_attribute(ds.get(), "units", vector.units);
      write_array(ds, whole);
    });
  }
}

// The opening faces, /openings: their geometry (the same on every rank: rank 0 writes its own)
// and each field's values on the faces, gathered from the ranks that own them, with a checksum.
void write_openings(hid_t file, const parallel::Communicator& comm, const OpeningsView& openings,
                    const RootSteps& step) {
  const auto& faces = openings.faces;
  if (faces.empty()) return;
  const hsize_t n = faces.size();
  Group group;
  step([&] {
    group = Group(check(H5Gcreate2(file, "openings", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        "H5Gcreate openings"));
    write_utf8_array_attribute(group.get(), "region_names", openings.region_names);
    Dataset points = create_dataset(group.get(), "points", H5T_NATIVE_DOUBLE, {4 * n, 3}, nullptr);
    write_utf8_attribute(points.get(), "units", "m");
    Dataset quads = create_dataset(group.get(), "quads", H5T_NATIVE_INT32, {n, 4}, nullptr);
    Dataset region = create_dataset(group.get(), "region", H5T_NATIVE_INT32, {n}, nullptr);
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
  const RootGather owned(comm, {openings.owned.begin(), openings.owned.end()}, n);
  const double fill = std::numeric_limits<double>::quiet_NaN();
  for (const auto& field : openings.fields) {
    const auto whole = owned.gather(field.values, field.width, fill);
    std::vector<hsize_t> dims = {n};
    if (field.width != 1) dims.push_back(static_cast<hsize_t>(field.width));
    step([&] {
      Dataset ds = create_dataset(group.get(), field.name, H5T_NATIVE_DOUBLE, dims, &fill);
      if (!field.units.empty()) write_utf8_attribute(ds.get(), "units", field.units);
      write_array(ds, whole);
    });
  }
}

// Whether the open snapshot has the dataset /fields/NAME.
bool has_field(hid_t file, const std::string& name) {
  return H5Lexists(file, "fields", H5P_DEFAULT) > 0 &&
         H5Lexists(file, ("fields/" + name).c_str(), H5P_DEFAULT) > 0;
}

}  // namespace

SnapshotHeader read_snapshot_header(const std::string& path, const std::vector<std::string>& names) {
  File file = open_snapshot_readonly(path);
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
  File file = open_snapshot_readonly(path);
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
  const auto& g = layout.grid();
  const RootSteps step(comm);
  const auto boundary_naturals = all_boundary_naturals(flags);
  const Placement placement = place_cells(layout, layout.owned_count(), boundary_naturals, path);
  const auto dims = domain_dims(g);
  // A snapshot without boundary cells stores one element in each boundary dataset (the fill).
  const hsize_t boundary_elements = std::max<hsize_t>(boundary_naturals.size(), 1);
  const RootGather fluid(comm, placement.fluid_elements, product(dims));
  const RootGather boundary(comm, placement.boundary_elements, boundary_elements);
  File file;  // rank 0's
  bool created = false;  // on every rank: whether rank 0 has the file open
  try {
    step([&] { file = create_file(temporary); });
    created = true;
    step([&] {
      if (reserve > 0) reserve_disk_space(temporary, reserve);
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
    write_grid(file.get(), g, flags, step);

    Group field_group, boundary_group;
    step([&] {
      field_group = Group(check(H5Gcreate2(file.get(), "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                "H5Gcreate fields"));
      boundary_group = Group(check(H5Gcreate2(file.get(), "boundary", H5P_DEFAULT, H5P_DEFAULT,
                                              H5P_DEFAULT), "H5Gcreate boundary"));
      Dataset ds = create_dataset(boundary_group.get(), "natural", H5T_NATIVE_INT64,
                                  {boundary_elements}, nullptr);
      if (!boundary_naturals.empty())
        check_status(H5Dwrite(ds.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                              boundary_naturals.data()), "H5Dwrite natural");
    });
    const double fill = std::numeric_limits<double>::quiet_NaN();
    // Rank 0 holds one whole array at a time (a field on the domain's cells, or its boundary cells).
    for (const auto& field : fields) {
      auto whole = fluid.gather(values_at(field.values, placement.fluid_locals, 1), 1, fill);
      step([&] {
        Dataset ds = create_dataset(field_group.get(), field.name, H5T_NATIVE_DOUBLE, dims, &fill);
        write_utf8_attribute(ds.get(), "centering", centering_name(field.centering));
        if (!field.units.empty()) write_utf8_attribute(ds.get(), "units", field.units);
        write_array(ds, whole);
      });
      whole = boundary.gather(values_at(field.values, placement.boundary_locals, 1), 1, fill);
      step([&] {
        Dataset bs = create_dataset(boundary_group.get(), field.name, H5T_NATIVE_DOUBLE,
                                    {boundary_elements}, &fill);
        write_array(bs, whole);
      });
    }
    write_cell_vectors(field_group.get(), g, placement, fluid, viewing.cell_vectors, step);
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
    if (created) leave_failed_file_open(file.release());
    throw Hdf5Error("cannot write the snapshot " + path + " (" + e.what() + "; disk full?)");
  }
  agree(comm, [&] {
    if (!comm.is_root()) return;
    release_unused_reservation(temporary);
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw Hdf5Error("cannot rename " + temporary + " to " + path);
  });
}

namespace {

// One rank's part of read_snapshot, with its own serial HDF5 file.
SnapshotContents read_local(const std::string& path, const parallel::Layout& layout,
                            const std::vector<std::string>& names,
                            std::vector<std::vector<double>>& fields,
                            const std::vector<std::string>& optional) {
  const auto& g = layout.grid();
  File file = open_snapshot_readonly(path);
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
    const auto stored = read_doubles(file.get(), face_names[d]);
    const auto& faces = g.axis(d).faces();
    bool same = stored.size() == faces.size();
    for (std::size_t i = 0; same && i < stored.size(); ++i)
      same = std::abs(stored[i] - faces[i]) <= 1e-12 * (1.0 + std::abs(faces[i]));
    if (!same)
      throw Hdf5Error("snapshot " + path + " was written on another grid (" +
                      std::string("xyz").substr(static_cast<std::size_t>(d), 1) + ": " +
                      std::to_string(static_cast<long>(stored.size()) - 1) + " cells in the file, " +
                      std::to_string(g.cells(d)) + " in this deck, or different coordinates)");
  }

  // Boundary ordinals come from the file's list, not from this run's flags.
  const Placement placement =
      place_cells(layout, layout.local_count(), read_int64s(file.get(), "boundary/natural"), path);
  fields.assign(names.size(), std::vector<double>(static_cast<std::size_t>(layout.local_count())));
  // Each rank reads one whole dataset at a time and takes its cells from it.
  const auto take = [&](const std::string& dataset, const std::vector<int>& locals,
                        const std::vector<std::uint64_t>& elements, std::vector<double>& out) {
    const auto whole = read_doubles(file.get(), dataset);
    for (std::size_t p = 0; p < locals.size(); ++p) {
      if (elements[p] >= whole.size())
        throw Hdf5Error("snapshot " + path + ": dataset " + dataset + " is smaller than the grid");
      out[static_cast<std::size_t>(locals[p])] = whole[elements[p]];
    }
  };
  for (std::size_t f = 0; f < names.size(); ++f) {
    if (!has_field(file.get(), names[f])) {
      if (std::find(optional.begin(), optional.end(), names[f]) == optional.end())
        throw Hdf5Error("snapshot " + path + " has no field '" + names[f] + "'");
      std::fill(fields[f].begin(), fields[f].end(), std::nan(""));
      continue;
    }
    take("fields/" + names[f], placement.fluid_locals, placement.fluid_elements, fields[f]);
    take("boundary/" + names[f], placement.boundary_locals, placement.boundary_elements, fields[f]);
    contents.field_names.push_back(names[f]);
  }
  return contents;
}

}  // namespace

SnapshotContents read_snapshot(const std::string& path, const parallel::Layout& layout,
                               const std::vector<std::string>& names,
                               std::vector<std::vector<double>>& fields,
                               const std::vector<std::string>& optional) {
  // Every rank reads the file on its own; a failure on any rank (one whose cells find the
  // geometry different) stops every rank with its message.
  SnapshotContents contents;
  agree(layout.comm(), [&] { contents = read_local(path, layout, names, fields, optional); });
  return contents;
}

}  // namespace bagnold::io
