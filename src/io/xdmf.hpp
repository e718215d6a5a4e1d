#pragma once
// The XDMF index of a run (run.xmf): a temporal collection of the snapshots, so ParaView opens
// the whole run at once. Rewritten (atomically) after every snapshot by rank 0.

#include <string>
#include <vector>

#include "src/grid/structured_grid.hpp"
#include "src/io/snapshot.hpp"

namespace bagnold::io {

struct IndexedSnapshot {
  std::string file;  // relative to the index's directory
  double time = 0.0;
  std::vector<std::string> absent_fields;  // of the run's fields, those this file lacks (older)
};

// XDMF text for the snapshots; fields are cell-centred attributes on a 3-D rectilinear mesh
// (face fields are shown on their owning cell; the HDF5 attribute `centering` says which face).
// A snapshot's absent_fields are left out of its entry.
std::string xdmf_text(const grid::StructuredGrid& grid, const std::vector<IndexedSnapshot>& snapshots,
                      const std::vector<std::string>& field_names);

// Writes `text` to `path` through a temporary file and a rename.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace bagnold::io
