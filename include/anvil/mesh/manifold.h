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

} // namespace anvil::mesh
