#pragma once
// PETSc lives from before the first test to after the last, and is finalized before
// MPI_Finalize (tests/support/mpi_main.cpp calls it after RUN_ALL_TESTS returns). Include in
// exactly one source file of a test executable whose steps own a LinearSystem.

#include <gtest/gtest.h>

#include <memory>

#include "solver/petsc/handle.hpp"

namespace bagnold::tests {
namespace {

class PetscEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { m_session = std::make_unique<solver::PetscSession>(nullptr, nullptr); }
  void TearDown() override { m_session.reset(); }

 private:
  std::unique_ptr<solver::PetscSession> m_session;
};
[[maybe_unused]] ::testing::Environment* const petsc_environment =
    ::testing::AddGlobalTestEnvironment(new PetscEnvironment);

}  // namespace
}  // namespace bagnold::tests
