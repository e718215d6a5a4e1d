#include "solver/petsc/linear_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "solver/petsc/busy_segments.hpp"
#include "solver/petsc/work_clock.hpp"

namespace bagnold::solver {

PetscSession::PetscSession(int* argc, char*** argv) {
  petsc_check(PetscInitialize(argc, argv, nullptr, nullptr), "PetscInitialize");
}

PetscSession::~PetscSession() { PetscFinalize(); }

void PetscSession::add_options(const std::string& options) {
  if (options.empty()) return;
  petsc_check(PetscOptionsInsertString(nullptr, options.c_str()), "PetscOptionsInsertString");
  PetscBool log_view = PETSC_FALSE;
  petsc_check(PetscOptionsHasName(nullptr, nullptr, "-log_view", &log_view), "PetscOptionsHasName");
  if (log_view) petsc_check(PetscLogDefaultBegin(), "PetscLogDefaultBegin");
}

std::vector<std::string> PetscSession::unused_options() {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  petsc_check(PetscOptionsLeftGet(nullptr, &count, &names, &values), "PetscOptionsLeftGet");
  std::vector<std::string> unused;
  for (PetscInt i = 0; i < count; ++i)
    unused.push_back("-" + std::string(names[i]) + (values[i] ? " " + std::string(values[i]) : ""));
  petsc_check(PetscOptionsLeftRestore(nullptr, &count, &names, &values), "PetscOptionsLeftRestore");
  return unused;
}

namespace {
// "pressure" for the options prefix "pressure_".
std::string segment_name(const std::string& prefix) { return prefix.substr(0, prefix.find_last_not_of('_') + 1); }
}  // namespace

LinearSystem::LinearSystem(MPI_Comm comm, SparsityPattern pattern_in, std::int64_t first_row,
                           const std::string& prefix, const KrylovSettings& settings)
    : m_comm(comm), m_rows(pattern_in.rows()), m_first_row(first_row), m_pattern(std::move(pattern_in)),
      m_values(m_pattern.columns.size(), 0.0), m_rhs_values(static_cast<std::size_t>(m_rows), 0.0),
      m_prefix(prefix), m_settings(settings),
      m_assembly_segment(new_busy_segment(segment_name(prefix) + " assembly")),
      m_solve_segment(new_busy_segment(segment_name(prefix) + " solve")) {
  const SparsityPattern& pattern = m_pattern;
  const auto n = static_cast<PetscInt>(m_rows);
  petsc_check(MatCreate(comm, m_matrix.out()), "MatCreate");
  petsc_check(MatSetSizes(m_matrix.get(), n, n, PETSC_DETERMINE, PETSC_DETERMINE), "MatSetSizes");
  petsc_check(MatSetType(m_matrix.get(), MATAIJ), "MatSetType");
  std::vector<PetscInt> row_index(pattern.columns.size()), column_index(pattern.columns.size());
  for (std::int64_t r = 0; r < m_rows; ++r)
    for (auto k = pattern.offsets[static_cast<std::size_t>(r)]; k < pattern.offsets[static_cast<std::size_t>(r) + 1]; ++k) {
      row_index[static_cast<std::size_t>(k)] = static_cast<PetscInt>(first_row + r);
      column_index[static_cast<std::size_t>(k)] = static_cast<PetscInt>(pattern.columns[static_cast<std::size_t>(k)]);
    }
  petsc_check(MatSetPreallocationCOO(m_matrix.get(), static_cast<PetscCount>(row_index.size()),
                                     row_index.data(), column_index.data()),
              "MatSetPreallocationCOO");
  petsc_check(MatCreateVecs(m_matrix.get(), m_solution.out(), m_rhs.out()), "MatCreateVecs");
  create_ksp();
}

void LinearSystem::set_row(std::int64_t row, const std::int64_t* columns, const double* values,
                           int count, double rhs) {
  const auto r = static_cast<std::size_t>(row - m_first_row);
  const auto begin = static_cast<std::size_t>(m_pattern.offsets[r]);
  const auto width = static_cast<std::size_t>(m_pattern.offsets[r + 1]) - begin;
  const std::int64_t* pattern = m_pattern.columns.data() + begin;
  double* slots = m_values.data() + begin;
  constexpr std::size_t widest = 32;
  if (width > widest) throw std::logic_error("LinearSystem::set_row: a row wider than 32 entries");
  bool set[widest] = {};
  std::size_t next = 0;  // where the previous entry's slot ended
  for (int i = 0; i < count; ++i) {
    // Rows usually list their columns in the pattern's order, or in it but for one entry (the
    // momentum rows' diagonal comes last): search from the slot after the previous entry's,
    // wrapping round once, so such a row costs one or two comparisons per entry.
    std::size_t j = next < width ? next : 0;
    std::size_t tried = 0;
    while (tried < width && pattern[j] != columns[i]) {
      j = j + 1 < width ? j + 1 : 0;
      ++tried;
    }
    if (tried == width) throw std::logic_error("LinearSystem::set_row: an entry outside the sparsity pattern");
    slots[j] = set[j] ? slots[j] + values[i] : values[i];
    set[j] = true;
    next = j + 1;
  }
  m_rhs_values[r] = rhs;
}

void LinearSystem::create_ksp() {
  petsc_check(KSPCreate(m_comm, m_ksp.out()), "KSPCreate");
  petsc_check(KSPSetOptionsPrefix(m_ksp.get(), m_prefix.c_str()), "KSPSetOptionsPrefix");
  petsc_check(KSPSetType(m_ksp.get(), m_settings.ksp_type.c_str()), "KSPSetType");
  PC pc = nullptr;
  petsc_check(KSPGetPC(m_ksp.get(), &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, m_settings.pc_type.c_str()), "PCSetType");
  petsc_check(KSPSetTolerances(m_ksp.get(), m_settings.relative_tolerance,
                               m_settings.absolute_tolerance, PETSC_DEFAULT,
                               m_settings.max_iterations), "KSPSetTolerances");
  petsc_check(KSPSetInitialGuessNonzero(m_ksp.get(), PETSC_TRUE), "KSPSetInitialGuessNonzero");
  // The outer iteration hands over a good guess: reduce its residual by the relative tolerance
  // (PETSc's default measures against ||b||, which stalls the outer loop near that tolerance).
  petsc_check(KSPConvergedDefaultSetUIRNorm(m_ksp.get()), "KSPConvergedDefaultSetUIRNorm");
  // KrylovSettings::default_options go into PETSc's options database for this one
  // KSPSetFromOptions and out again, so that they neither reach another system nor count as
  // options the user gave.
  const auto written = write_default_options();
  petsc_check(KSPSetFromOptions(m_ksp.get()), "KSPSetFromOptions");
  take_back_default_options(written);
}

std::vector<std::string> LinearSystem::write_default_options() const {
  std::vector<std::string> written;
  if (m_settings.default_options.empty()) return written;
  // Only for the preconditioner they were chosen for: the command line may choose another.
  char chosen[64] = "";
  PetscBool given = PETSC_FALSE;
  petsc_check(PetscOptionsGetString(nullptr, m_prefix.c_str(), "-pc_type", chosen, sizeof chosen, &given),
              "PetscOptionsGetString");
  if (given && m_settings.pc_type != chosen) return written;
  for (const auto& [name, value] : m_settings.default_options) {
    petsc_check(PetscOptionsHasName(nullptr, m_prefix.c_str(), ("-" + name).c_str(), &given),
                "PetscOptionsHasName");
    if (given) continue;
    written.push_back("-" + m_prefix + name);
    petsc_check(PetscOptionsSetValue(nullptr, written.back().c_str(), value.c_str()), "PetscOptionsSetValue");
  }
  return written;
}

void LinearSystem::take_back_default_options(const std::vector<std::string>& written) const {
  for (const auto& option : written) {
    PetscBool used = PETSC_FALSE;
    // PETSc keeps the names without their dash.
    petsc_check(PetscOptionsUsed(nullptr, option.c_str() + 1, &used), "PetscOptionsUsed");
    petsc_check(PetscOptionsClearValue(nullptr, option.c_str()), "PetscOptionsClearValue");
    if (!used)
      throw std::logic_error("LinearSystem: the default option " + option + " is not one of " +
                             m_settings.pc_type + "'s");
  }
}

void LinearSystem::keep_preconditioner() {
  petsc_check(KSPSetReusePreconditioner(m_ksp.get(), PETSC_TRUE), "KSPSetReusePreconditioner");
}

void LinearSystem::renew_preconditioner() { create_ksp(); }

SolveReport LinearSystem::solve(std::vector<double>& x) {
  // The assembly's segment (busy_segments.hpp).
  end_busy_segment(m_assembly_segment, m_assembly_units.value_or(static_cast<double>(m_rows)));
  m_assembly_units.reset();
  const SolveReport report = solve_assembled(x);
  end_busy_segment(m_solve_segment, static_cast<double>(krylov_rows()) * (report.iterations + 1));
  return report;
}

SolveReport LinearSystem::solve_assembled(std::vector<double>& x) {
  petsc_check(MatSetValuesCOO(m_matrix.get(), m_values.data(), INSERT_VALUES), "MatSetValuesCOO");
  PetscScalar* rhs = nullptr;
  petsc_check(VecGetArray(m_rhs.get(), &rhs), "VecGetArray");
  std::copy(m_rhs_values.begin(), m_rhs_values.end(), rhs);
  petsc_check(VecRestoreArray(m_rhs.get(), &rhs), "VecRestoreArray");
  if (!m_assembled_once && m_settings.constant_null_space) {
    PetscNullSpace null_space;
    petsc_check(MatNullSpaceCreate(m_comm, PETSC_TRUE, 0, nullptr, null_space.out()),
                "MatNullSpaceCreate");
    petsc_check(MatSetNullSpace(m_matrix.get(), null_space.get()), "MatSetNullSpace");
    // The right-hand side of a closed domain sums to round-off; remove it exactly.
  }
  if (m_settings.constant_null_space) {
    MatNullSpace null_space = nullptr;
    petsc_check(MatGetNullSpace(m_matrix.get(), &null_space), "MatGetNullSpace");
    if (null_space) petsc_check(MatNullSpaceRemove(null_space, m_rhs.get()), "MatNullSpaceRemove");
  }
  m_assembled_once = true;
  if (m_settings.solve_decoupled_rows_directly) return solve_coupled_rows(x);
  PetscScalar* values = nullptr;
  petsc_check(VecGetArray(m_solution.get(), &values), "VecGetArray");
  std::copy(x.begin(), x.begin() + m_rows, values);
  petsc_check(VecRestoreArray(m_solution.get(), &values), "VecRestoreArray");
  const SolveReport report = run_ksp(m_matrix.get(), m_rhs.get(), m_solution.get());
  const PetscScalar* solved = nullptr;
  petsc_check(VecGetArrayRead(m_solution.get(), &solved), "VecGetArrayRead");
  std::copy(solved, solved + m_rows, x.begin());
  petsc_check(VecRestoreArrayRead(m_solution.get(), &solved), "VecRestoreArrayRead");
  return report;
}

std::int64_t LinearSystem::krylov_rows() const {
  return m_settings.solve_decoupled_rows_directly ? static_cast<std::int64_t>(m_coupled.size()) : m_rows;
}

SolveReport LinearSystem::run_ksp(Mat matrix, Vec rhs, Vec solution) {
  petsc_check(KSPSetOperators(m_ksp.get(), matrix, matrix), "KSPSetOperators");
  {
    const ScopedWorkClock clock(ScopedWorkClock::solve);
    petsc_check(KSPSolve(m_ksp.get(), rhs, solution), "KSPSolve");
  }
  SolveReport report;
  PetscInt iterations = 0;
  KSPConvergedReason reason;
  petsc_check(KSPGetIterationNumber(m_ksp.get(), &iterations), "KSPGetIterationNumber");
  petsc_check(KSPGetConvergedReason(m_ksp.get(), &reason), "KSPGetConvergedReason");
  petsc_check(KSPGetResidualNorm(m_ksp.get(), &report.residual_norm), "KSPGetResidualNorm");
  report.iterations = static_cast<int>(iterations);
  report.converged = reason > 0;
  report.reason = KSPConvergedReasons[reason];
  // A matrix with Inf or NaN (a diverging outer iteration) can leave the preconditioner failed
  // for every later solve, even of a healthy matrix: start the next solve from a fresh KSP.
  PetscInt size = 0;
  petsc_check(VecGetLocalSize(solution, &size), "VecGetLocalSize");
  const PetscScalar* solved = nullptr;
  petsc_check(VecGetArrayRead(solution, &solved), "VecGetArrayRead");
  int finite = std::all_of(solved, solved + size, [](double v) { return std::isfinite(v); });
  petsc_check(VecRestoreArrayRead(solution, &solved), "VecRestoreArrayRead");
  MPI_Allreduce(MPI_IN_PLACE, &finite, 1, MPI_INT, MPI_MIN, m_comm);
  if (reason == KSP_DIVERGED_NANORINF || reason == KSP_DIVERGED_PC_FAILED || !finite) create_ksp();
  return report;
}

LinearSystem::DecoupledRows LinearSystem::split_decoupled_rows(std::vector<double>& x) {
  m_next_coupled.clear();
  DecoupledRows known;
  for (std::int64_t r = 0; r < m_rows; ++r) {
    const auto ur = static_cast<std::size_t>(r);
    const std::int64_t row = m_first_row + r;
    double diagonal = 0.0;
    bool coupled = false;
    for (auto k = m_pattern.offsets[ur]; k < m_pattern.offsets[ur + 1]; ++k) {
      const auto uk = static_cast<std::size_t>(k);
      if (m_pattern.columns[uk] == row) diagonal += m_values[uk];
      else if (m_values[uk] != 0.0) coupled = true;
    }
    if (coupled) {
      m_next_coupled.push_back(static_cast<PetscInt>(row));
      continue;
    }
    x[ur] = m_rhs_values[ur] / diagonal;
    known.nonzero = known.nonzero || x[ur] != 0.0;
    known.finite = known.finite && std::isfinite(x[ur]);  // false: a zero diagonal, a singular system
  }
  return known;
}

SolveReport LinearSystem::solve_coupled_rows(std::vector<double>& x) {
  const DecoupledRows known = split_decoupled_rows(x);
  // One reduction: did any rank's coupled rows change, is any known value nonzero or not
  // finite, how many coupled rows are there.
  long long counts[4] = {m_coupled_built && m_next_coupled == m_coupled ? 0 : 1, known.nonzero ? 1 : 0,
                         known.finite ? 0 : 1, static_cast<long long>(m_next_coupled.size())};
  MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPI_LONG_LONG, MPI_SUM, m_comm);
  const bool changed = counts[0] > 0, any_known = counts[1] > 0, any_coupled = counts[3] > 0;
  if (changed) {
    m_coupled.swap(m_next_coupled);
    m_coupled_built = true;
    m_coupled_matrix.reset();
    m_coupled_rows.reset();
    if (any_coupled) {
      const auto n = static_cast<PetscInt>(m_coupled.size());
      petsc_check(ISCreateGeneral(m_comm, n, m_coupled.data(), PETSC_COPY_VALUES, m_coupled_rows.out()),
                  "ISCreateGeneral");
      petsc_check(MatCreateSubMatrix(m_matrix.get(), m_coupled_rows.get(), m_coupled_rows.get(),
                                     MAT_INITIAL_MATRIX, m_coupled_matrix.out()),
                  "MatCreateSubMatrix");
      petsc_check(MatCreateVecs(m_coupled_matrix.get(), m_coupled_solution.out(), m_coupled_rhs.out()),
                  "MatCreateVecs");
      create_ksp();  // a KSP keeps the sizes of the operators it was first set up with
    }
  } else if (any_coupled) {
    Mat reused = m_coupled_matrix.get();
    petsc_check(MatCreateSubMatrix(m_matrix.get(), m_coupled_rows.get(), m_coupled_rows.get(),
                                   MAT_REUSE_MATRIX, &reused),
                "MatCreateSubMatrix");
  }
  SolveReport report;
  report.converged = counts[2] == 0;
  report.reason = report.converged ? "no coupled rows" : "a decoupled row with a zero diagonal";
  if (!any_coupled || !report.converged) return report;

