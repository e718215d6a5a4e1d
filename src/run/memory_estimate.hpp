#pragma once
// The memory a run of a deck's grid needs, estimated before anything is allocated, against the
// memory of the machine: a grid too large for it is refused with the grid's line instead of
// ending in std::bad_alloc (or the kernel's OOM killer) while the geometry is built.
//
// The estimate per rank is a fit to the measured peak resident memory of two-fluid runs
// (docs/reliability.md, "Memory estimate"):
//   bytes = base + per_box_cell × (nx + 2)(ny + 2)(nz + 2) + per_cell × nx ny nz / ranks,
// (no + 2 in a periodic direction), base for the libraries (MPI, PETSc, hypre, HDF5),
// per_box_cell for what every rank holds of the whole box (cell flags, owners, the partition),
// per_cell for the fields, the matrices and the solvers' work space of the cells a rank owns. Blocked cells count as stored: the estimate
// is an upper bound for a geometry that blocks much of its box. Ranks on one node add up.

#include <string>

#include "src/deck/deck.hpp"
#include "src/parallel/communicator.hpp"
#include "src/util/machine_memory.hpp"

namespace bagnold::run {

struct MemoryFit {
  double base;          // [B per rank]
  double per_box_cell;  // [B per cell of the extended box, per rank]
  double per_cell;      // [B per cell of the domain, divided among the ranks]
};
// The measured figures (docs/reliability.md).
MemoryFit measured_memory_fit();

struct MemoryEstimate {
  double rank_bytes = 0.0;  // this rank
  double node_bytes = 0.0;  // the ranks of this rank's node together
  MachineMemory node;       // this rank's node
  int ranks = 1;
  // The node whose estimate is the largest share of its physical memory (the same on all ranks).
  double worst_node_bytes = 0.0;
  double worst_node_physical = 0.0;
  double worst_node_available = 0.0;
  bool fits() const { return worst_node_bytes <= worst_node_physical; }
};

// Collective.
MemoryEstimate estimate_memory(const deck::Grid& grid, const parallel::Communicator& comm);

// "about 1.2 GB on 2 ranks (0.6 GB per rank); this machine has 24 GB (22 GB available)".
std::string memory_text(const MemoryEstimate& estimate);

}  // namespace bagnold::run
