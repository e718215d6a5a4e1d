#pragma once
// Room on disk reserved for a file before it is written, so that a disk filling from elsewhere
// stops the run before the file is written rather than halfway through it.
// The reservation lies beyond the file's end (fallocate with FALLOC_FL_KEEP_SIZE), so the file
// grows into it as it is written; `release_unused_reservation` gives back what the file did not
// use. On a file system without fallocate the reservation is skipped.

#include <cstdint>
#include <string>

namespace bagnold::io {

// Reserves `bytes` from the start of the existing file `path`. Throws Hdf5Error naming the file
// when the disk has not that much room.
void reserve_disk_space(const std::string& path, std::uintmax_t bytes);
// Frees the reserved room beyond the end of `path`.
void release_unused_reservation(const std::string& path);

}  // namespace bagnold::io
