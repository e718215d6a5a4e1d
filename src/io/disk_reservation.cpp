#include "src/io/disk_reservation.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "src/io/io_error.hpp"

namespace bagnold::io {

void reserve_disk_space(const std::string& path, std::uintmax_t bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY);
  if (fd < 0) throw Hdf5Error("cannot open " + path + " (" + std::strerror(errno) + ")");
  const int result = ::fallocate(fd, FALLOC_FL_KEEP_SIZE, 0, static_cast<off_t>(bytes));
  const int error = result == 0 ? 0 : errno;
  ::close(fd);
  if (error == 0 || error == EOPNOTSUPP || error == ENOSYS) return;
  throw Hdf5Error("cannot reserve " + std::to_string(bytes / 1024) + " kB for " + path + " (" +
                  std::strerror(error) + ")");
}

void release_unused_reservation(const std::string& path) {
  // Truncating to the file's own size frees the blocks reserved beyond its end.
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) (void)::truncate(path.c_str(), status.st_size);
}

}  // namespace bagnold::io
