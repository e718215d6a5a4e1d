#pragma once
// A file-system or HDF5 action that can fail on some ranks only (rank 0 alone writes the
// monitor, the XDMF index and the snapshots; a restart's reading can fail on one rank's cells)
// must not leave the others waiting in a collective it has left: every rank calls `agree`,
// which runs `action` and then tells all ranks whether it threw on any of them. If it did, every
// rank throws io::Hdf5Error with the message of the lowest rank that failed.

#include <functional>

#include "src/parallel/communicator.hpp"

namespace bagnold::io {

// Collective.
void agree(const parallel::Communicator& comm, const std::function<void()>& action);

}  // namespace bagnold::io
