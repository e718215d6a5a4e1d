#include "src/run/stop_request.hpp"

#include <csignal>

namespace bagnold::run {

namespace {
volatile std::sig_atomic_t received_signal = 0;

extern "C" void record_signal(int signal) { received_signal = signal; }
}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, record_signal);
  std::signal(SIGTERM, record_signal);
}

bool stop_requested(const parallel::Communicator& comm) {
  return comm.max(static_cast<std::int64_t>(received_signal)) != 0;
}

bool signal_received() { return received_signal != 0; }

int stop_signal() { return static_cast<int>(received_signal); }

}  // namespace bagnold::run
