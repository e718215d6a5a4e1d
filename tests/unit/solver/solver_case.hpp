#pragma once
// Shared set-up of the solver step tests: a small deck built in code, its domain, the
// discretization and settings every step reads, and a state to fill by hand. Helpers for the
// positions of staggered velocities and for sums over ranks.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/simple/solver_settings.hpp"
#include "src/deck/load.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::tests {

// A box of nx × ny × nz cells of 1 cm, periodic in the directions listed in `periodic` (TOML
// array body, e.g. "\"x\", \"y\""), no gravity unless `gravity_z` is given, both phases
// (0.5 mm beads, ρ_s = 2500, plastic closure, Gidaspow drag) unless `extra` turns them off.
// `extra` is appended (boundaries, numerics, further sections).
inline std::string unit_deck(int nx, int ny, int nz, const std::string& periodic,
                             double gravity_z, const std::string& extra = "") {
  auto n = [](int c) { return std::to_string(c); };
  auto len = [](int c) { return std::to_string(0.01 * c); };
  return "[run]\nend_time = 0.1\n"
         "[physics]\ngravity = [0.0, 0.0, " + std::to_string(gravity_z) + "]\n"
         "[grid]\nperiodic = [" + periodic + "]\n"
         "[grid.x]\nmax = " + len(nx) + "\ncells = " + n(nx) + "\n"
         "[grid.y]\nmax = " + len(ny) + "\ncells = " + n(ny) + "\n"
         "[grid.z]\nmax = " + len(nz) + "\ncells = " + n(nz) + "\n"
         "[output]\ndirectory = \"out\"\nprogress = \"never\"\n" + extra;
}

// Two-phase sections: the solids material, drag and closure (plastic unless `stress` names
// another), appended to unit_deck's `extra`; with_gas = false: solids in vacuum.
inline std::string two_fluid(const std::string& stress = "plastic", bool with_gas = true) {
  return std::string(with_gas ? "[gas]\ndensity = 1.2\nviscosity = 1.8e-5\n" : "[gas]\nenabled = false\n") +
         "[solids]\ndiameter = 5e-4\ndensity = 2500.0\n"
         "[models.drag]\nmodel = \"gidaspow\"\n"
         "[models.solids_stress]\nmodel = \"" + stress + "\"\n";
}
// Linear solves far below every tolerance a test asserts (a [numerics] table to append last).
inline const std::string tight_linear_solves =
    "[numerics]\npressure_tolerance = 1e-12\nmomentum_tolerance = 1e-12\n";

// A 3 × 3 × 3 box of 1 cm cells, solids in vacuum with the plastic closure, with a pressure
// outflow under its middle floor cell (x, y in 1–2 cm), and `numerics` (lines of [numerics]).
inline std::string box_with_a_hole(const std::string& numerics) {
  return unit_deck(3, 3, 3, "", 0.0,
                   two_fluid("plastic", false) +
                       "[[boundary]]\nname = \"hole\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
                       "min = [0.01, 0.01, -1.0]\nmax = [0.02, 0.02, 0.0]\npressure = 101325.0\n"
                       "[numerics]\n" + numerics + "\n");
}

inline std::string gas_only() { return "[gas]\ndensity = 1.2\nviscosity = 1.8e-5\n[solids]\nenabled = false\n"; }

// Deck, domain, discretization, settings and a state (all fields per local cell).
struct Case {
  explicit Case(const std::string& text, const std::vector<std::string>& overrides = {})
      : deck(deck::load_deck_text(text, "unit.toml", overrides)),
        domain(deck, parallel::Communicator()),
        disc(domain),
        settings(deck, domain),
        state(domain.layout.local_count()),
        old(domain.layout.local_count()) {}

  const parallel::Layout& layout() const { return domain.layout; }
  int local_count() const { return domain.layout.local_count(); }
  int owned_fluid() const { return domain.layout.owned_fluid_count(); }
  bool fluid(int l) const { return l >= 0 && domain.layout.kind(l) == grid::CellKind::fluid; }

  // Centre of local cell l, and the position of its staggered velocity along d (the + face).
  std::array<double, 3> centre(int l) const { return domain.grid.centre(domain.layout.index3(l)); }
  std::array<double, 3> face_position(int l, int d) const {
    auto x = centre(l);
    x[static_cast<std::size_t>(d)] =
        domain.grid.axis(d).upper_face(domain.layout.index3(l)[static_cast<std::size_t>(d)]);
    return x;
  }
  double sum(double x) const { return domain.layout.comm().sum(x); }
  double max(double x) const { return domain.layout.comm().max(x); }

  // Σ ε_s V over the owned fluid cells of all ranks.
  double solids_volume(const run::FlowState& s) const {
    double total = 0.0;
    for (int l = 0; l < owned_fluid(); ++l) total += s.solids_fraction[static_cast<std::size_t>(l)] * disc.volume(l);
    return sum(total);
  }
  // ε_g = 1 − ε_s wherever ε_s is set (every local cell).
  static void complete_gas_fraction(run::FlowState& s) {
    for (std::size_t i = 0; i < s.solids_fraction.size(); ++i) s.gas_fraction[i] = 1.0 - s.solids_fraction[i];
  }

  deck::Deck deck;
  parallel::Domain domain;
  solver::Discretization disc;
  solver::SolverSettings settings;
  run::FlowState state;
  run::FlowState old;
};

// A smooth, position-dependent value that differs from cell to cell and is the same on every
// rank for the same cell (so halo copies agree without an exchange).
inline double wiggle(const std::array<double, 3>& x, double phase = 0.0) {
  return std::sin(173.0 * x[0] + 311.0 * x[1] + 97.0 * x[2] + phase);
}

// Solids (no gas) at ε_s everywhere, velocity u_i = G_ij x_j at every face; old = state.
inline void set_linear_solids(Case& c, double eps_s, const double G[3][3]) {
  for (int l = 0; l < c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    c.state.solids_fraction[i] = eps_s;
    c.state.gas_fraction[i] = 1.0 - eps_s;
    for (int a = 0; a < 3; ++a) {
      const auto x = c.face_position(l, a);
      double u = 0.0;
      for (int b = 0; b < 3; ++b) u += G[a][b] * x[static_cast<std::size_t>(b)];
      c.state.solids_velocity[static_cast<std::size_t>(a)][i] = u;
    }
  }
  c.old = c.state;
}

}  // namespace bagnold::tests
