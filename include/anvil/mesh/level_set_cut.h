// A tet mesh cut by a level set (a trim: docs/chains.md): the part where
// φ ≤ 0, its elements split where the cut crosses them so that the cut face
// lies on the cut, without moving a node. Each element the cut crosses is
// split into a tet, a pyramid (two tets) or a prism (three tets: Dompierre
// et al. 1999, "How to subdivide pyramids, prisms and hexahedra into
// tetrahedra"); a quadrilateral face is split along the diagonal through its
// vertex of smallest number, so that the two elements sharing it split it
// alike and the result is conforming.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <functional>
#include <span>
#include <vector>

namespace anvil::mesh {

/// A node of the cut mesh: x = (1 − t) x_a + t x_b of the input's nodes a
/// and b (b = a and t = 0 for a node of the input).
struct NodeOrigin {
  int a = 0, b = 0;
  double t = 0.0;
};

struct LevelSetCut {
  TetMesh mesh;                   ///< with its boundary; the input's tags kept on the pieces of its faces, the cut 0
  std::vector<int> parent;        ///< per tet of `mesh`: the input tet it is part of
  std::vector<NodeOrigin> origin; ///< per node of `mesh`
};

/// The part of `mesh` where φ ≤ 0. `phi` holds φ at the nodes: 0 exactly for
/// a node on the cut, which stays where it is. The cut point of an edge
/// whose ends have φ of opposite signs is found on `level` (φ anywhere, by
/// regula falsi from the linear estimate). An element whose nodes are all
/// on the cut is kept when `level` is negative at its centre. The input
/// nodes that stay come first, in their order, then the new ones.
LevelSetCut cut_by_level_set(const TetMesh& mesh, std::span<const double> phi,
                             const std::function<double(const Point&)>& level);

} // namespace anvil::mesh
