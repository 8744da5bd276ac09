// Giving a mesh back a volume it lost at its surface (the chords of a
// remeshed curved patch cut into it).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::mesh {

/// Moves the nodes flagged `movable` (boundary nodes) along their outward
/// normal, the sum of their boundary faces' area vectors, by the one distance
/// that gives `mesh` the volume `target` (mm³): to first order
/// dV = δ Σ |A_i| / 3; a second pass removes the second-order rest. The
/// nodes of a tet the move would invert stay where they are, and the rest
/// move further. Returns the distance (mm; 0 when no node may move).
double restore_volume(TetMesh& mesh, double target, const std::vector<char>& movable);

} // namespace anvil::mesh
