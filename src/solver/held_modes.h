// Private to src/solver: the near-null space the velocity AMG aggregates
// with, the rigid-body modes less the directions a penalty holds at each
// node (anvil/solver/held_directions.h), read from the assembled system.
#pragma once
#include <petscmat.h>

namespace anvil::solver::petsc {

/// The first `count` rigid-body modes (3: the translations; 6: and the
/// rotations) of the nodes at `coordinates` (this process's, three entries a
/// node, in the order of the velocity rows `system` gives this process: four
/// rows a node, velocity then pressure), less the directions held at each
/// node, orthonormal as PETSc asks. The caller destroys it.
MatNullSpace held_rigid_body_modes(Mat system, Vec coordinates, int count);

} // namespace anvil::solver::petsc
