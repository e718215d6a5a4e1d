#pragma once
// The XDMF index of a run (run.xmf): a temporal collection of the snapshots, so ParaView opens
// the whole run at once. Rewritten (atomically) after every snapshot by rank 0.
//
// Each time is a spatial collection of two grids (docs/paraview.md):
//   cells     the 3-D rectilinear mesh of the domain, its cell data the fields (face fields
//             shown on their owning cell; the HDF5 attribute `centering` says which face) and
//             the cell-centred velocity vectors (AttributeType Vector);
//   openings  the faces of the boundary openings as quadrilaterals, their cell data the face
//             velocities (vectors and outward normal components) and the region index; only in
//             a snapshot that has opening faces.

#include <string>
#include <vector>

#include "src/grid/structured_grid.hpp"
#include "src/io/snapshot.hpp"

namespace bagnold::io {

struct IndexedSnapshot {
  std::string file;  // relative to the index's directory
  double time = 0.0;
  std::vector<std::string> absent_fields;  // of the run's fields, those this file lacks (older)
  std::size_t opening_faces = 0;           // faces in its /openings (0: no openings grid)
};

// The names the index shows, by where they are stored.
struct IndexedFields {
  std::vector<std::string> cell_scalars;     // /fields/NAME, (nz, ny, nx)
  std::vector<std::string> cell_vectors;     // /fields/NAME, (nz, ny, nx, 3)
  std::vector<std::string> opening_scalars;  // /openings/NAME, (faces)
  std::vector<std::string> opening_vectors;  // /openings/NAME, (faces, 3)
};

// XDMF text for the snapshots. A snapshot's absent_fields are left out of its entry.
std::string xdmf_text(const grid::StructuredGrid& grid, const std::vector<IndexedSnapshot>& snapshots,
                      const IndexedFields& fields);

// Writes `text` to `path` through a temporary file and a rename.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace bagnold::io
