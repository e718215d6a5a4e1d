#pragma once
// What each staggered velocity is, per direction d and owning cell c (the face between c and its
// + neighbour n along d), decided once from the global cell flags and boundary regions:
//   unknown  c and n fluid (periodic wrap included), or one fluid and the other a pressure
//            inflow/outflow cell: solved by the momentum predictor;
//   fixed    one fluid and the other a wall or mass-inflow cell: the normal velocity is given;
//   none     no fluid on either side.
// And, for each unknown, its six stencil links (DESIGN.md: every field indexed by its owner).

#include <array>
#include <cstdint>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::solver {

enum class FaceClass : std::uint8_t { none, unknown, fixed };

// How the momentum equation of an unknown face velocity sees one of its six neighbours.
enum class LinkKind : std::uint8_t {
  unknown,         // another unknown (local index `local`)
  fixed,           // a given face velocity stored at `local`
  wall,            // a wall or inflow half a cell away, tangential velocity `value`
  zero_gradient,   // free-slip wall, open boundary, or no neighbour: no diffusive flux
};

struct Link {
  int local = -1;
  LinkKind kind = LinkKind::zero_gradient;
  double value = 0.0;
  int region = -1;  // wall: the boundary region across it (its solids wall condition)
};

struct VelocityFaces {
  // The gas's or the solids' faces: they differ only in what a mass inflow brings (its gas or
  // solids velocity); the unknowns are the same.
  VelocityFaces(const parallel::Domain& domain, bool solids_phase);

  std::array<std::vector<FaceClass>, 3> kind;      // per local cell
  std::array<std::vector<double>, 3> fixed_value;  // normal velocity of fixed faces [m/s]
  // links[d][6 * l + face] for unknown faces (face order: parallel::Face).
  std::array<std::vector<Link>, 3> links;
  // Whether a cell holds a pressure boundary (p' = 0 there, pressure given).
  std::vector<std::uint8_t> pressure_boundary;
  std::vector<double> boundary_pressure;  // [Pa] in pressure boundary cells
  bool has_pressure_boundary = false;     // false: the pressure is fixed only up to a constant
};

}  // namespace bagnold::solver
