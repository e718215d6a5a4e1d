#pragma once
// Move-only owners of PETSc objects; get() lends the raw handle. Every PETSc call goes through
// petsc_check(), which turns an error code into an exception naming the call.

#include <petscksp.h>

#include <stdexcept>
#include <string>
#include <vector>
#include <utility>

namespace bagnold::solver {

class PetscFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline void petsc_check(PetscErrorCode code, const char* what) {
  if (code != 0) throw PetscFailure(std::string("PETSc: ") + what + " failed (error " +
                                    std::to_string(static_cast<int>(code)) + ")");
}

template <class T, PetscErrorCode (*Destroy)(T*)>
class PetscHandle {
 public:
  PetscHandle() = default;
  explicit PetscHandle(T object) : m_object(object) {}
  PetscHandle(PetscHandle&& other) noexcept : m_object(std::exchange(other.m_object, nullptr)) {}
  PetscHandle& operator=(PetscHandle&& other) noexcept {
    if (this != &other) {
      reset();
      m_object = std::exchange(other.m_object, nullptr);
    }
    return *this;
  }
  PetscHandle(const PetscHandle&) = delete;
  PetscHandle& operator=(const PetscHandle&) = delete;
  ~PetscHandle() { reset(); }

  T get() const { return m_object; }
  T* out() { reset(); return &m_object; }  // for PETSc's create functions
  void reset() {
    if (m_object) Destroy(&m_object);
    m_object = nullptr;
  }

 private:
  T m_object = nullptr;
};

using PetscVec = PetscHandle<Vec, VecDestroy>;
using PetscMat = PetscHandle<Mat, MatDestroy>;
using PetscKsp = PetscHandle<KSP, KSPDestroy>;
using PetscIs = PetscHandle<IS, ISDestroy>;
using PetscNullSpace = PetscHandle<MatNullSpace, MatNullSpaceDestroy>;

// PetscInitialize / PetscFinalize for the lifetime of a program (after MPI is initialized).
class PetscSession {
 public:
  PetscSession(int* argc, char*** argv);
  // PETSc options from the command line ("-log_view -pressure_ksp_monitor"); starts logging
  // when -log_view is among them (PETSc only does so for options given at initialization).
  static void add_options(const std::string& options);
  // The options (with their values) that nothing has read so far: after a run, the misspelled or
  // misplaced ones (PETSc's PetscOptionsLeftGet).
  static std::vector<std::string> unused_options();
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
};

}  // namespace bagnold::solver
