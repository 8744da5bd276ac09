#include "anvil/remesh/die_feature_depth.h"

#include "anvil/contact/SurfaceSearch.h"

#include <algorithm>

namespace anvil::remesh {

double die_feature_depth(const mesh::TetMesh& body, const std::vector<mesh::Point>& die_vertices) {
  mesh::Point low = body.nodes.front(), high = low;
  for (const mesh::Point& x : body.nodes) low = low.cwiseMin(x), high = high.cwiseMax(x);
  std::vector<mesh::Point> candidates;
  for (const mesh::Point& x : die_vertices)
    if ((x.array() > low.array()).all() && (x.array() < high.array()).all()) candidates.push_back(x);
  if (candidates.empty()) return 0.0;
  const contact::SurfaceSearch surface(body.nodes, body.boundary_faces);
  double deepest = 0.0;
  for (const mesh::Point& x : candidates) {
    const contact::SurfaceSearch::Closest c = surface.closest(x);
    const mesh::Triangle& f = body.boundary_faces[c.face];
    const mesh::Point outward = (body.nodes[f[1]] - body.nodes[f[0]]).cross(body.nodes[f[2]] - body.nodes[f[0]]);
    if ((x - c.point).dot(outward) < 0.0) deepest = std::max(deepest, (x - c.point).norm());
  }
  return deepest;
}

} // namespace anvil::remesh
