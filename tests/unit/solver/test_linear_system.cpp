// LinearSystem (solver/petsc/linear_system.hpp): rows whose off-diagonal values are all zero are
// solved directly and left out of the Krylov solve (KrylovSettings::solve_decoupled_rows_directly),
// with the same answer as the whole system's; on 1 and 2 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "solver/petsc/linear_system.hpp"
#include "solver/simple/pressure_correction.hpp"
#include "tests/support/petsc_environment.hpp"

namespace bagnold::tests {
namespace {

using solver::KrylovSettings;
using solver::LinearSystem;
using solver::SolveReport;
using solver::SparsityPattern;

constexpr int rows_per_rank = 12;

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// A chain of rows i − 1, i, i + 1 over all ranks, this rank's block of rows_per_rank.
struct Chain {
  std::int64_t first = static_cast<std::int64_t>(rank()) * rows_per_rank;
  std::int64_t total = static_cast<std::int64_t>(ranks()) * rows_per_rank;

  SparsityPattern pattern() const {
    SparsityPattern p;
    for (std::int64_t i = first; i < first + rows_per_rank; ++i) {
      std::int64_t columns[3];
      int count = 0;
      for (std::int64_t j = i - 1; j <= i + 1; ++j)
        if (j >= 0 && j < total) columns[count++] = j;
      p.add_row(columns, count);
    }
    return p;
  }

