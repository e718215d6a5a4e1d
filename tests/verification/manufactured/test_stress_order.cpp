// Observed order of the discrete stress divergence of the momentum rows
// (solver/simple/momentum_assembly.cpp) with a manufactured field: a compressible periodic
// velocity, a viscosity that spans four decades (1 to 10⁴ Pa s) and a bulk viscosity λ = 0.7 μ.
// The rows' stress force (their residual with μ, λ set minus the same with them zero) per unit
// volume is compared with the exact ∇·σ, σ = μ(∇u + ∇uᵀ) + (λ − ⅔ μ)(∇·u) I, at each face
// velocity's position, on 16³, 32³ and 64³ cells of the same periodic box; the largest error must
// fall as h² (both phases: the gas has λ = 0). This checks the consistency of the discrete
// operator, including the transpose and dilatational terms and the harmonic face viscosities.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solver/simple/face_fractions.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::gas;
using solver::solids;

constexpr double box = 0.08;  // periodic box edge [m]
constexpr double k = 2.0 * M_PI / box;
constexpr double bulk_ratio = 0.7;  // λ/μ of the solids

// A product of sines Π_b sin(k x_b + phase_b) times amplitude, and its derivatives.
struct SineProduct {
  double amplitude;
  std::array<double, 3> phase;
  // ∂^{n_0+n_1+n_2} / ∂x_0^{n_0} ∂x_1^{n_1} ∂x_2^{n_2} at x (each n_b ≤ 2).
  double derivative(const std::array<double, 3>& x, const std::array<int, 3>& n) const {
    double value = amplitude;
    for (std::size_t b = 0; b < 3; ++b) {
      const double arg = k * x[b] + phase[b];
      switch (n[b]) {
        case 0: value *= std::sin(arg); break;
        case 1: value *= k * std::cos(arg); break;
        default: value *= -k * k * std::sin(arg); break;
      }
    }
    return value;
  }
  double operator()(const std::array<double, 3>& x) const { return derivative(x, {0, 0, 0}); }
};

// A compressible velocity (∇·u ≠ 0) and log10 μ = 2 + 2 g (μ from 1 to 10⁴ Pa s).
const std::array<SineProduct, 3> velocity{{{0.3, {0.3, 1.9, 0.7}}, {0.2, {1.1, 0.4, 2.3}}, {0.25, {2.0, 0.9, 0.1}}}};
const SineProduct log_shape{1.0, {0.2, 1.3, 0.6}};

double viscosity(const std::array<double, 3>& x) { return std::pow(10.0, 2.0 + 2.0 * log_shape(x)); }

std::array<int, 3> order(int a, int b = -1) {
  std::array<int, 3> n{0, 0, 0};
  ++n[static_cast<std::size_t>(a)];
  if (b >= 0) ++n[static_cast<std::size_t>(b)];
  return n;
}

// (∇·σ)_d at x.
double exact_force(const std::array<double, 3>& x, int d, bool with_bulk) {
  const double mu = viscosity(x);
  std::array<double, 3> grad_mu;
  for (int j = 0; j < 3; ++j) grad_mu[static_cast<std::size_t>(j)] = mu * std::log(10.0) * 2.0 * log_shape.derivative(x, order(j));
  const double lambda_ratio = with_bulk ? bulk_ratio : 0.0;
  const auto& ud = velocity[static_cast<std::size_t>(d)];
  double divergence = 0.0, divergence_d = 0.0, force = 0.0;
  for (int j = 0; j < 3; ++j) {
    const auto& uj = velocity[static_cast<std::size_t>(j)];
    divergence += uj.derivative(x, order(j));
    divergence_d += uj.derivative(x, order(j, d));
    force += grad_mu[static_cast<std::size_t>(j)] * (ud.derivative(x, order(j)) + uj.derivative(x, order(d))) +
             mu * (ud.derivative(x, order(j, j)) + uj.derivative(x, order(d, j)));
  }
  const double coefficient = (lambda_ratio - 2.0 / 3.0) * mu;
  force += (lambda_ratio - 2.0 / 3.0) * grad_mu[static_cast<std::size_t>(d)] * divergence + coefficient * divergence_d;
  return force;
}

