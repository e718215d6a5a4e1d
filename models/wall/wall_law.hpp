#pragma once
// The solids' tangential wall laws, chosen per [[boundary]] region by name (deck key
// solids_wall) through a registry, as the stress and drag closures are (models/registry.hpp).
// Every law gives one implicit coefficient per wall face (wall_coefficient.hpp):
//     τ_w = −c_w (u_P − U_wall),   1/c_w = δ/μ_s + 1/c_slip,
// which the momentum row of u_P takes as a_P += c_w A, b += c_w A U_wall. c_slip per member:
//   no-slip          ∞         c_w = μ_s/δ                                      (no_slip.cpp)
//   free-slip        0         c_w = 0                                          (free_slip.cpp)
//   johnson-jackson  c_JJ(φ, g0, Θ), Johnson & Jackson (1987): Θ of the cell where the closure
//                    defines one, else the wall temperature at which q_w = 0
//                                                                    (johnson_jackson.cpp)
//   dense-slip       ρ_s d γ̇/F(η), the report's App. C slip                  (dense_slip.cpp)
// A law is built once per region from the material, the region's wall parameters and what the
// solids-stress closure says about itself (ClosureAtWall); it never sees the solver.

#include <functional>
#include <memory>
#include <string>

#include "models/material.hpp"
#include "models/registry.hpp"

namespace bagnold::models {
class SolidsStressModel;
}

namespace bagnold::models::wall {

// The solids next to a wall face, averaged over the two cells beside the tangential velocity.
struct NearWallSolids {
  double fraction = 0.0;     // φ [-]
  double pressure = 0.0;     // P_s [Pa]
  double viscosity = 0.0;    // μ_s [Pa s]
  double strain_rate = 0.0;  // γ̇ [1/s]
  double temperature = 0.0;  // Θ [m²/s²] (NaN where the closure defines none)
  double slip_speed = 0.0;   // |u_s − U_wall| tangential, at the cell centres [m/s]
};

// A [[boundary]] region's wall parameters (each law reads the ones it takes).
struct WallParameters {
  double specularity = 0.0;       // φ' [-], johnson-jackson
  double wall_restitution = 0.0;  // e_w [-], johnson-jackson
  double wall_friction = 0.0;     // μ_w [-], dense-slip
};

// What a wall law needs from the solids-stress closure (SolidsStressModel::packing_limit and
// wall_radial_distribution, for the run's material).
struct ClosureAtWall {
  bool defines_temperature = false;  // whether Θ of the near-wall cells is meaningful
  double packing_limit = 1.0;        // φ_max [-]
  std::function<double(double)> radial_distribution;  // g0(φ) [-] at the wall
};

// The closure's properties above for `material`. The returned g0 refers to `model`, which must
// outlive it.
ClosureAtWall closure_at_wall(const SolidsStressModel& model, const Material& material);

struct WallLawInput {
  Material material;
  WallParameters wall;
  ClosureAtWall closure;
};

class WallLaw {
 public:
  virtual ~WallLaw() = default;
  virtual std::string name() const = 0;
  // c_w [Pa s/m] for the tangential velocity a distance δ = wall_distance [m] > 0 from the wall.
  virtual double coefficient(const NearWallSolids& near, double wall_distance) const = 0;
  // Whether the law lets the solids slip (false only for no-slip).
  virtual bool slips() const = 0;
};

// Members: no-slip, free-slip, johnson-jackson, dense-slip. make() throws std::invalid_argument
// where the law's limits are violated (require_valid, DenseSlip's constructor).
Registry<WallLaw, WallLawInput>& wall_law_registry();

}  // namespace bagnold::models::wall
