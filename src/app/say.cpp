// say(): every message of the program goes through the one Console (run/console.hpp), on rank 0
// only, so a log line never lands on the progress line.
#include <mpi.h>

#include "src/app/commands.hpp"
#include "src/run/console.hpp"

namespace bagnold::app {

void say(const std::string& text, bool error) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return;
  run::console().line(text, error);
}

}  // namespace bagnold::app