// The largest |discrete − exact| of (∇·σ)_d over the rows of one phase along all three
// directions, on n³ cells, relative to the largest exact value.
double stress_error(int n, solver::Phase phase) {
  const std::string length = std::to_string(box);
  Case c(unit_deck(n, n, n, "\"x\", \"y\", \"z\"", 0.0, two_fluid("plastic")),
         {"grid.x.max=" + length, "grid.y.max=" + length, "grid.z.max=" + length});
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  for (int l = 0; l < c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    c.state.solids_fraction[i] = 0.5;
    c.state.gas_fraction[i] = 0.5;
    for (int a = 0; a < 3; ++a) {
      const double u = velocity[static_cast<std::size_t>(a)](c.face_position(l, a));
      c.state.gas_velocity[static_cast<std::size_t>(a)][i] = u;
      c.state.solids_velocity[static_cast<std::size_t>(a)][i] = u;
    }
    const double mu = viscosity(c.centre(l));
    fields.viscosity[static_cast<std::size_t>(phase)][i] = mu;
    fields.bulk_viscosity[i] = phase == solids ? bulk_ratio * mu : 0.0;
  }
  c.old = c.state;
  solver::velocity_divergence(c.disc, c.state.gas_velocity, fields.divergence[gas]);
  solver::velocity_divergence(c.disc, c.state.solids_velocity, fields.divergence[solids]);
  solver::CarriedFractions carried(static_cast<std::size_t>(c.local_count()));
  solver::carry_all_fractions(c.disc, c.state, carried);
  solver::ClosureFields inviscid = fields;
  for (auto& v : inviscid.viscosity) std::fill(v.begin(), v.end(), 0.0);
  std::fill(inviscid.bulk_viscosity.begin(), inviscid.bulk_viscosity.end(), 0.0);

  const std::array<std::vector<double>, 3> no_source;
  double worst = 0.0, largest = 0.0;
  for (int d = 0; d < 3; ++d) {
    std::vector<solver::MomentumRow> with, without;
    const solver::MomentumAssemblyInputs viscous{c.disc, c.settings, c.old, 1e-3, fields, carried, no_source};
    const solver::MomentumAssemblyInputs bare{c.disc, c.settings, c.old, 1e-3, inviscid, carried, no_source};
    solver::MomentumAssemblyScratch scratch;
    solver::assemble_momentum_rows(viscous, phase, d, c.state, nullptr, true, with, scratch);
    solver::assemble_momentum_rows(bare, phase, d, c.state, nullptr, true, without, scratch);
    const auto& u = (phase == gas ? c.state.gas_velocity : c.state.solids_velocity)[static_cast<std::size_t>(d)];
    const auto& numbering = c.disc.velocity_numbering(d);
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
      const int l = numbering.owned_locals[r];
      const auto i = static_cast<std::size_t>(l);
      auto residual = [&](const solver::MomentumRow& row) { return row.b + row.neighbours_u - row.a * u[i]; };
      const double discrete = (residual(with[r]) - residual(without[r])) / with[r].volume;
      const double exact = exact_force(c.face_position(l, d), d, phase == solids);
      worst = std::max(worst, std::abs(discrete - exact));
      largest = std::max(largest, std::abs(exact));
    }
  }
  return c.max(worst) / c.max(largest);
}

TEST(StressOrder, FullStressDivergenceIsSecondOrderWithFourDecadesOfViscosity) {
  for (const auto phase : {solids, gas}) {
    const double e16 = stress_error(16, phase), e32 = stress_error(32, phase), e64 = stress_error(64, phase);
    const double p1 = std::log2(e16 / e32), p2 = std::log2(e32 / e64);
    std::printf("%s: relative max error %.3e (16), %.3e (32), %.3e (64); observed order %.2f, %.2f\n",
                phase == solids ? "solids" : "gas", e16, e32, e64, p1, p2);
    EXPECT_GT(p2, 1.9) << (phase == solids ? "solids" : "gas");
    EXPECT_LT(p2, 2.1) << (phase == solids ? "solids" : "gas");
    EXPECT_LT(e64, 0.02);
  }
}

}  // namespace
}  // namespace bagnold::tests
