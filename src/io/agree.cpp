#include "src/io/agree.hpp"

#include <exception>
#include <string>

#include "src/io/io_error.hpp"

namespace bagnold::io {

void agree(const parallel::Communicator& comm, const std::function<void()>& action) {
  std::string problem;
  try {
    action();
  } catch (const std::exception& e) {  // Hdf5Error, or the file system's
    problem = e.what();
    if (problem.empty()) problem = "a file-system operation failed";
  }
  // The lowest failing rank (size() when none) sends its message to all.
  const int mine = problem.empty() ? comm.size() : comm.rank();
  int failed = mine;
  MPI_Allreduce(&mine, &failed, 1, MPI_INT, MPI_MIN, comm.get());
  if (failed == comm.size()) return;
  comm.broadcast(problem, failed);
  throw Hdf5Error(problem);
}

}  // namespace bagnold::io
