// Bisecting edges of a tetrahedral mesh: every tet and boundary face on an
// edge is cut in two at its midpoint. The geometry does not change (the
// midpoint of a boundary edge lies on the boundary's faces), so a P1 field
// takes the mean of the edge's ends there and an element field its
// parent's value, exactly.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <array>
#include <utility>
#include <vector>

namespace anvil::mesh {

/// What bisect_edges made: where each new node and tet came from.
struct Bisection {
  std::vector<std::array<int, 2>> midpoint_of; ///< per node added (numbered after the mesh's): the edge's ends
  std::vector<int> parent;                     ///< per tet of the result: the tet of the input it is part of
};

/// Bisects the edges `edges` (node pairs) of `mesh` in turn, in place: a
/// midpoint node added per edge, each tet on it replaced by its two halves
/// (the first half in its place, the second appended), boundary faces alike
/// with their tags. An edge that is not one of `mesh` is skipped.
Bisection bisect_edges(TetMesh& mesh, const std::vector<std::array<int, 2>>& edges);

/// An element field (or flag) of the mesh before `cut`, onto the tets after
/// it: each half takes its parent's value.
template <class T> void carry_to_halves(const Bisection& cut, std::vector<T>& values) {
  std::vector<T> halves(cut.parent.size());
  for (std::size_t e = 0; e < cut.parent.size(); ++e)
    halves[e] = values[cut.parent[e]];
  values = std::move(halves);
}

} // namespace anvil::mesh
