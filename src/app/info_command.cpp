// bagnold info: what this build is and what it can run.
#include <hdf5.h>
#include <metis.h>
#include <mpi.h>

#include <string>

#include "models/drag/drag_law.hpp"
#include "models/stress/solids_stress.hpp"
#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/deck/load.hpp"
#include "src/util/build_info.hpp"

#ifndef BAGNOLD_BUILD_TYPE
#define BAGNOLD_BUILD_TYPE "unknown"
#endif
#ifndef BAGNOLD_PETSC_VERSION
#define BAGNOLD_PETSC_VERSION "unknown"
#endif

namespace bagnold::app {

int info_command() {
  char mpi_version[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(mpi_version, &length);
  std::string mpi(mpi_version, static_cast<std::size_t>(length));
  if (const auto newline = mpi.find_first_of(",\n"); newline != std::string::npos) mpi.resize(newline);
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  unsigned h5_major = 0, h5_minor = 0, h5_release = 0;
  H5get_libversion(&h5_major, &h5_minor, &h5_release);

  std::string text;
  text += "bagnold " + version() + " (git " + git_hash() + ", " BAGNOLD_BUILD_TYPE " build, " __VERSION__
          ")\n";
  text += "MPI: " + mpi + ", " + std::to_string(ranks) + " rank(s) in this run\n";
  text += "PETSc: " BAGNOLD_PETSC_VERSION "\n";
  text += "HDF5: " + std::to_string(h5_major) + "." + std::to_string(h5_minor) + "." +
          std::to_string(h5_release) + " (parallel)\n";
  text += "METIS: " + std::to_string(METIS_VER_MAJOR) + "." + std::to_string(METIS_VER_MINOR) +
          "." + std::to_string(METIS_VER_SUBMINOR) + "\n";
  text += "solids-stress models:\n";
  for (const auto& e : models::stress_registry().entries())
    text += "  " + e.name + std::string(e.name.size() < 24 ? 24 - e.name.size() : 1, ' ') +
            e.summary + "\n";
  text += "drag laws:\n";
  for (const auto& e : models::drag_registry().entries())
    text += "  " + e.name + std::string(e.name.size() < 24 ? 24 - e.name.size() : 1, ' ') +
            e.summary + "\n";
  say(text);
  return success;
}

int keys_command() {
  say(deck::key_reference_markdown());
  return success;
}

}  // namespace bagnold::app
