#include "anvil/remesh/die_feature_depth.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/core/processes.h"
#include "anvil/remesh/field_transfer.h"

#include <algorithm>

namespace anvil::remesh {

std::vector<SunkVertex> sunk_die_vertices(const mesh::TetMesh& mesh, const mesh::MeshRange& body,
                                          const std::vector<std::vector<mesh::Point>>& die_vertices) {
  mesh::Point low = mesh.nodes[body.first_node], high = low;
  for (int i = body.first_node; i < body.first_node + body.node_count; ++i)
    low = low.cwiseMin(mesh.nodes[i]), high = high.cwiseMax(mesh.nodes[i]);
  // The vertices in the body's box, then those in one of its tets. The side
  // of the closest surface facet is no inside test: next to an edge of the
  // body the closest point is on two facets, and the wrong one says inside.
  std::vector<mesh::Point> candidates;
  std::vector<int> die_of;
  for (std::size_t d = 0; d < die_vertices.size(); ++d)
    for (const mesh::Point& x : die_vertices[d])
      if ((x.array() > low.array()).all() && (x.array() < high.array()).all())
        candidates.push_back(x), die_of.push_back(static_cast<int>(d));
  std::vector<SunkVertex> sunk;
  if (candidates.empty()) return sunk;
  const PointLocator in_mesh(mesh);
  const std::vector<mesh::Triangle> faces(mesh.boundary_faces.begin() + body.first_face,
                                          mesh.boundary_faces.begin() + body.first_face + body.face_count);
  const contact::SurfaceSearch surface(mesh.nodes, faces);
  // Each candidate's depth below the body's surface, -1 outside the body.
  const std::vector<double> depth =
      processes::share_out(static_cast<int>(candidates.size()), 1, [&](int k, double* below) {
        const std::optional<Location> at = in_mesh.containing(candidates[k]);
        const bool inside = at && at->tet >= body.first_tet && at->tet < body.first_tet + body.tet_count;
        *below = inside ? (candidates[k] - surface.closest(candidates[k]).point).norm() : -1.0;
      });
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (depth[k] >= 0.0) sunk.push_back({die_of[k], {depth[k], candidates[k]}});
  return sunk;
}

std::vector<DieFeature> deepest_per_die(const std::vector<SunkVertex>& sunk, std::size_t dies) {
  std::vector<DieFeature> deepest(dies);
  for (const SunkVertex& v : sunk)
    if (v.feature.depth > deepest[v.die].depth) deepest[v.die] = v.feature;
  return deepest;
}

std::vector<DieFeature> die_feature_depths(const mesh::TetMesh& mesh, const mesh::MeshRange& body,
                                           const std::vector<std::vector<mesh::Point>>& die_vertices) {
  return deepest_per_die(sunk_die_vertices(mesh, body, die_vertices), die_vertices.size());
}

std::vector<std::vector<mesh::Point>> dies_in_place(const scene::Scene& scene, const scene::RunState& state) {
  std::vector<std::vector<mesh::Point>> vertices;
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    vertices.push_back(scene.dies[d].surface->triangles().vertices);
    for (mesh::Point& x : vertices.back())
      x += state.dies[d].displacement;
  }
  return vertices;
}

} // namespace anvil::remesh
