#pragma once
// Errors of reading or writing output files (snapshots, XDMF, monitor): the message names the
// file and what failed.

#include <stdexcept>

namespace bagnold::io {

class Hdf5Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bagnold::io
