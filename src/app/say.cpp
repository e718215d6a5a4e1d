#include <mpi.h>

#include <cstdio>

#include "src/app/commands.hpp"

namespace bagnold::app {

void say(const std::string& text, bool error) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return;
  std::FILE* stream = error ? stderr : stdout;
  std::fputs(text.c_str(), stream);
  if (!text.empty() && text.back() != '\n') std::fputc('\n', stream);
  std::fflush(stream);
}

}  // namespace bagnold::app
