#pragma once
// The solids' tangential wall conditions of the [[boundary]] regions (deck key solids_wall),
// evaluated as one implicit coefficient per wall face (models/wall/wall_coefficient.hpp):
//     τ_w = −c_w (u_P − U_wall),   1/c_w = δ/μ_s + 1/c_slip,
// which the momentum row of u_P takes as a_P += c_w A, b += c_w A U_wall, where a no-slip wall
// puts μ_s A/δ (momentum_assembly.cpp). c_slip per law:
//   no-slip          ∞        (the assembly keeps μ_s A/δ; this class is not asked)
//   free-slip        0
//   johnson-jackson  c_JJ(φ, g0, Θ) (models/wall/johnson_jackson.hpp): Θ of the cell where the
//                    closure defines one, else the wall temperature at which q_w = 0
//   dense-slip       ρ_s d γ̇/F(η), the report's App. C slip (models/wall/dense_slip.hpp)
// Evaluated on the first outer iteration of a step and held for the rest of it
// (SolidsWallCoefficients): the slip laws switch steeply near yield (η ≈ η_s), and
// re-evaluating them every iteration made the iterations cycle.

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "models/wall/dense_slip.hpp"
#include "models/wall/johnson_jackson.hpp"
#include "solver/discretization.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/velocity_faces.hpp"
#include "src/deck/deck.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// The solids next to a wall face, averaged over the two cells beside the tangential velocity.
struct NearWallSolids {
  double fraction = 0.0;     // φ [-]
  double pressure = 0.0;     // P_s [Pa]
  double viscosity = 0.0;    // μ_s [Pa s]
  double strain_rate = 0.0;  // γ̇ [1/s]
  double temperature = 0.0;  // Θ [m²/s²] (NaN where the closure defines none)
  double slip_speed = 0.0;   // |u_s − U_wall| tangential, at the cell centres [m/s]
};

class SolidsWalls {
 public:
  // One law per region of `regions` (the deck's [[boundary]] and the implicit "walls").
  // `has_temperature`: whether the closure defines Θ. Throws std::invalid_argument where a
  // law's limits are violated (the deck loader reports these first).
  SolidsWalls(const deck::Deck& deck, const grid::BoundaryRegions& regions, bool has_temperature);

  // Whether region r (-1: none) has a solids law other than no-slip.
  bool partial(int region) const {
    return region >= 0 && static_cast<std::size_t>(region) < m_laws.size() &&
           slips(m_laws[static_cast<std::size_t>(region)]);
  }
  bool any_partial() const { return std::ranges::any_of(m_laws, slips); }
  // c_w [Pa s/m] for a face of region r at wall distance δ [m].
  double coefficient(int region, const NearWallSolids& near, double wall_distance) const;

 private:
  enum class Kind { no_slip, free_slip, johnson_jackson, dense_slip };
  struct Law {
    Kind kind = Kind::no_slip;
    models::wall::JohnsonJacksonWall johnson_jackson{0.0, 0.0, 1.0};
    std::optional<models::wall::DenseSlip> dense;
  };
  static bool slips(const Law& law) { return law.kind != Kind::no_slip; }
  models::Material m_material;
  bool m_has_temperature;
  std::vector<Law> m_laws;
};

// The held c_w [Pa s/m] of every partial-slip solids wall face, per tangential component d and
// slot 6 × local + face of the velocity's stencil.
class SolidsWallCoefficients {
 public:
  SolidsWallCoefficients(const deck::Deck& deck, const Discretization& discretization,
                         bool has_temperature);

  // Whether the wall across `link` has a partial-slip solids law.
  bool partial(const Link& link) const { return m_walls.partial(link.region); }
  // c_w of the face `face` of the component-d velocity owned by l, evaluated now from the
  // iterate (refresh) or as last evaluated. e the wall-normal direction.
  double coefficient(const Discretization& discretization, const run::FlowState& state,
                     const ClosureFields& closures, const Link& link, int l, int d, int face,
                     bool refresh);

 private:
  SolidsWalls m_walls;
  std::array<std::vector<double>, 3> m_held;  // empty without partial-slip walls
};

// The closure's packing limit φ_max for Johnson–Jackson: 1 − packed_gas_fraction where the
// closure has that coefficient (plastic, mfix-default), else φ_c(μ) of App. A Table I.
double solids_packing_limit(const deck::Deck& deck);

}  // namespace bagnold::solver