  // The coupled rows' right-hand side b − A x_known, with x_known zero on the coupled rows.
  const PetscScalar* known_product = nullptr;
  if (any_known) {
    if (!m_known.get())
      petsc_check(MatCreateVecs(m_matrix.get(), m_known.out(), m_known_product.out()), "MatCreateVecs");
    PetscScalar* known_values = nullptr;
    petsc_check(VecGetArray(m_known.get(), &known_values), "VecGetArray");
    std::copy(x.begin(), x.begin() + m_rows, known_values);
    for (const PetscInt row : m_coupled) known_values[row - m_first_row] = 0.0;
    petsc_check(VecRestoreArray(m_known.get(), &known_values), "VecRestoreArray");
    petsc_check(MatMult(m_matrix.get(), m_known.get(), m_known_product.get()), "MatMult");
    petsc_check(VecGetArrayRead(m_known_product.get(), &known_product), "VecGetArrayRead");
  }
  PetscScalar *rhs = nullptr, *guess = nullptr;
  petsc_check(VecGetArray(m_coupled_rhs.get(), &rhs), "VecGetArray");
  petsc_check(VecGetArray(m_coupled_solution.get(), &guess), "VecGetArray");
  for (std::size_t i = 0; i < m_coupled.size(); ++i) {
    const auto r = static_cast<std::size_t>(m_coupled[i] - m_first_row);
    rhs[i] = m_rhs_values[r] - (known_product ? known_product[r] : 0.0);
    guess[i] = x[r];
  }
  petsc_check(VecRestoreArray(m_coupled_solution.get(), &guess), "VecRestoreArray");
  petsc_check(VecRestoreArray(m_coupled_rhs.get(), &rhs), "VecRestoreArray");
  if (known_product)
    petsc_check(VecRestoreArrayRead(m_known_product.get(), &known_product), "VecRestoreArrayRead");

  report = run_ksp(m_coupled_matrix.get(), m_coupled_rhs.get(), m_coupled_solution.get());
  const PetscScalar* solved = nullptr;
  petsc_check(VecGetArrayRead(m_coupled_solution.get(), &solved), "VecGetArrayRead");
  for (std::size_t i = 0; i < m_coupled.size(); ++i)
    x[static_cast<std::size_t>(m_coupled[i] - m_first_row)] = solved[i];
  petsc_check(VecRestoreArrayRead(m_coupled_solution.get(), &solved), "VecRestoreArrayRead");
  return report;
}

}  // namespace bagnold::solver
