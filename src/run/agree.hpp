#pragma once
// A file-system action that only some ranks perform (rank 0 writes the monitor and the XDMF
// index) must not leave the others waiting in a collective it has left: every rank calls
// `agree`, which runs `action` and then tells all ranks whether it threw on any of them. If it
// did, every rank throws io::Hdf5Error with the message of the lowest rank that failed.

#include <functional>

#include "src/parallel/communicator.hpp"

namespace bagnold::run {

// Collective.
void agree(const parallel::Communicator& comm, const std::function<void()>& action);

}  // namespace bagnold::run
