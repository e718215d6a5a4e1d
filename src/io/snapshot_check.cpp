#include "src/io/snapshot_check.hpp"

#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "src/io/hdf5_handle.hpp"
#include "src/io/hdf5_read.hpp"

namespace bagnold::io {

std::uint64_t element_hash(std::uint64_t index, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  std::uint64_t z = bits ^ (index * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::uint64_t checksum(std::span<const double> values) {
  std::uint64_t sum = 0;
  for (std::size_t e = 0; e < values.size(); ++e) sum += element_hash(e, values[e]);
  return sum;
}

namespace {

// The whole dataset at `path` in the file, or nothing if it is absent.
std::optional<std::vector<double>> read_all(hid_t file, const std::string& path) {
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  return read_doubles(file, path);
}

// The dataset's stored checksum, or nothing (a snapshot written before checksums existed).
std::optional<std::uint64_t> stored_checksum(hid_t file, const std::string& path) {
  Dataset ds(check(H5Dopen2(file, path.c_str(), H5P_DEFAULT), path.c_str()));
  if (H5Aexists(ds.get(), "checksum") <= 0) return std::nullopt;
  Attribute a(check(H5Aopen(ds.get(), "checksum", H5P_DEFAULT), "checksum"));
  std::uint64_t value = 0;
  check_status(H5Aread(a.get(), H5T_NATIVE_UINT64, &value), "H5Aread checksum");
  return value;
}

std::optional<std::string> check_dataset(hid_t file, const std::string& path,
                                         std::vector<double>& values) {
  const auto stored = read_all(file, path);
  if (!stored) return std::nullopt;
  values = *stored;
  if (const auto expected = stored_checksum(file, path)) {
    if (checksum(values) != *expected) return "dataset " + path + " does not match its checksum (corrupted)";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> verify_snapshot(const std::string& path,
                                           const std::vector<FieldRange>& ranges) {
  try {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (file.get() < 0) return std::string("cannot open it as HDF5 (truncated or not a snapshot)");
    std::vector<std::uint8_t> flags;
    hsize_t dims[3] = {0, 0, 0};  // nz, ny, nx
    {
      Dataset ds(check(H5Dopen2(file.get(), "grid/cell_flags", H5P_DEFAULT), "grid/cell_flags"));
      Dataspace space(check(H5Dget_space(ds.get()), "H5Dget_space"));
      if (H5Sget_simple_extent_ndims(space.get()) != 3) return std::string("grid/cell_flags is not 3-D");
      H5Sget_simple_extent_dims(space.get(), dims, nullptr);
      flags.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
      check_status(H5Dread(ds.get(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, flags.data()),
                   "H5Dread grid/cell_flags");
    }
    std::vector<double> values;
    for (const auto& range : ranges) {
      if (auto problem = check_dataset(file.get(), "boundary/" + range.name, values)) return problem;
      const std::string field = "fields/" + range.name;
      if (auto problem = check_dataset(file.get(), field, values)) return problem;
      if (H5Lexists(file.get(), field.c_str(), H5P_DEFAULT) <= 0) continue;
      if (values.size() != flags.size()) return "dataset " + field + " does not have the grid's shape";
      for (std::size_t e = 0; e < values.size(); ++e) {
        if (flags[e] != 1) continue;  // grid::CellKind::fluid
        const double v = values[e];
        const bool ok = std::isnan(v) ? range.nan_allowed
                                      : std::isfinite(v) && v >= range.low && v <= range.high;
        if (!ok)
          return fmt::format("dataset {} holds {} in fluid cell (i, j, k) = ({}, {}, {}), outside "
                             "[{}, {}]{}",
                             field, v, e % dims[2], (e / dims[2]) % dims[1], e / (dims[2] * dims[1]),
                             range.low, range.high, range.nan_allowed ? " (or NaN)" : "");
      }
    }
  } catch (const Hdf5Error& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

}  // namespace bagnold::io
