#pragma once
// The unknowns of one time step as one vector, for the Newton solve of the whole step
// (newton_step.hpp): per rank, its owned rows of each block in turn,
//   gas velocity x, y, z | solids velocity x, y, z | gas pressure | solids fraction,
// each block in its own numbering's row order (Discretization::velocity_numbering,
// cell_numbering), the ranks one after the other. A block is absent when its phase does not
// move (no gas momentum: no gas velocity and no pressure; no solids momentum: no solids velocity
// and no fraction). Every local cell (halo included) knows the global index of each of its
// unknowns, so a row can name its columns on other ranks.

#include <petscvec.h>

#include <array>
#include <cstdint>
#include <vector>

#include "solver/discretization.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class StepUnknowns {
 public:
  enum Block : int { gas_x, gas_y, gas_z, solids_x, solids_y, solids_z, pressure, fraction, block_count };
  static Block velocity_block(Phase phase, int d) { return static_cast<Block>((phase == gas ? gas_x : solids_x) + d); }

  // collective
  StepUnknowns(const Discretization& discretization, std::array<bool, 2> moves);

  bool present(Block block) const { return m_present[static_cast<std::size_t>(block)]; }
  // The global index of `block`'s unknown at local cell `local`, -1 where it has none.
  std::int64_t index(Block block, int local) const {
    return local < 0 ? -1 : m_index[static_cast<std::size_t>(block)][static_cast<std::size_t>(local)];
  }
  // The owned cells of a block, in row order (empty when absent).
  const std::vector<int>& owned_locals(Block block) const;
  std::int64_t first_row() const { return m_first; }
  std::int64_t owned_rows() const { return m_owned; }
  std::int64_t total_rows() const { return m_total; }
  // The local offset (within this rank's rows) of a block's first row.
  std::int64_t block_offset(Block block) const { return m_offset[static_cast<std::size_t>(block)]; }

  // The vector holds each unknown's change from an origin (set_origin: the step's start) in
  // units of its block's scale (set_scales), so that its entries vary by comparable amounts: a
  // velocity in units of a reference speed, the gas pressure (10⁵ Pa absolute, changing by a few
  // Pa) in units of a reference pressure, the fraction as it is. The matrix-free Jacobian
  // differences F along this vector with a step relative to its size: on absolute pressures that
  // step would be far too coarse for the velocities.
  void set_scales(double velocity, double pressure_scale);
  void set_origin(const run::FlowState& state);
  // The entry of the owned row r (within the rank) that stands for the value `value`.
  double entry(std::int64_t r, double value) const { return (value - m_origin[static_cast<std::size_t>(r)]) / m_row_scale[static_cast<std::size_t>(r)]; }
  double scale(Block block) const { return m_scale[static_cast<std::size_t>(block)]; }
  // Per owned row, the scale of its unknown (for the Jacobian's columns).
  void fill_scales(Vec scales) const;

  // The state's unknowns into `x` (this rank's rows).
  void gather(const run::FlowState& state, Vec x) const;
  // `x` into the state's unknowns, halos exchanged; ε_g = 1 − ε_s in fluid cells.
  void scatter(Vec x, run::FlowState& state) const;

 private:
  double& value(Block block, run::FlowState& state, int local) const;
  const Discretization& m_discretization;
  std::array<bool, block_count> m_present{};
  std::array<std::vector<std::int64_t>, block_count> m_index;
  std::array<std::int64_t, block_count> m_offset{};
  std::array<double, block_count> m_scale{1, 1, 1, 1, 1, 1, 1, 1};
  std::vector<double> m_origin, m_row_scale;  // per owned row
  std::int64_t m_first = 0, m_owned = 0, m_total = 0;
  std::vector<int> m_none;
};

}  // namespace bagnold::solver
