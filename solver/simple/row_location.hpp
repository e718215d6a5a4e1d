#pragma once
// Where a row of an equation lies, in words a user can act on: a fluid cell, and for a momentum
// row the face of that cell that carries the velocity and the boundary region beyond it.

#include <cstdint>

#include "solver/simple/step_record.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::solver {

// The row of `equation` owned by the cell of natural index `owner`; `plus` is the natural index
// of the owner's + neighbour along the momentum row's direction (-1: none; unused for the
// continuity equations). A momentum row's face may be owned by a boundary cell (an opening's
// face belongs to the cell beyond it): the location is then the fluid cell on the other side,
// with its − face.
CellLocation locate_row(const parallel::Domain& domain, int equation, std::int64_t owner,
                        std::int64_t plus);

}  // namespace bagnold::solver
