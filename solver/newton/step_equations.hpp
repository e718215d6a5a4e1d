#pragma once
// The discrete equations of one implicit-Euler time step as one residual F(x) over the step's
// unknowns (step_unknowns.hpp), and their Jacobian, for the Newton solve of the whole step
// (newton_step.hpp). Both come from one evaluation at x: the closures (closures.hpp), then the
// momentum rows of both phases and every component (assemble_momentum_rows, the same rows the
// segregated outer iteration solves), then both continuity equations. The residual rows are
//   momentum   A u − Σ a_nb u_nb − b − βV u_other        (A = a + βV; momentum_rows.hpp)
//   mixture    Σ_faces sign A (ε_g u_g + ε_s u_s)          (pressure_correction.cpp)
//   solids     (ε_s − ε_s^old) V/dt + Σ_faces sign A ε_up u_s   (volume_fraction_correction.cpp)
// with a solids row that carries no solids (below solids_threshold) the identity u_s = 0. Each row
// is divided by its own scale, fixed for the step at its first evaluation: a momentum row by the
// forces that act on its control volume (MomentumRow::force and the drag), a mixture row by its
// throughput, a solids row by the force its fraction error makes (the "force" residual
// normalization's measure, volume_fraction_correction.cpp) over its cell's weight; so ‖F‖ is a
// force balance, which the line search and the convergence test read.
//
// The Jacobian is the rows' own linearization: each momentum row's matrix entries (convection,
// viscous stress with μ_s at the iterate — or its tangent under numerics.viscosity_linearization =
// "newton" — transient, the transpose's cross part, drag on both phases), the pressure and P_s
// gradients (dP_s/dε_s of each cell), the fraction carried by the pressure, weight and transient
// terms, and every continuity term exactly, in velocity and in the upwind or interpolated
// fraction. What it leaves out (β's and μ_s's dependence on the velocities and fractions, the
// TVD correction, the viscosity's dependence on ε_s) makes it the Picard linearization of those
// terms; the Newton solve takes it as its Jacobian or, with -newton_snes_mf_operator, as the
// preconditioner of the exact, matrix-free one.
//
// The stress–velocity linearization (Rudi, Shih & Stadler 2020, G-cubed 21, e2020GC009059, Sec. 3):
// the exact tangent of a viscosity μ_s(γ̇) is δτ = 2 μ_s (δD + (n − 1) N (N:δD)), n = dln τ/dln γ̇
// and N = D/γ̇ the strain direction; a rate-independent (frictional) stress has n = 0, and where
// it stands rigid (γ̇ → 0, N the direction of round-off) this tangent has no stiffness along N:
// Newton's direction there is not one of descent and the step stalls. The stress–velocity
// Newton replaces the second N by a stress direction S of its own, updated after each Newton
// iteration from the linearized relation S γ̇ = D,
//     S ← S + (δD − S (2 N:δD))/γ̇,   then projected onto 2 S:S ≤ 1,
// so that S = N where the material yields and |S| < 1 where it stands, and the tangent
// 2 μ_s (δD + (n − 1) N (S:δD)) keeps its stiffness there. Here the solids' viscous rows take
// it in the diagonal form of ClosureFields::tangent_factor (per face component (a, b):
// 1 + w (n − 1) N_ab S_ab); the step's Jacobian is the exact one (matrix-free) plus Q, the
// difference between these rows with S and with N, so only the rate-independent part changes.
// The residual, and with it the converged step, is the same.

#include <petscmat.h>
#include <petscvec.h>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "solver/newton/step_unknowns.hpp"
#include "solver/simple/closures.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "solver/simple/solids_wall.hpp"
#include "solver/simple/step_record.hpp"

namespace bagnold::solver {

class StepEquations {
 public:
  StepEquations(const Discretization& discretization, const SolverSettings& settings,
                Closures& closures, SolidsWallCoefficients* walls,
                const std::array<std::vector<double>, 3>& gas_source);

  const StepUnknowns& unknowns() const { return m_unknowns; }
  StepUnknowns& unknowns() { return m_unknowns; }
  // A new step from `old` over dt: the next evaluation fixes the rows' scales and refreshes the
  // partial-slip walls' coefficients.
  void start_step(const run::FlowState& old, double dt);
  // Evaluates at `state` (its unknowns; its P_s, γ̇_P, Θ updated by the closures): the scaled
  // residual into f, the sums the step is judged by into `sums` (local, not reduced), and the
  // largest row of each equation into `worst`.
  void residual(run::FlowState& state, Vec f, IterationSums& sums, WorstCells& worst);
  // The assembled linearization at the state of the last residual() into P. With
  // `stress_velocity`, also the stress–velocity correction of the solids' viscous rows into Q
  // (below); otherwise Q is left empty.
  void jacobian(const run::FlowState& state, Mat P, Mat Q, bool stress_velocity);
  // The closures and rows of the last residual(): what conserve_solids needs after convergence.
  const CarriedFractions& carried() const { return m_carried; }
  const ClosureFields& fields() const { return m_fields; }
  // Creates J with its rows' preallocation (collective).
  void create_matrix(Mat* J) const;

 private:
  // βV on the face of the row owned by l along d (the cells' β interpolated to the face, times
  // the control volume), 0 without drag.
  double face_drag(int l, int d, double volume) const;
  void momentum_residual(const run::FlowState& state, PetscScalar* f, IterationSums& sums, WorstCells& worst);
  void continuity_residual(const run::FlowState& state, PetscScalar* f, IterationSums& sums, WorstCells& worst);

  const Discretization& m_discretization;
  const SolverSettings& m_settings;
  Closures& m_closures;
  SolidsWallCoefficients* m_walls;
  const std::array<std::vector<double>, 3>& m_gas_source;
  StepUnknowns m_unknowns;
  // Per direction, the local cell of each velocity-numbering global index on this rank (the rows
  // name their neighbours by it).
  std::array<std::unordered_map<std::int64_t, int>, 3> m_local_of;
  const run::FlowState* m_old = nullptr;
  double m_dt = 0.0;
  bool m_first = true;  // the step's first evaluation: scales fixed, wall coefficients refreshed
  ClosureFields m_fields;
  CarriedFractions m_carried;
  std::array<std::array<std::vector<MomentumRow>, 3>, 2> m_rows;  // [phase][d], per owned row
  // The stress–velocity linearization: S per symmetric component and local cell (empty until the
  // first Jacobian), the strain-rate tensor and γ̇ where S was last updated, the solids rows
  // with N's tangent, and the factors.
  std::array<std::vector<double>, 6> m_stress_direction, m_updated_tensor;
  std::vector<double> m_updated_rate;
  std::array<std::vector<MomentumRow>, 3> m_tangent_rows;
  std::array<std::vector<double>, 6> m_factors;
  void update_stress_direction();
  void assemble_tangent_rows(const run::FlowState& state, const std::array<std::vector<double>, 6>& direction,
                             std::array<std::vector<MomentumRow>, 3>& rows);
  MomentumAssemblyScratch m_scratch;
  // Per equation, the mean over its rows of what it is normalized by, fixed at the step's first
  // evaluation; per solids row, the force its fraction error makes per unit imbalance, fixed then
  // too; per owned row of F, the factor it was multiplied by in the last evaluation.
  std::array<double, equation_count> m_mean{};
  std::vector<double> m_fraction_force;
  std::vector<double> m_scale;
  // A closed domain fixes the pressure's level: the first pressure row of rank 0 holds P there at
  // the step's start (the continuity it replaces follows from the others').
  bool m_pin_pressure = false;
  double m_pinned_pressure = 0.0;
};

}  // namespace bagnold::solver
