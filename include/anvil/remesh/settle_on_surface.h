// Putting the new boundary nodes of a remeshed body back onto the surface
// of the body it replaces, and the volume its curved patches lose to chords
// back onto them.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::remesh {

/// Puts the boundary nodes of `out` that `movable` flags (CGAL's new or
/// moved ones) back onto the surface of `body` (patches `patch`, tags
/// `tag_of_patch`) and gives `out` the volume `volume` on its curved patches.
/// CGAL smooths the vertices of a curved patch in its tangent plane, which
/// lets them sink below the old surface (0.34 % of a quarter cylinder's
/// volume at h = R/10); what is left after the move is the chord error of
/// the new facets. Not where that would leave an element below
/// `quality_floor` (in a die fillet's groove this move can flatten an
/// element): the volume restoration makes up what such a node leaves.
void settle_on_old_surface(mesh::TetMesh& out, const mesh::TetMesh& body, const std::vector<int>& patch,
                           const std::vector<int>& tag_of_patch, const std::vector<char>& movable, double volume,
                           double quality_floor);

} // namespace anvil::remesh
