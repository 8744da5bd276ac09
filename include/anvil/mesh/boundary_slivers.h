// Flat tets on a body's surface. A remesher that keeps the surface's
// feature lines (patch borders) cannot flip or collapse the edges of a tet
// whose four nodes lie on them: where a die edge has pressed a crease into
// the surface, CGAL leaves such tets at quality 0.001, and every remesh
// after makes them again (cases/conrod.yaml).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::mesh {

/// Removes the tets of `mesh` below quality `below` that have two or three
/// faces on the boundary, where the surface stays a manifold: with two, the
/// edge their other faces share must not be on the boundary already; with
/// three, the node they share must be in no other tet (it goes with the
/// tet). A tet of the second kind (an ear) below `ears_below` goes too
/// where it covers a tet below `below`: that tet may be held by the ear
/// alone (on the connecting rod, a flat tet on a strip of the symmetry
/// plane a fiftieth of a millimetre wide, which every CGAL try kept). Each
/// tet removed takes its volume off the body (a flat tet's is about
/// quality × edge³) and turns its other faces into boundary faces, tagged
/// as the removed face that faces most the same way. Repeated while the
/// tets it uncovers qualify. Returns how many tets it removed; the
/// boundary is rebuilt when any. The first `frozen` tets stay, first and
/// in their order (a local remesh's kept tets); `old_node`, when given,
/// gets per node left its number before (an ear's node goes with it).
int peel_boundary_slivers(TetMesh& mesh, double below, double ears_below, int frozen = 0,
                          std::vector<int>* old_node = nullptr);

} // namespace anvil::mesh
