#include "anvil/mesh/restore_volume.h"

namespace anvil::mesh {

double restore_volume(TetMesh& mesh, double target, const std::vector<char>& movable) {
  std::vector<Point> normal(mesh.nodes.size(),
                            Point::Zero()); // Σ face area vectors / 3: the node's share of the surface
  for (const Triangle& face : mesh.boundary_faces) {
    const Point third = area_vector(mesh, face) / 3.0;
    for (int v : face)
      normal[v] += third;
  }
  double area = 0.0;
  for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
    if (movable[v]) area += normal[v].norm();
  if (area <= 0.0) return 0.0;
  double distance = 0.0;
  for (int pass = 0; pass < 2; ++pass) { // the second pass removes the second-order rest
    const double shift = (target - volume(mesh)) / area;
    for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
      if (movable[v]) mesh.nodes[v] += shift * normal[v].normalized();
    distance += shift;
  }
  return distance;
}

} // namespace anvil::mesh
