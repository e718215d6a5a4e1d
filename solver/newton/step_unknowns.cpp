// The step's unknowns as one vector (step_unknowns.hpp).
#include "solver/newton/step_unknowns.hpp"

#include <span>

#include "solver/petsc/handle.hpp"
#include "solver/simple/volume_fraction_correction.hpp"

namespace bagnold::solver {

const std::vector<int>& StepUnknowns::owned_locals(Block block) const {
  if (!present(block)) return m_none;
  if (block < pressure) return m_discretization.velocity_numbering(block % 3).owned_locals;
  return m_discretization.cell_numbering().owned_locals;
}

StepUnknowns::StepUnknowns(const Discretization& discretization, std::array<bool, 2> moves)
    : m_discretization(discretization) {
  const auto& layout = discretization.layout();
  for (int b = 0; b < block_count; ++b) {
    const bool gas_block = b < solids_x || b == pressure;
    m_present[static_cast<std::size_t>(b)] = gas_block ? moves[gas] : moves[solids];
  }
  for (int b = 0; b < block_count; ++b) {
    m_offset[static_cast<std::size_t>(b)] = m_owned;
    m_owned += static_cast<std::int64_t>(owned_locals(static_cast<Block>(b)).size());
  }
  const auto& comm = layout.comm();
  const std::int64_t owned = m_owned;
  MPI_Exscan(&owned, &m_first, 1, MPI_INT64_T, MPI_SUM, comm.get());
  if (comm.rank() == 0) m_first = 0;
  MPI_Allreduce(&owned, &m_total, 1, MPI_INT64_T, MPI_SUM, comm.get());
  for (int b = 0; b < block_count; ++b) {
    auto& index = m_index[static_cast<std::size_t>(b)];
    index.assign(static_cast<std::size_t>(layout.local_count()), -1);
    const auto& locals = owned_locals(static_cast<Block>(b));
    for (std::size_t r = 0; r < locals.size(); ++r)
      index[static_cast<std::size_t>(locals[r])] = m_first + m_offset[static_cast<std::size_t>(b)] + static_cast<std::int64_t>(r);
    parallel::exchange_halo<std::int64_t>(layout, index);
  }
}

double& StepUnknowns::value(Block block, run::FlowState& state, int local) const {
  const auto l = static_cast<std::size_t>(local);
  if (block < solids_x) return state.gas_velocity[static_cast<std::size_t>(block)][l];
  if (block < pressure) return state.solids_velocity[static_cast<std::size_t>(block - solids_x)][l];
  return block == pressure ? state.gas_pressure[l] : state.solids_fraction[l];
}

void StepUnknowns::set_scales(double velocity, double pressure_scale) {
  for (int b = 0; b < static_cast<int>(pressure); ++b) m_scale[static_cast<std::size_t>(b)] = velocity;
  m_scale[pressure] = pressure_scale;
  m_scale[fraction] = 1.0;
  m_row_scale.resize(static_cast<std::size_t>(m_owned));
  for (int b = 0; b < block_count; ++b) {
    const auto offset = m_offset[static_cast<std::size_t>(b)];
    const auto rows = static_cast<std::int64_t>(owned_locals(static_cast<Block>(b)).size());
    for (std::int64_t r = offset; r < offset + rows; ++r) m_row_scale[static_cast<std::size_t>(r)] = m_scale[static_cast<std::size_t>(b)];
  }
}

void StepUnknowns::set_origin(const run::FlowState& state) {
  m_origin.resize(static_cast<std::size_t>(m_owned));
  auto& mutable_state = const_cast<run::FlowState&>(state);  // value() only reads here
  for (int b = 0; b < block_count; ++b) {
    const auto& locals = owned_locals(static_cast<Block>(b));
    const auto offset = m_offset[static_cast<std::size_t>(b)];
    for (std::size_t r = 0; r < locals.size(); ++r)
      m_origin[static_cast<std::size_t>(offset) + r] = value(static_cast<Block>(b), mutable_state, locals[r]);
  }
}

void StepUnknowns::fill_scales(Vec scales) const {
  PetscScalar* values = nullptr;
  petsc_check(VecGetArray(scales, &values), "VecGetArray");
  for (int b = 0; b < block_count; ++b) {
    const auto offset = m_offset[static_cast<std::size_t>(b)];
    const auto rows = static_cast<std::int64_t>(owned_locals(static_cast<Block>(b)).size());
    for (std::int64_t r = offset; r < offset + rows; ++r) values[r] = m_scale[static_cast<std::size_t>(b)];
  }
  petsc_check(VecRestoreArray(scales, &values), "VecRestoreArray");
}

void StepUnknowns::gather(const run::FlowState& state, Vec x) const {
  PetscScalar* values = nullptr;
  petsc_check(VecGetArray(x, &values), "VecGetArray");
  auto& mutable_state = const_cast<run::FlowState&>(state);  // value() only reads here
  for (int b = 0; b < block_count; ++b) {
    const auto& locals = owned_locals(static_cast<Block>(b));
    const auto offset = m_offset[static_cast<std::size_t>(b)];
    for (std::size_t r = 0; r < locals.size(); ++r)
      values[offset + static_cast<std::int64_t>(r)] =
          entry(offset + static_cast<std::int64_t>(r), value(static_cast<Block>(b), mutable_state, locals[r]));
  }
  petsc_check(VecRestoreArray(x, &values), "VecRestoreArray");
}

void StepUnknowns::scatter(Vec x, run::FlowState& state) const {
  const PetscScalar* values = nullptr;
  petsc_check(VecGetArrayRead(x, &values), "VecGetArrayRead");
  for (int b = 0; b < block_count; ++b) {
    const auto& locals = owned_locals(static_cast<Block>(b));
    const auto offset = m_offset[static_cast<std::size_t>(b)];
    for (std::size_t r = 0; r < locals.size(); ++r)
      value(static_cast<Block>(b), state, locals[r]) =
          m_origin[static_cast<std::size_t>(offset) + r] +
          values[offset + static_cast<std::int64_t>(r)] * m_scale[static_cast<std::size_t>(b)];
  }
  petsc_check(VecRestoreArrayRead(x, &values), "VecRestoreArrayRead");
  const auto& layout = m_discretization.layout();
  for (int d = 0; d < 3; ++d) {
    if (present(velocity_block(gas, d))) parallel::exchange_halo<double>(layout, state.gas_velocity[static_cast<std::size_t>(d)]);
    if (present(velocity_block(solids, d))) parallel::exchange_halo<double>(layout, state.solids_velocity[static_cast<std::size_t>(d)]);
  }
  if (present(pressure)) parallel::exchange_halo<double>(layout, state.gas_pressure);
  if (present(fraction)) {
    parallel::exchange_halo<double>(layout, state.solids_fraction);
    update_gas_fraction(m_discretization, state);
  }
}

}  // namespace bagnold::solver
