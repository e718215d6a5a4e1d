#pragma once
// SIGINT and SIGTERM during a run: the handler only records the request; the time loop asks
// after every step (collectively, so all ranks stop at the same step), writes a final complete
// snapshot and the run exits with code 3.

#include "src/parallel/communicator.hpp"

namespace bagnold::run {

void install_stop_handlers();
// Collective: whether any rank has received SIGINT or SIGTERM.
bool stop_requested(const parallel::Communicator& comm);
// The signal received (0 if none), for the message.
int stop_signal();

}  // namespace bagnold::run
