// Flat tets taken out by re-triangulating the ring of tets around one of
// their edges (docs/remeshing.md). A remesher that may not move a tet's
// four nodes leaves it flat where they are coplanar: on the frozen border of
// a rebuilt region, a planar quad split along one diagonal on the kept side
// and along the other on the rebuilt side has a flat tet between the two.
#pragma once
#include "anvil/mesh/TetMesh.h"

namespace anvil::mesh {

/// Takes the tets from `first` on that are below quality `below` out of
/// `mesh`, each through one of its edges whose ring of tets is closed (the
/// edge inside the body) and lies wholly from `first` on, either by
///  - edge removal (Shewchuk 2002): the ring replaced by the best
///    triangulation of the edge's link polygon joined to the edge's ends;
///  - or, where no such triangulation beats the ring, a lifted split: a new
///    node near the edge's midpoint, moved off the flat tet's plane, joined
///    to every face of the ring's surface (the ring of a flat tet whose two
///    faces lie on a plane it may not cross has no other way out);
/// of its edges, the one whose new tets have the best worst quality, taken
/// when that beats the worst of its ring; a lifted split only where no edge
/// removal does. Boundary faces and tets before `first`
/// stay as they are; new tets and new nodes go at the end. Returns how many
/// rings it re-triangulated.
int mend_flat_tets(TetMesh& mesh, int first, double below);

} // namespace anvil::mesh
