// Whether a tet mesh is a manifold with boundary. CGAL's remesher builds its
// triangulation from the tets and closes the boundary with one outside
// vertex: that fails where the boundary is pinched (two parts of the body
// touching at a node or an edge), and a remesh whose result is pinched
// would leave the body a mesh no later remesh can take.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <string>

namespace anvil::mesh {

/// What keeps the tets of `mesh` from being a manifold with boundary,
/// naming the first offence (1-based node numbers): a face in more than
/// two tets, a boundary edge on other than two boundary faces, or a node
/// whose boundary faces form more than one fan. The boundary is taken from
/// the tets (faces used once), not from mesh.boundary_faces. Empty when
/// none.
std::string manifold_fault(const TetMesh& mesh);

/// Whether the tets of `mesh` fill a ball: a manifold (manifold_fault)
/// whose boundary is one sphere. CGAL's remesher builds its triangulation
/// from tets only when they do.
bool is_ball(const TetMesh& mesh);

/// Cuts the pinches of `mesh` where a remesher left two parts of the body
/// touching (CGAL across a flash thinner than its elements): around a
/// boundary edge on four or more boundary faces, or a node whose boundary
/// faces form more than one fan, the tets there fall into groups joined
/// through faces at the edge or node; all but the group of largest volume
/// are removed (a few tets at a thin fin's edge), with the nodes no tet
/// uses then. The faces they uncover are tagged as the removed boundary
/// face facing most the same way whose tag fits them (a flat tag only on its
/// plane), else 0. Repeated while it cuts; a face in three tets is left.
/// Returns how many tets it removed.
int cut_pinches(TetMesh& mesh);

} // namespace anvil::mesh
