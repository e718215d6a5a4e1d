#pragma once
// Material properties of the granular phase, shared by every closure. SI units.
// The deck fills this from [solids]; the rheometer fills it from --set / --deck.

namespace bagnold::models {

struct Material {
  double diameter = 1e-3;    // d [m]
  double density = 2500.0;   // ρ_s [kg/m³]
  double restitution = 0.8;  // e [-], normal coefficient of restitution
  double friction = 0.3;     // μ [-], interparticle friction coefficient
  double stiffness = 1e5;    // k [N/m], Hookean normal spring stiffness (rheology models)
  double bond_number = 0.0;  // Bo* [-], modified Bond number (cohesive rheology)

  bool operator==(const Material&) const = default;
};

}  // namespace bagnold::models
