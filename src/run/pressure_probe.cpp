#include "src/run/pressure_probe.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "src/run/layer_average.hpp"

namespace bagnold::run {

namespace {

// The cell i of one axis whose [lower, upper) face interval holds x (the last cell holds its
// upper face), or -1 outside.
int cell_of(const grid::AxisCoordinates& axis, double x) {
  const auto& faces = axis.faces();
  if (x < faces.front() || x > faces.back()) return -1;
  const auto above = std::upper_bound(faces.begin(), faces.end(), x);
  return std::min(static_cast<int>(above - faces.begin()) - 1, axis.cells() - 1);
}

bool layer_has_fluid(const parallel::Domain& domain, int axis, int layer) {
  const auto& g = domain.grid;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  grid::Index3 ijk{};
  ijk[static_cast<std::size_t>(axis)] = layer;
  for (int i = 0; i < g.cells(a); ++i)
    for (int j = 0; j < g.cells(b); ++j) {
      ijk[static_cast<std::size_t>(a)] = i;
      ijk[static_cast<std::size_t>(b)] = j;
      if (domain.flags.kind[static_cast<std::size_t>(g.natural(ijk))] == grid::CellKind::fluid)
        return true;
    }
  return false;
}

std::string point_text(const std::array<double, 3>& x) {
  return fmt::format("[{:g}, {:g}, {:g}]", x[0], x[1], x[2]);
}

}  // namespace

std::optional<grid::Index3> cell_holding(const grid::StructuredGrid& grid,
                                         const std::array<double, 3>& point) {
  grid::Index3 ijk{};
  for (int d = 0; d < 3; ++d) {
    const int i = cell_of(grid.axis(d), point[static_cast<std::size_t>(d)]);
    if (i < 0) return std::nullopt;
    ijk[static_cast<std::size_t>(d)] = i;
  }
  return ijk;
}

std::vector<ProbeProblem> pressure_probe_problems(const deck::Deck& deck,
                                                  const parallel::Domain& domain) {
  std::vector<ProbeProblem> problems;
  const int axis = deck.physics.gravity_axis();
  for (std::size_t p = 0; p < deck.pressure_probes.size(); ++p) {
    const auto& probe = deck.pressure_probes[p];
    for (const auto& [end, point] : {std::pair{"lower", probe.lower}, std::pair{"upper", probe.upper}}) {
      const std::string key = fmt::format("pressure_probe[{}].{}", p, end);
      const auto cell = cell_holding(domain.grid, point);
      if (!cell) {
        problems.push_back({key, "the point " + point_text(point) + " is outside the domain"});
      } else if (probe.average == "cell" &&
                 domain.flags.kind[static_cast<std::size_t>(domain.grid.natural(*cell))] !=
                     grid::CellKind::fluid) {
        problems.push_back({key, "the point " + point_text(point) +
                                     " lies in a blocked cell: give one in a fluid cell"});
      } else if (probe.average == "layer" && axis >= 0 &&
                 !layer_has_fluid(domain, axis, (*cell)[static_cast<std::size_t>(axis)])) {
        problems.push_back({key, "the layer of cells across gravity that holds " +
                                     point_text(point) + " has no fluid cell"});
      }
    }
  }
  return problems;
}

std::vector<std::string> pressure_probe_columns(const std::vector<deck::PressureProbe>& probes) {
  std::vector<std::string> columns;
  for (const auto& p : probes) columns.push_back("dp_" + p.name);
  return columns;
}

std::vector<double> pressure_drops(const deck::Deck& deck, const parallel::Domain& domain,
                                   const FlowState& state) {
  const auto& probes = deck.pressure_probes;
  std::vector<double> drops(probes.size(), 0.0);
  if (probes.empty()) return drops;
  const auto& layout = domain.layout;
  const int axis = deck.physics.gravity_axis();
  const bool any_layer =
      std::any_of(probes.begin(), probes.end(), [](const auto& p) { return p.average == "layer"; });
  const LayerMeans layers =
      any_layer ? layer_means(domain, axis, state.gas_pressure) : LayerMeans{};
  // Cell probes: the rank that owns the cell contributes its pressure, the others 0.
  std::vector<grid::Natural> cells;
  for (const auto& p : probes)
    for (const auto& point : {p.lower, p.upper}) {
      const auto cell = cell_holding(domain.grid, point);
      cells.push_back(cell && p.average == "cell" ? domain.grid.natural(*cell) : -1);
    }
  std::vector<double> owned(cells.size(), 0.0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (cells[c] == layout.natural(l)) owned[c] = state.gas_pressure[static_cast<std::size_t>(l)];
  layout.comm().sum_in_place(owned);
  for (std::size_t p = 0; p < probes.size(); ++p) {
    if (probes[p].average == "cell") {
      drops[p] = owned[2 * p] - owned[2 * p + 1];
      continue;
    }
    const auto layer = [&](const std::array<double, 3>& point) {
      return layers.mean[static_cast<std::size_t>((*cell_holding(domain.grid, point))[static_cast<std::size_t>(axis)])];
    };
    drops[p] = layer(probes[p].lower) - layer(probes[p].upper);
  }
  return drops;
}

}  // namespace bagnold::run
