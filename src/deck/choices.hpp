#pragma once
// The named choices of the deck's option families that are not models (models have their
// registries, models/registry.hpp): each family's names and values are listed once, here; the
// deck schema takes its allowed names from these tables and the solver its values, so adding a
// choice is one edit of its table (and the code that implements it).

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace bagnold::deck {

template <class Value>
struct Choice {
  std::string_view name;
  Value value;
};

// The names of a table, in its order (for the deck schema's one_of).
template <class Value, std::size_t N>
std::vector<std::string> choice_names(const std::array<Choice<Value>, N>& table) {
  std::vector<std::string> names;
  for (const auto& c : table) names.emplace_back(c.name);
  return names;
}

// The value named `name`; std::invalid_argument naming the family and the choices otherwise.
template <class Value, std::size_t N>
Value choice_value(const std::array<Choice<Value>, N>& table, const std::string& name,
                   const char* family) {
  for (const auto& c : table)
    if (c.name == name) return c.value;
  std::string known;
  for (const auto& c : table) known += (known.empty() ? "" : ", ") + std::string(c.name);
  throw std::invalid_argument("unknown " + std::string(family) + " '" + name + "' (known: " + known + ")");
}

// numerics.convection: first-order upwind or a TVD limiter (solver/convection_limiter.hpp).
enum class Limiter { upwind, superbee, muscl, van_leer, minmod };
inline constexpr std::array<Choice<Limiter>, 5> limiter_choices{{{"upwind", Limiter::upwind},
                                                                 {"superbee", Limiter::superbee},
                                                                 {"muscl", Limiter::muscl},
                                                                 {"van_leer", Limiter::van_leer},
                                                                 {"minmod", Limiter::minmod}}};

// numerics.residual_normalization (solver/simple/momentum_residual.hpp).
enum class ResidualNormalization { force, deviation, velocity_scale, mfix };
inline constexpr std::array<Choice<ResidualNormalization>, 4> residual_normalization_choices{
    {{"force", ResidualNormalization::force},
     {"velocity-scale", ResidualNormalization::velocity_scale},
     {"deviation", ResidualNormalization::deviation},
     {"mfix", ResidualNormalization::mfix}}};

// numerics.viscosity_average: how a face or edge viscosity is made from the cells around it
// (solver/simple/momentum_assembly.cpp).
enum class ViscosityAverage { arithmetic, harmonic, yield_bounded };
inline constexpr std::array<Choice<ViscosityAverage>, 3> viscosity_average_choices{
    {{"arithmetic", ViscosityAverage::arithmetic},
     {"harmonic", ViscosityAverage::harmonic},
     {"yield-bounded", ViscosityAverage::yield_bounded}}};

// numerics.viscosity_linearization: how the solids momentum rows take μ_s(γ̇)
// (solver/simple/momentum_assembly.cpp).
enum class ViscosityLinearization { picard, newton };
inline constexpr std::array<Choice<ViscosityLinearization>, 2> viscosity_linearization_choices{
    {{"picard", ViscosityLinearization::picard}, {"newton", ViscosityLinearization::newton}}};

// numerics.solids_momentum: the solids momentum components solved one at a time or together
// (solver/simple/coupled_solids_momentum.hpp).
enum class SolidsMomentum { segregated, coupled };
inline constexpr std::array<Choice<SolidsMomentum>, 2> solids_momentum_choices{
    {{"segregated", SolidsMomentum::segregated}, {"coupled", SolidsMomentum::coupled}}};

// numerics.step_solver: how a time step's equations are solved: the segregated outer iteration
// (solver/simple/advance.cpp) or Newton on the whole step (solver/newton/newton_step.hpp).
enum class StepSolver { outer_iteration, newton };
inline constexpr std::array<Choice<StepSolver>, 2> step_solver_choices{
    {{"outer-iteration", StepSolver::outer_iteration}, {"newton", StepSolver::newton}}};

// numerics.newton_linearization: the Jacobian of the Newton step (solver/newton/step_equations.hpp).
enum class NewtonLinearization { stress_velocity, exact };
inline constexpr std::array<Choice<NewtonLinearization>, 2> newton_linearization_choices{
    {{"stress-velocity", NewtonLinearization::stress_velocity}, {"exact", NewtonLinearization::exact}}};

// numerics.algorithm: the pressure-velocity coupling (solver/simple/momentum_predictor.cpp).
enum class Coupling { simplec, simple };
inline constexpr std::array<Choice<Coupling>, 2> coupling_choices{
    {{"simplec", Coupling::simplec}, {"simple", Coupling::simple}}};

}  // namespace bagnold::deck
