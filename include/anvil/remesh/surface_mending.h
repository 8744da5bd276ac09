// Surface mending (docs/remeshing.md §3): a poor element held by the body's
// surface (a skinny surface triangle, or a flat element with two faces on
// the surface) is mended by flipping a surface edge, or by collapsing a
// short one, where the surface is flat: every other node stays where it
// is, so the contact surface keeps its nodes, and only the elements around
// the edge change.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::remesh {

/// The surface is mended where its triangles' normals differ by at most
/// this (degrees): the surface's change is then a sliver of volume.
constexpr double kFlatSurface = 20.0;

/// What mend_surface did.
struct SurfaceMending {
  int flips = 0;              ///< surface edges flipped
  int collapses = 0;          ///< short surface edges collapsed (one node gone each)
  std::vector<char> changed;  ///< a tet of the new mesh: made or reshaped by the mending
  std::vector<int> old_node;  ///< a node of the new mesh: its number before (the collapsed nodes are gone)
  double volume_change = 0.0; ///< mm³, of the body
  double worst_before = 1.0;  ///< worst quality of the elements the mending replaced
  double worst_after = 1.0;   ///< and of those it made
};

/// Mends, in `body`, the elements below `threshold` quality that have a
/// face on the surface, with the best of:
/// - a flip of a surface edge ab between triangles abc and abd to cd: the
///   elements around ab (its shell) are replaced by those joining a and b
///   to a triangulation of the shell's ring (one shell element: it is
///   taken off);
/// - a collapse of a surface edge uv onto v: u's elements take v instead,
///   those holding both go (valid only when the edge's link condition holds).
/// Only where the surface triangles involved have one boundary tag and
/// normals within `most_angle` (degrees) of each other, and only when every
/// new element is better than the worst it replaces. The new elements take
/// each of `element_fields` (one value a tet) by Anvil's transfer from
/// those they replace (conservative, peaks kept). body.boundary_faces and
/// tags are kept up to date; nodes are renumbered when one goes (old_node).
SurfaceMending mend_surface(mesh::TetMesh& body, const std::vector<std::vector<double>*>& element_fields,
                            double threshold, double most_angle);

} // namespace anvil::remesh
