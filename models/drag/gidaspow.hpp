#pragma once
// Gidaspow drag: Ergun in dense beds, Wen–Yu in dilute suspensions.
//
// Sources:
//   D. Gidaspow (1994), Multiphase Flow and Fluidization: Continuum and Kinetic Theory
//     Descriptions, Academic Press, Boston (Ch. 5); J. Ding and D. Gidaspow (1990), "A bubbling
//     fluidization model using kinetic theory of granular flow", AIChE Journal 36(4), 523–538.
//   S. Ergun (1952), "Fluid flow through packed columns", Chemical Engineering Progress 48(2),
//     89–94.
//   Wen & Yu (1966) with Schiller–Naumann C_D: see wen_yu.hpp.
//   As MFIX implements it (DRAG_GIDASPOW and DRAG_GIDASPOW_BLEND in model/drag_gs.f).
//
//   ε_g ≤ 0.8:  β_Ergun = 150 ε_s² μ_g / (ε_g d_p²) + 1.75 ε_s ρ_g |u_g − u_s| / d_p
//   ε_g > 0.8:  β_WenYu (wen_yu.hpp)
// The boundary point ε_g = 0.8 takes Ergun, as in MFIX.
//
// THE SWITCH IS DISCONTINUOUS: at ε_g = 0.8 the two branches differ (for air and 1 mm beads at
// 1 m/s slip, Ergun gives 555 and Wen–Yu 387 kg/(m³ s)), which can make the outer iterations of
// a cell near 0.8 oscillate. The coefficient `transition = "arctan-blend"` replaces the step by
// the smooth switch of MFIX's GIDASPOW_BLEND (origin unknown to MFIX; cited there as
// D. Lathouwers and J. Bellan (2000), Proc. 2000 U.S. DOE Hydrogen Program Review,
// NREL/CP-570-28890):
//   φ_gs = arctan(150 · 1.75 (ε_g − 0.8))/π + ½,   β = (1 − φ_gs) β_Ergun + φ_gs β_WenYu.
// The blend is exact on neither side (arctan tails decay slowly): φ_gs = 0.0024 at ε_g = 0.3,
// 0.012 at 0.7, 0.988 at 0.9 and 0.994 at 0.99 — about 1 % of the other law within 0.1 of 0.8.

#include <string>

#include "models/drag/drag_law.hpp"

namespace bagnold::models::drag {

// Ergun's β [kg/(m³ s)] at one state; ε_g in (0, 1], slip ≥ 0.
double ergun_coefficient(const DragProperties& p, double gas_fraction, double slip_speed);

// Weight φ_gs of Wen–Yu in the blended variant (0 deep in the Ergun range, 1 in the dilute).
double gidaspow_blend_weight(double gas_fraction);

// The Ergun/Wen–Yu boundary, ε_g = 0.8 (Ergun at and below it).
inline constexpr double gidaspow_switch_gas_fraction = 0.8;

enum class GidaspowTransition { step, arctan_blend };

class Gidaspow final : public DragLaw {
 public:
  Gidaspow(GidaspowTransition transition, double min_gas_fraction)
      : m_transition(transition), m_min_gas_fraction(min_gas_fraction) {}
  std::string name() const override { return "gidaspow"; }
  void evaluate(const DragProperties& properties, const DragState& in,
                std::span<double> beta) const override;

 private:
  GidaspowTransition m_transition;
  double m_min_gas_fraction;  // ε_g,min [-]
};

}  // namespace bagnold::models::drag
