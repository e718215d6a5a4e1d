#pragma once
// The discretization of one rank's part of the domain, built once and never changed: cell
// widths, face areas and volumes, what each staggered velocity is (velocity_faces.hpp), and the
// global numberings of the linear systems' unknowns. Every step of the outer iteration reads it;
// none writes it.
//
// Two stencils every step shares (DESIGN.md, "Grid, fields, geometry"):
//   for_each_cell_face   the six faces of a cell as its continuity equation sees them, each with
//                        the cell that owns the face's velocity (the cell itself on its +
//                        faces, the − neighbour on its − faces) and the face area; the
//                        divergence of a face field q is Σ_faces sign · A · q_owner / V;
//   centre_velocity      component d of a staggered velocity at a cell centre, the mean of the
//                        cell's two faces along d, with its convention at walls and openings
//                        (src/parallel/centre_velocity.hpp; the snapshots' cell vectors use it too).

#include <array>
#include <memory>

#include "solver/sparsity_pattern.hpp"
#include "solver/unknown_numbering.hpp"
#include "solver/velocity_faces.hpp"
#include "src/parallel/centre_velocity.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::solver {

enum Phase : int { gas = 0, solids = 1 };

class Discretization {
 public:
  explicit Discretization(const parallel::Domain& domain);  // collective

  const parallel::Domain& domain() const { return m_domain; }
  const parallel::Layout& layout() const { return m_domain.layout; }

  double width(int local, int d) const {
    return m_width[static_cast<std::size_t>(local) * 3 + static_cast<std::size_t>(d)];
  }
  // Area of the cell's face normal to d.
  double face_area(int local, int d) const { return width(local, (d + 1) % 3) * width(local, (d + 2) % 3); }
  double volume(int local) const { return width(local, 0) * width(local, 1) * width(local, 2); }
  // Whether local cell `local` (or -1: none) is a boundary cell of an opening (pressure outflow
  // or inflow, mass inflow; grid::is_opening_cell).
  bool opening(int local) const { return local >= 0 && m_opening[static_cast<std::size_t>(local)] != 0; }
  // For a boundary cell of a pressure outflow or inflow (or -1: none), the local fluid cell
  // beside it (the last in the order −x, +x, −y, +y, −z, +z, as MFIX's SET_OUTFLOW); -1 for
  // any other cell, or when no fluid neighbour is stored on this rank.
  int pressure_opening_fluid(int local) const {
    return local >= 0 ? m_pressure_opening_fluid[static_cast<std::size_t>(local)] : -1;
  }

  // The gas's or the solids' velocity faces (they differ only in what a mass inflow brings).
  const VelocityFaces& faces(Phase phase) const { return *m_faces[static_cast<std::size_t>(phase)]; }
  // Unknown face velocities along d (the same for both phases), and fluid cells.
  const UnknownNumbering& velocity_numbering(int d) const { return *m_velocity_numbering[static_cast<std::size_t>(d)]; }
  const UnknownNumbering& cell_numbering() const { return *m_cell_numbering; }

  // The nonzero patterns of the linear systems: a velocity component's momentum rows (its
  // unknown neighbours and itself), and a cell-centred correction's rows (its fluid neighbours
  // across unknown faces of `phase`, and itself).
  SparsityPattern momentum_pattern(int d) const;
  SparsityPattern cell_pattern(Phase phase) const;

  // Σ over all ranks' fluid cells of ½ Σ_faces A [m²]: the area a velocity scale is carried
  // through when a continuity residual is normalized.
  double reference_area() const { return m_reference_area; }
  // The smallest width of this rank's owned fluid cells [m].
  double smallest_width() const { return m_smallest_width; }

 private:
  const parallel::Domain& m_domain;
  std::vector<char> m_opening;  // per local cell: an opening's boundary cell
  std::vector<int> m_pressure_opening_fluid;  // per local cell: pressure_opening_fluid
  std::vector<double> m_width;  // 3 per local cell
  std::array<std::unique_ptr<VelocityFaces>, 2> m_faces;
  std::array<std::unique_ptr<UnknownNumbering>, 3> m_velocity_numbering;
  std::unique_ptr<UnknownNumbering> m_cell_numbering;
  double m_reference_area = 0.0;
  double m_smallest_width = 0.0;
};

// One face of a cell as its continuity equation sees it.
struct CellFace {
  int face;       // parallel::Face
  int direction;  // d
  int sign;       // +1 on the + face, −1 on the − face
  int neighbour;  // local index across it (-1: not stored)
  int owner;      // the cell whose velocity component d sits on this face
  double area;    // [m²]
  // The value on this face of a staggered field (one vector per direction, indexed by owner).
  template <class Field>
  auto of(const Field& face_field) const {
    return face_field[static_cast<std::size_t>(direction)][static_cast<std::size_t>(owner)];
  }
};

// Calls visit(const CellFace&) for each face of local cell l whose velocity is stored.
template <class Visit>
void for_each_cell_face(const Discretization& discretization, int l, Visit&& visit) {
  const auto& layout = discretization.layout();
  for (int face = 0; face < 6; ++face) {
    const int d = parallel::face_direction(face);
    const int s = parallel::face_sign(face);
    const int m = layout.neighbour(l, face);
    const int owner = s > 0 ? l : m;
    if (owner < 0) continue;
    visit(CellFace{face, d, s, m, owner, discretization.face_area(l, d)});
  }
}

// ∇·u = Σ_faces sign · A · u_owner / V of a staggered velocity field, for the owned fluid cells
// (the halo exchanged); 0 in every other cell. `divergence` has one value per local cell.
void velocity_divergence(const Discretization& discretization,
                         const std::array<std::vector<double>, 3>& velocity,
                         std::vector<double>& divergence);

// Component d of a staggered velocity field at the centre of local cell l (convention above).
using parallel::centre_velocity;

}  // namespace bagnold::solver
