#pragma once
// The solids' tangential wall conditions of the [[boundary]] regions (deck key solids_wall):
// one models::wall::WallLaw per region from the wall-law registry (models/wall/wall_law.hpp),
// each giving one implicit coefficient per wall face,
//     τ_w = −c_w (u_P − U_wall),   1/c_w = δ/μ_s + 1/c_slip,
// which the momentum row of u_P takes as a_P += c_w A, b += c_w A U_wall, where a no-slip wall
// puts μ_s A/δ (momentum_assembly.cpp). Only walls (no_slip_wall, moving_wall) take the
// region's law; every other region is no-slip here (its faces are not walls for the solids).
// The coefficients are evaluated on the first outer iteration of a step and held for the rest
// of it (SolidsWallCoefficients): the slip laws switch steeply near yield (η ≈ η_s), and
// re-evaluating them every iteration made the iterations cycle.

#include <memory>
#include <vector>

#include "models/stress/solids_stress.hpp"
#include "models/wall/wall_law.hpp"
#include "solver/discretization.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/velocity_faces.hpp"
#include "src/deck/deck.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// |u_s − U_wall| tangential to a wall whose normal is along `normal`, at the centre of local
// cell l (both tangential components).
double tangential_slip_speed(const parallel::Layout& layout, const run::FlowState& state, int l,
                             int normal, const std::array<double, 3>& wall_velocity);

// The solids' wall law of each boundary region, in region order: the region's solids_wall for
// a wall (no_slip_wall, moving_wall), no-slip for any other region. `closure` must outlive them.
std::vector<std::unique_ptr<models::wall::WallLaw>> solids_wall_laws(
    const deck::Deck& deck, const grid::BoundaryRegions& regions,
    const models::SolidsStressModel& closure);

// The held c_w [Pa s/m] of every partial-slip solids wall face, per tangential component d and
// slot 6 × local + face of the velocity's stencil.
class SolidsWallCoefficients {
 public:
  // `closure`: the solids-stress model (its packing limit, g0 and Θ), which must outlive this.
  // Throws std::invalid_argument where a law's limits are violated (the deck loader reports
  // these first).
  SolidsWallCoefficients(const deck::Deck& deck, const Discretization& discretization,
                         const models::SolidsStressModel& closure);

  // Whether the wall across `link` has a partial-slip solids law.
  bool partial(const Link& link) const {
    return link.region >= 0 && m_laws[static_cast<std::size_t>(link.region)]->slips();
  }
  // c_w of the face `face` of the component-d velocity owned by l, evaluated now from the
  // iterate (refresh) or as last evaluated. e the wall-normal direction.
  double coefficient(const Discretization& discretization, const run::FlowState& state,
                     const ClosureFields& closures, const Link& link, int l, int d, int face,
                     bool refresh);

 private:
  std::vector<std::unique_ptr<models::wall::WallLaw>> m_laws;  // per region
  std::array<std::vector<double>, 3> m_held;  // empty without partial-slip walls
};

}  // namespace bagnold::solver
