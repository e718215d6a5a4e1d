# Finds every dependency and, when one is missing, stops with the Debian package that provides it.
# tools/setup installs what the program needs, tools/setup --tests also what the tests need.

function(bagnold_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR
      "Bagnold needs ${what}, which was not found.\n"
      "On Debian install it with:  sudo apt-get install ${package}\n"
      "(or run tools/setup, which installs what the program needs and builds it; with --tests also\n"
      "what the tests need).")
  endif()
endfunction()

find_package(PkgConfig QUIET)
bagnold_require(PKG_CONFIG_FOUND "pkg-config" "pkg-config")

find_package(MPI COMPONENTS C CXX QUIET)
bagnold_require(MPI_FOUND "MPI (OpenMPI)" "libopenmpi-dev openmpi-bin")

pkg_check_modules(PETSC QUIET IMPORTED_TARGET petsc)
bagnold_require(PETSC_FOUND "PETSc (pkg-config module 'petsc')" "petsc-dev")

# Parallel HDF5: Debian's OpenMPI build of HDF5 ships the pkg-config module hdf5-openmpi.
pkg_check_modules(HDF5 QUIET IMPORTED_TARGET hdf5-openmpi)
bagnold_require(HDF5_FOUND "parallel HDF5 (pkg-config module 'hdf5-openmpi')" "libhdf5-openmpi-dev")

find_path(METIS_INCLUDE_DIR metis.h)
find_library(METIS_LIBRARY metis)
if(METIS_INCLUDE_DIR AND METIS_LIBRARY)
  set(METIS_FOUND TRUE)
endif()
bagnold_require(METIS_FOUND "METIS" "libmetis-dev")
add_library(bagnold_metis INTERFACE)
target_include_directories(bagnold_metis SYSTEM INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(bagnold_metis INTERFACE ${METIS_LIBRARY})

find_package(tomlplusplus QUIET)
bagnold_require(tomlplusplus_FOUND "toml++" "libtomlplusplus-dev")

find_package(CLI11 QUIET)
bagnold_require(CLI11_FOUND "CLI11" "libcli11-dev")

find_package(fmt QUIET)
bagnold_require(fmt_FOUND "fmt" "libfmt-dev")

# GoogleTest only for the tests (BAGNOLD_TESTS, in CMakeLists.txt): the program does not need it.
find_package(GTest QUIET)

find_program(MPIEXEC_EXECUTABLE NAMES mpirun mpiexec)
bagnold_require(MPIEXEC_EXECUTABLE "mpirun" "openmpi-bin")
