// Free surface tags: the tags a generated billet's faces start with
// (mesh/generators.h: x-min … z-max, bottom, top, lateral) name nothing
// once those faces have deformed, unless a condition selects them. Kept
// apart they stay patch borders for a whole remesh (boundary_patches),
// which CGAL keeps where they are: the bar's edge, long since drawn smooth
// into the part, stays a line of nodes no remesh moves, and the element a
// die crushes flat against it is made again by every try (the connecting
// rod at 1.0 mm, at the bar's upper side edge by the small boss). The last
// try of a whole remesh (remesh_tries.h) takes them as one free surface,
// and a mesh it made keeps them so; every try taking them so made the hub
// flange's load jumps at whole remeshes larger (docs/remeshing.md).
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/BoundaryCondition.h"

#include <span>

namespace anvil::remesh {

/// Gives tag 0 (untagged) to the boundary faces of `body` whose tag no
/// condition of `conditions` selects by tag and whose faces do not all lie
/// in one plane (mesh::flat_tags: a symmetry plane, an end face the dies
/// have not reached, stays apart, and the remesher keeps its nodes on it).
/// Returns how many faces it changed.
int free_surface_tags(mesh::TetMesh& body, std::span<const scene::BoundaryCondition> conditions);

} // namespace anvil::remesh
