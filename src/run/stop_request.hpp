#pragma once
// SIGINT and SIGTERM during a run: the handler only records the request. The solver asks after
// every outer iteration (signal_received, carried in the iteration's Allreduce so that all ranks
// abandon the step in progress together); the time loop then writes the last completed step's
// state as the final snapshot and the run exits with code 3.

#include "src/parallel/communicator.hpp"

namespace bagnold::run {

void install_stop_handlers();
// Whether this rank has received SIGINT or SIGTERM (not collective).
bool signal_received();
// Collective: whether any rank has received SIGINT or SIGTERM.
bool stop_requested(const parallel::Communicator& comm);
// The signal received (0 if none), for the message.
int stop_signal();

}  // namespace bagnold::run
