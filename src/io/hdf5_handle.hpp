#pragma once
// Move-only owners of HDF5 identifiers: the destructor closes, get() lends the raw id, release()
// hands it over.
// Every HDF5 call that can fail goes through check(), which throws with the operation's name.

#include <hdf5.h>

#include "src/io/io_error.hpp"
#include <string>
#include <utility>

namespace bagnold::io {

inline hid_t check(hid_t id, const char* what) {
  if (id < 0) throw Hdf5Error(std::string("HDF5: ") + what + " failed");
  return id;
}
inline void check_status(herr_t status, const char* what) {
  if (status < 0) throw Hdf5Error(std::string("HDF5: ") + what + " failed");
}

template <herr_t (*Close)(hid_t)>
class Hdf5Handle {
 public:
  Hdf5Handle() = default;
  explicit Hdf5Handle(hid_t id) : m_id(id) {}
  Hdf5Handle(Hdf5Handle&& other) noexcept : m_id(std::exchange(other.m_id, -1)) {}
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
      reset();
      m_id = std::exchange(other.m_id, -1);
    }
    return *this;
  }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle() { reset(); }

  hid_t get() const { return m_id; }
  // Gives up ownership without closing: the caller closes the id, or leaves it open on purpose.
  hid_t release() { return std::exchange(m_id, -1); }
  void reset() {
    if (m_id >= 0) Close(m_id);
    m_id = -1;
  }

 private:
  hid_t m_id = -1;
};

using File = Hdf5Handle<H5Fclose>;
using Group = Hdf5Handle<H5Gclose>;
using Dataset = Hdf5Handle<H5Dclose>;
using Dataspace = Hdf5Handle<H5Sclose>;
using PropertyList = Hdf5Handle<H5Pclose>;
using Attribute = Hdf5Handle<H5Aclose>;
using Datatype = Hdf5Handle<H5Tclose>;

}  // namespace bagnold::io
