#pragma once
// The cells one rank stores: its owned cells, then a halo two cells deep (every stored cell
// within two cells, across faces, edges or corners, of an owned cell). Local numbering:
//   [0, owned_fluid_count)            owned fluid cells, ascending natural index
//   [owned_fluid_count, owned_count)  owned boundary cells
//   [owned_count, local_count)        halo cells, grouped by owner rank
// Owned fluid cells are numbered contiguously across ranks (rank 0 first): that global fluid
// index is the row of a cell-centred unknown in PETSc's numbering.

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "src/grid/cell_flags.hpp"
#include "src/grid/structured_grid.hpp"
#include "src/parallel/communicator.hpp"

namespace bagnold::parallel {

// Faces of a cell, in this order everywhere: west, east, south, north, bottom, top.
enum Face : int { west = 0, east = 1, south = 2, north = 3, bottom = 4, top = 5 };
inline constexpr int face_direction(int face) { return face / 2; }
inline constexpr int face_sign(int face) { return face % 2 == 0 ? -1 : 1; }

struct HaloPlan {
  struct Peer {
    int rank = 0;
    std::vector<int> send;  // owned local indices this peer holds in its halo
    int receive_begin = 0;  // halo cells owned by the peer: [receive_begin, receive_end)
    int receive_end = 0;
  };
  std::vector<Peer> peers;
};

class Layout {
 public:
  Layout(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
         const std::vector<int>& owner, const Communicator& comm);

  int owned_fluid_count() const { return m_owned_fluid; }
  int owned_count() const { return m_owned; }
  int local_count() const { return static_cast<int>(m_natural.size()); }
  bool is_owned(int local) const { return local < m_owned; }

  grid::Natural natural(int local) const { return m_natural[static_cast<std::size_t>(local)]; }
  grid::Index3 index3(int local) const { return m_grid->index3(natural(local)); }
  grid::CellKind kind(int local) const { return m_kind[static_cast<std::size_t>(local)]; }
  int region(int local) const { return m_region[static_cast<std::size_t>(local)]; }
  // Local index of the face neighbour, or -1 when it is not stored on this rank.
  int neighbour(int local, int face) const {
    return m_neighbours[static_cast<std::size_t>(local) * 6 + static_cast<std::size_t>(face)];
  }
  // Local index of the stored cell with this natural index, or -1.
  int find(grid::Natural n) const;

  std::int64_t global_fluid_index(int local) const {
    return m_global_fluid[static_cast<std::size_t>(local)];
  }
  std::int64_t global_fluid_offset() const { return m_fluid_offset; }
  std::int64_t global_fluid_count() const { return m_fluid_total; }

  const HaloPlan& halo() const { return m_halo; }
  const grid::StructuredGrid& grid() const { return *m_grid; }
  const Communicator& comm() const { return m_comm; }

 private:
  void build_halo_plan(const std::vector<int>& owner);

  const grid::StructuredGrid* m_grid;
  Communicator m_comm;
  int m_owned_fluid = 0;
  int m_owned = 0;
  std::vector<grid::Natural> m_natural;
  std::vector<grid::CellKind> m_kind;
  std::vector<std::int16_t> m_region;
  std::vector<int> m_neighbours;
  std::vector<std::int64_t> m_global_fluid;
  std::int64_t m_fluid_offset = 0;
  std::int64_t m_fluid_total = 0;
  std::unordered_map<grid::Natural, int> m_local_of;
  HaloPlan m_halo;
};

// MPI datatype of the values a field may hold.
template <class T>
MPI_Datatype mpi_type();
template <> inline MPI_Datatype mpi_type<double>() { return MPI_DOUBLE; }
template <> inline MPI_Datatype mpi_type<float>() { return MPI_FLOAT; }
template <> inline MPI_Datatype mpi_type<int>() { return MPI_INT; }
template <> inline MPI_Datatype mpi_type<std::int64_t>() { return MPI_INT64_T; }
template <> inline MPI_Datatype mpi_type<std::uint8_t>() { return MPI_UINT8_T; }

// Copies owned values into the other ranks' halos. Works for every field, scalar or staggered,
// since all are indexed by their owning cell; `values` has local_count() entries.
template <class T>
void exchange_halo(const Layout& layout, std::span<T> values);

}  // namespace bagnold::parallel
