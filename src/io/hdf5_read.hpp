#pragma once
// Whole datasets read into memory with the calling rank's own (serial) HDF5 file: the snapshot
// check and the restart reader read every array this way.

#include <cstdint>
#include <string>
#include <vector>

#include "src/io/hdf5_handle.hpp"

namespace bagnold::io {

// The snapshot at `path`, opened read-only; throws Hdf5Error naming it when it cannot be opened.
File open_snapshot_readonly(const std::string& path);

// The whole dataset at `path` in `file` as doubles (as int64 values); throws Hdf5Error naming
// the dataset when it is absent or unreadable.
std::vector<double> read_doubles(hid_t file, const std::string& path);
std::vector<std::int64_t> read_int64s(hid_t file, const std::string& path);

}  // namespace bagnold::io
