#include "anvil/remesh/die_feature_depth.h"

#include "anvil/contact/SurfaceSearch.h"

#include <algorithm>
#include <memory>

namespace anvil::remesh {

std::vector<double> die_feature_depths(const mesh::TetMesh& mesh, const mesh::MeshRange& body,
                                       const std::vector<std::vector<mesh::Point>>& die_vertices) {
  mesh::Point low = mesh.nodes[body.first_node], high = low;
  for (int i = body.first_node; i < body.first_node + body.node_count; ++i)
    low = low.cwiseMin(mesh.nodes[i]), high = high.cwiseMax(mesh.nodes[i]);
  const std::vector<mesh::Triangle> faces(mesh.boundary_faces.begin() + body.first_face,
                                          mesh.boundary_faces.begin() + body.first_face + body.face_count);
  std::unique_ptr<contact::SurfaceSearch> surface; // built once, when a vertex is in the body's box
  std::vector<double> deepest(die_vertices.size(), 0.0);
  for (std::size_t d = 0; d < die_vertices.size(); ++d)
    for (const mesh::Point& x : die_vertices[d]) {
      if (!(x.array() > low.array()).all() || !(x.array() < high.array()).all()) continue;
      if (!surface) surface = std::make_unique<contact::SurfaceSearch>(mesh.nodes, faces);
      const contact::SurfaceSearch::Closest c = surface->closest(x);
      if ((x - c.point).dot(mesh::area_vector(mesh, faces[c.face])) < 0.0)
        deepest[d] = std::max(deepest[d], (x - c.point).norm());
    }
  return deepest;
}

} // namespace anvil::remesh
