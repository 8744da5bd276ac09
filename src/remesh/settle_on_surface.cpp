#include "anvil/remesh/settle_on_surface.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/core/error.h"
#include "anvil/mesh/QualityGuard.h"
#include "anvil/mesh/flat_tags.h"
#include "anvil/mesh/restore_volume.h"
#include "anvil/mesh/tet_geometry.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace anvil::remesh {
namespace {

/// Tags whose faces are not all in one plane somewhere in `body`: a patch
/// that is curved (the barrel of an upset billet), where new facets are
/// chords of the old surface.
std::set<int> curved_tags(const mesh::TetMesh& body, const std::vector<int>& patch,
                          const std::vector<int>& tag_of_patch) {
  std::vector<mesh::Point> first_normal(tag_of_patch.size(), mesh::Point::Zero());
  std::set<int> curved;
  for (std::size_t f = 0; f < body.boundary_faces.size(); ++f) {
    const mesh::Point n = mesh::area_vector(body, body.boundary_faces[f]).normalized();
    mesh::Point& first = first_normal[patch[f]];
    if (first.isZero())
      first = n;
    else if (first.dot(n) < 1.0 - 1e-9)
      curved.insert(tag_of_patch[patch[f]]);
  }
  return curved;
}

/// The nodes inside curved patches (every face around them on one): where
/// the chords of a re-triangulated curved surface cut the old surface by
/// about h²/8R, a volume loss that must not accumulate over remeshes.
std::vector<char> inside_curved_patches(const mesh::TetMesh& mesh, const std::set<int>& curved) {
  std::vector<char> movable(mesh.nodes.size(), 0), fixed(mesh.nodes.size(), 0);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    for (int v : mesh.boundary_faces[f])
      (curved.count(mesh.boundary_tags[f]) > 0 ? movable : fixed)[v] = 1;
  for (std::size_t v = 0; v < movable.size(); ++v)
    movable[v] = movable[v] && !fixed[v];
  return movable;
}

} // namespace

void settle_on_old_surface(mesh::TetMesh& out, const mesh::TetMesh& body, const std::vector<int>& patch,
                           const std::vector<int>& tag_of_patch, const std::vector<char>& movable, double volume,
                           double quality_floor) {
  const contact::SurfaceSearch old_surface(body.nodes, body.boundary_faces);
  std::vector<char> on_boundary = mesh::boundary_node_flags(out);
  for (std::size_t n = 0; n < on_boundary.size(); ++n)
    on_boundary[n] = on_boundary[n] && movable[n];
  mesh::QualityGuard guard(out);
  for (std::size_t n = 0; n < out.nodes.size(); ++n)
    if (on_boundary[n]) guard.move(out, int(n), old_surface.closest(out.nodes[n]).point, quality_floor);
  // A node on the border of a flat patch may land on the curved face next
  // to it (off a symmetry plane by a fraction of a µm, enough to make the
  // plane's faces no longer coplanar): flat patches keep their nodes.
  const auto planes = mesh::flat_tags(body);
  for (std::size_t f = 0; f < out.boundary_faces.size(); ++f) {
    const auto plane = planes.find(out.boundary_tags[f]);
    if (plane == planes.end()) continue;
    const auto& [normal, offset] = plane->second;
    for (int v : out.boundary_faces[f])
      if (movable[v]) out.nodes[v] -= (normal.dot(out.nodes[v]) - offset) * normal;
  }
  // A region's remesh can put a facet of a flat patch onto a kept node off
  // its plane (a node 0.18 mm inside the connecting rod's symmetry plane):
  // the tag would no longer be flat, and the next remesh would move the
  // whole plane as a curved patch. Such a result is refused. Checked after
  // every snap: a node on two flat patches that meet at a slant is moved by
  // both.
  for (std::size_t f = 0; f < out.boundary_faces.size(); ++f) {
    const auto plane = planes.find(out.boundary_tags[f]);
    if (plane == planes.end() || mesh::in_plane(out, out.boundary_faces[f], plane->second)) continue;
    const auto& [normal, offset] = plane->second;
    double off = 0.0;
    for (int v : out.boundary_faces[f])
      off = std::max(off, std::abs(normal.dot(out.nodes[v]) - offset));
    char text[160];
    std::snprintf(text, sizeof text, "a face of the flat boundary patch with tag %d lies %.3g mm off its plane",
                  plane->first, off);
    throw RunError(text);
  }
  std::vector<char> restorable = inside_curved_patches(out, curved_tags(body, patch, tag_of_patch));
  for (std::size_t n = 0; n < restorable.size(); ++n)
    restorable[n] = restorable[n] && movable[n];
  mesh::restore_volume(out, volume, restorable);
}

} // namespace anvil::remesh