  // Row i: decoupled(i) gives the diagonal `decoupled_diagonal`, zero off-diagonals and
  // b = rhs(i); otherwise the coupled row 3 x_i − x_{i−1} − x_{i+1} = 1 + i/10.
  void fill(LinearSystem& system, const std::function<bool(std::int64_t)>& decoupled,
            const std::function<double(std::int64_t)>& rhs, double decoupled_diagonal = 2.0) const {
    for (std::int64_t i = first; i < first + rows_per_rank; ++i) {
      std::int64_t columns[3];
      double values[3];
      int count = 0;
      for (std::int64_t j = i - 1; j <= i + 1; ++j) {
        if (j < 0 || j >= total) continue;
        columns[count] = j;
        values[count++] = j == i ? (decoupled(i) ? decoupled_diagonal : 3.0) : (decoupled(i) ? 0.0 : -1.0);
      }
      system.set_row(i, columns, values, count, decoupled(i) ? rhs(i) : 1.0 + 0.1 * static_cast<double>(i));
    }
  }
};

KrylovSettings tight(bool direct) {
  KrylovSettings s;
  s.relative_tolerance = 1e-13;
  s.absolute_tolerance = 1e-30;
  s.solve_decoupled_rows_directly = direct;
  return s;
}

// Solves the chain with and without the direct solve of decoupled rows; returns the largest
// difference and checks the decoupled rows' values are exactly b / a.
double largest_difference(const Chain& chain, LinearSystem& direct, LinearSystem& whole,
                          const std::function<bool(std::int64_t)>& decoupled,
                          const std::function<double(std::int64_t)>& rhs, SolveReport& report) {
  chain.fill(direct, decoupled, rhs);
  chain.fill(whole, decoupled, rhs);
  std::vector<double> x(rows_per_rank, 0.5), y(rows_per_rank, 0.5);
  report = direct.solve(x);
  EXPECT_TRUE(whole.solve(y).converged);
  double largest = 0.0;
  for (int r = 0; r < rows_per_rank; ++r) {
    const std::int64_t i = chain.first + r;
    if (decoupled(i)) {
      EXPECT_EQ(x[static_cast<std::size_t>(r)], rhs(i) / 2.0) << "row " << i;
    }
    largest = std::max(largest, std::abs(x[static_cast<std::size_t>(r)] - y[static_cast<std::size_t>(r)]));
  }
  return largest;
}

TEST(LinearSystem, DecoupledRowsSolvedDirectlyGiveTheWholeSystemsAnswer) {
  const Chain chain;
  LinearSystem direct(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_direct_", tight(true));
  LinearSystem whole(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_whole_", tight(false));
  // Every third row decoupled with a nonzero value its coupled neighbours see.
  auto every_third = [](std::int64_t i) { return i % 3 == 1; };
  auto value = [](std::int64_t i) { return 4.0 + static_cast<double>(i); };
  SolveReport report;
  EXPECT_LT(largest_difference(chain, direct, whole, every_third, value, report), 1e-11);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.iterations, 0);
  EXPECT_EQ(direct.krylov_rows(), rows_per_rank - rows_per_rank / 3);
  EXPECT_EQ(whole.krylov_rows(), rows_per_rank);

  // The decoupled rows change between solves (the upper half of the chain, with b = 0: a phase
  // absent there): the coupled system is rebuilt, and agrees again.
  auto upper_half = [&chain](std::int64_t i) { return i >= chain.total / 2; };
  auto zero = [](std::int64_t) { return 0.0; };
  EXPECT_LT(largest_difference(chain, direct, whole, upper_half, zero, report), 1e-11);
  EXPECT_TRUE(report.converged);
  std::int64_t coupled_here = 0;
  for (std::int64_t i = chain.first; i < chain.first + rows_per_rank; ++i) coupled_here += upper_half(i) ? 0 : 1;
  EXPECT_EQ(direct.krylov_rows(), coupled_here);

  // The same rows again: the coupled system is reused, with new values.
  auto shifted = [](std::int64_t i) { return 1.0 - static_cast<double>(i); };
  EXPECT_LT(largest_difference(chain, direct, whole, upper_half, shifted, report), 1e-11);
}

TEST(LinearSystem, AllRowsDecoupledNeedNoKrylovIteration) {
  const Chain chain;
  LinearSystem direct(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_all_", tight(true));
  LinearSystem whole(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_all_whole_", tight(false));
  SolveReport report;
  auto all = [](std::int64_t) { return true; };
  auto value = [](std::int64_t i) { return 0.25 * static_cast<double>(i); };
  EXPECT_LT(largest_difference(chain, direct, whole, all, value, report), 1e-11);
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.iterations, 0);
  EXPECT_EQ(direct.krylov_rows(), 0);
}

TEST(LinearSystem, DecoupledRowWithZeroDiagonalFailsTheSolve) {
  const Chain chain;
  LinearSystem direct(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_singular_", tight(true));
  // The last row of the chain (on the last rank) is empty: a singular system.
  chain.fill(direct, [&chain](std::int64_t i) { return i == chain.total - 1; },
             [](std::int64_t) { return 1.0; }, 0.0);
  std::vector<double> x(rows_per_rank, 0.0);
  EXPECT_FALSE(direct.solve(x).converged);  // on every rank
}

// KrylovSettings::default_options reach the KSP (here: at most 2 iterations, where the chain
// needs more to 1e-13) unless the options database holds the same option, and never stay in it.
TEST(LinearSystem, DefaultOptionsHoldUnlessGivenAndLeaveNoTrace) {
  const Chain chain;
  KrylovSettings settings = tight(false);
  settings.pc_type = "none";  // block Jacobi's ILU(0) of a chain is exact
  settings.default_options = {{"ksp_max_it", "2"}};
  const auto iterations = [&](const char* prefix) {
    LinearSystem system(MPI_COMM_WORLD, chain.pattern(), chain.first, prefix, settings);
    chain.fill(system, [](std::int64_t) { return false; }, [](std::int64_t) { return 0.0; });
    std::vector<double> x(rows_per_rank, 0.0);
    return system.solve(x).iterations;
  };
  EXPECT_EQ(iterations("test_defaults_"), 2);
  PetscBool left = PETSC_TRUE;
  PetscOptionsHasName(nullptr, nullptr, "-test_defaults_ksp_max_it", &left);
  EXPECT_FALSE(left);
  PetscOptionsSetValue(nullptr, "-test_given_ksp_max_it", "500");
  const int given = iterations("test_given_");
  PetscOptionsClearValue(nullptr, "-test_given_ksp_max_it");
  EXPECT_GT(given, 2);
  // Another preconditioner chosen on the command line: the defaults are not for it.
  PetscOptionsSetValue(nullptr, "-test_other_pc_type", "jacobi");
  const int other = iterations("test_other_");
  PetscOptionsClearValue(nullptr, "-test_other_pc_type");
  EXPECT_GT(other, 2);
}

// The pressure's BoomerAMG options are all read by hypre (a misspelled one throws), and a CG
// with them solves the chain.
TEST(LinearSystem, PressureBoomerAmgOptionsAreHypres) {
  const Chain chain;
  KrylovSettings settings = tight(false);
  settings.ksp_type = "cg";
  settings.pc_type = "hypre";
  settings.default_options = solver::boomeramg_options();
  LinearSystem system(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_amg_", settings);
  chain.fill(system, [](std::int64_t) { return false; }, [](std::int64_t) { return 0.0; });
  std::vector<double> x(rows_per_rank, 0.0);
  EXPECT_TRUE(system.solve(x).converged);
  settings.default_options.emplace_back("pc_hypre_boomeramg_coarsen_typo", "HMIS");
  EXPECT_THROW(LinearSystem(MPI_COMM_WORLD, chain.pattern(), chain.first, "test_typo_", settings),
               std::logic_error);
}

}  // namespace
}  // namespace bagnold::tests
