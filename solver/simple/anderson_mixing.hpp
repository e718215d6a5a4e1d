#pragma once
// Anderson mixing of the outer iteration (numerics.anderson_depth = m > 0).
//
// One outer iteration maps the iterate x to G(x) (closures, predictors, corrections). Plain
// Picard takes x ← G(x). Anderson's type-II mixing (Walker & Ni, SIAM J. Numer. Anal. 49, 2011,
// Eqs. 1.4–1.5; Anderson, J. ACM 12, 1965) keeps the last m differences of the residuals
// f_i = G(x_i) − x_i and of the images G(x_i), and takes
//   γ = argmin ‖f_k − ΔF γ‖_W,     x_{k+1} = G(x_k) − ΔG γ,
// an affine combination of the last m + 1 images (the weights sum to 1, so ε_g + ε_s = 1 and
// every fixed boundary value are kept). The norm W weighs each field by a scale of its own
// (velocities by the residual velocity scale, the gas pressure by its range at the step's
// start, the fractions by 0.01), so that no unit dominates the least-squares fit.
//
// Mixed are the quantities the next iteration starts from: both phases' face velocities, the
// gas pressure and both volume fractions. The others (P_s, Θ, γ̇_P) are recomputed by the
// closures from these. Where the mixture would take ε_s below 0 or above the largest ε_s of the
// images, ε_s is clipped into that range (ε_g = 1 − ε_s); the count goes to the monitor
// (limit_anderson_clipped). A least-squares fit that fails (singular) restarts the history.
#include <vector>

#include "src/parallel/layout.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class AndersonMixing {
 public:
  AndersonMixing(const parallel::Layout& layout, int depth);

  // Starts a step from `old`: forgets the history; the gas pressure's range over the owned cells
  // (at least 1 Pa) becomes its scale. Collective.
  void start_step(const run::FlowState& old);
  // Before an outer iteration: records its input x_k.
  void remember_input(const run::FlowState& state);
  // After it: `state` holds G(x_k); replaces it by the mixture x_{k+1} (halos exchanged).
  // `velocity_scale` [m/s] weighs the velocities. Collective. Returns the number of this rank's
  // cells whose ε_s was clipped.
  long mix(run::FlowState& state, double velocity_scale);

 private:
  void pack(const run::FlowState& state, std::vector<double>& into) const;
  void unpack(const std::vector<double>& from, run::FlowState& state) const;
  double dot(const std::vector<double>& a, const std::vector<double>& b) const;  // local, weighted

  const parallel::Layout& m_layout;
  std::size_t m_depth;
  std::size_t m_owned;     // entries per field (the owned cells)
  double m_pressure_weight = 0.0;
  double m_velocity_weight = 1.0;
  std::vector<double> m_input, m_image, m_residual;        // x_k, G(x_k), f_k
  std::vector<double> m_last_image, m_last_residual;        // G(x_{k−1}), f_{k−1}
  bool m_has_last = false;
  std::vector<std::vector<double>> m_delta_f, m_delta_g;    // newest last, at most m_depth
};

}  // namespace bagnold::solver
