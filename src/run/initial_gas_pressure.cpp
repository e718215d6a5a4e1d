#include "src/run/initial_gas_pressure.hpp"

#include <cmath>

#include "src/run/layer_average.hpp"

namespace bagnold::run {

namespace {

void set_gas_weight(const deck::Deck& deck, const parallel::Domain& domain, FlowState& state) {
  const auto& layout = domain.layout;
  const auto& g = domain.grid;
  // The reference pressure at the domain's highest point along gravity.
  std::array<double, 3> reference{};
  for (int d = 0; d < 3; ++d) {
    const auto& faces = g.axis(d).faces();
    reference[static_cast<std::size_t>(d)] =
        deck.physics.gravity[static_cast<std::size_t>(d)] < 0 ? faces.back() : faces.front();
  }
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto x = g.centre(layout.index3(l));
    double head = 0.0;  // g · (x − x_ref) [m²/s²], >= 0 below the reference point
    for (std::size_t d = 0; d < 3; ++d) head += deck.physics.gravity[d] * (x[d] - reference[d]);
    state.gas_pressure[static_cast<std::size_t>(l)] = deck.gas.reference_pressure + deck.gas.density * head;
  }
}

void set_bed_weight(const deck::Deck& deck, const parallel::Domain& domain, FlowState& state) {
  const auto& layout = domain.layout;
  const int axis = deck.physics.gravity_axis();  // the deck's check: one axis, not periodic
  const double g = deck.physics.gravity[static_cast<std::size_t>(axis)];
  const auto& coordinates = domain.grid.axis(axis);
  const int n = coordinates.cells();
  const double gas_density = deck.gas.enabled ? deck.gas.density : 0.0;
  const double solids_density = deck.solids.enabled ? deck.solids.material.density : 0.0;
  std::vector<double> mixture(static_cast<std::size_t>(layout.local_count()), 0.0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    mixture[i] = state.gas_fraction[i] * gas_density + state.solids_fraction[i] * solids_density;
  }
  const auto layers = layer_means(domain, axis, mixture);
  // Layers from the top down: k = n − 1 ... 0 when gravity points to −axis, 0 ... n − 1 when +.
  const bool down_is_minus = g < 0.0;
  auto layer_from_top = [&](int depth) { return down_is_minus ? n - 1 - depth : depth; };
  // centre[k + 1]: the pressure at the centre of layer k, for k = −1 ... n (the ring layers
  // take the weight of the domain layer beside them over their half cell).
  std::vector<double> centre(static_cast<std::size_t>(n + 2), 0.0);
  double above = deck.gas.reference_pressure;  // at the upper face of the current layer
  const double weight = std::abs(g);
  for (int depth = 0; depth < n; ++depth) {
    const int k = layer_from_top(depth);
    const double half = 0.5 * weight * layers.mean[static_cast<std::size_t>(k)] * coordinates.width(k);
    centre[static_cast<std::size_t>(k + 1)] = above + half;
    above += 2.0 * half;
    if (depth == 0) {
      const int ring = down_is_minus ? n : -1;
      centre[static_cast<std::size_t>(ring + 1)] = deck.gas.reference_pressure - half;
    }
    if (depth == n - 1) {
      const int ring = down_is_minus ? -1 : n;
      centre[static_cast<std::size_t>(ring + 1)] = above + half;
    }
  }
  for (int l = 0; l < layout.local_count(); ++l) {
    const int k = layout.index3(l)[static_cast<std::size_t>(axis)];
    state.gas_pressure[static_cast<std::size_t>(l)] = centre[static_cast<std::size_t>(k + 1)];
  }
}

}  // namespace

void set_initial_gas_pressure(const deck::Deck& deck, const parallel::Domain& domain,
                              FlowState& state) {
  if (deck.gas.initial_pressure == "bed-weight")
    set_bed_weight(deck, domain, state);
  else
    set_gas_weight(deck, domain, state);
}

}  // namespace bagnold::run
