#include "src/io/hdf5_read.hpp"

namespace bagnold::io {

namespace {

template <typename T>
std::vector<T> read_whole(hid_t file, const std::string& path, hid_t type) {
  Dataset ds(check(H5Dopen2(file, path.c_str(), H5P_DEFAULT), path.c_str()));
  Dataspace space(check(H5Dget_space(ds.get()), "H5Dget_space"));
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!values.empty())
    check_status(H5Dread(ds.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                 ("H5Dread " + path).c_str());
  return values;
}

}  // namespace

File open_snapshot_readonly(const std::string& path) {
  // Errors are reported by exceptions with a message; HDF5's own stack dump would only add noise.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (file.get() < 0) throw Hdf5Error("cannot open snapshot " + path);
  return file;
}

std::vector<double> read_doubles(hid_t file, const std::string& path) {
  return read_whole<double>(file, path, H5T_NATIVE_DOUBLE);
}

std::vector<std::int64_t> read_int64s(hid_t file, const std::string& path) {
  return read_whole<std::int64_t>(file, path, H5T_NATIVE_INT64);
}

}  // namespace bagnold::io
