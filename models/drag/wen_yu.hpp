#pragma once
// Wen–Yu drag with the Schiller–Naumann single-sphere drag coefficient.
//
// Sources:
//   C. Y. Wen and Y. H. Yu (1966), "Mechanics of fluidization", Chemical Engineering Progress
//     Symposium Series 62(62), 100–111 — the single-sphere drag corrected for the
//     neighbours by a power of the voidage, here in its β form ε_g^−2.65.
//   L. Schiller and A. Naumann (1933), "Über die grundlegenden Berechnungen bei der
//     Schwerkraftaufbereitung", Zeitschrift des Vereines Deutscher Ingenieure 77, 318–320.
//   As written in D. Gidaspow (1994), Multiphase Flow and Fluidization, Academic Press, and as
//   MFIX implements it (DRAG_WEN_YU in model/drag_gs.f; model A).
//
//   Re  = ε_g ρ_g |u_g − u_s| d_p / μ_g
//   C_D = 24/Re (1 + 0.15 Re^0.687)  for Re < 1000,   0.44  for Re ≥ 1000
//   β   = ¾ C_D ε_s ε_g ρ_g |u_g − u_s| / d_p · ε_g^−2.65
//       = ¾ (C_D Re) ε_s μ_g ε_g^−2.65 / d_p²       (the form evaluated: finite at slip 0)
//
// Limits: at Re → 0, β → 18 μ_g ε_s ε_g^−2.65 / d_p², which for ε_s → 0 is n·3πμ_g d_p, Stokes
// drag on n = ε_s/(π d_p³/6) spheres per volume. C_D Re jumps by 0.4 % at Re = 1000 (438.3 to
// 440), as in the source. Meant for suspensions (ε_g ≳ 0.8); for packed and dense beds Gidaspow
// switches to Ergun's packed-bed correlation (gidaspow.hpp).

#include <string>

#include "models/drag/drag_law.hpp"

namespace bagnold::models::drag {

// Schiller–Naumann C_D·Re (0.44 Re above Re = 1000); 24 at Re = 0.
double schiller_naumann_drag_times_reynolds(double reynolds);

// β of Wen–Yu [kg/(m³ s)] at one state; ε_g in (0, 1], slip ≥ 0.
double wen_yu_coefficient(const DragProperties& p, double gas_fraction, double slip_speed);

class WenYu final : public DragLaw {
 public:
  explicit WenYu(double min_gas_fraction) : m_min_gas_fraction(min_gas_fraction) {}
  std::string name() const override { return "wen-yu"; }
  void evaluate(const DragProperties& properties, const DragState& in,
                std::span<double> beta) const override;

 private:
  double m_min_gas_fraction;  // ε_g,min [-]
};

}  // namespace bagnold::models::drag
