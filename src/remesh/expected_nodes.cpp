#include "anvil/remesh/expected_nodes.h"

#include "anvil/mesh/node_budget.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/size_levels.h"

#include <cmath>

namespace anvil::remesh {

ExpectedNodes expected_nodes(const mesh::TetMesh& body, const std::function<double(const mesh::Point&)>& size,
                             double edge_length, double smallest) {
  ExpectedNodes nodes;
  for (int e = 0; e < body.tet_count(); ++e)
    nodes.bulk +=
        mesh::kRemeshedNodesPerVolume * mesh::signed_volume(body, e) / std::pow(size(mesh::centroid(body, e)), 3);
  for (const mesh::Triangle& f : body.boundary_faces) {
    const mesh::Point centroid = (body.nodes[f[0]] + body.nodes[f[1]] + body.nodes[f[2]]) / 3.0;
    nodes.surface += mesh::kRemeshedNodesPerArea * mesh::area_vector(body, f).norm() / std::pow(size(centroid), 2);
  }
  for (const LevelBorder& level : level_borders(body, size, edge_length, smallest))
    nodes.surface += mesh::level_border_nodes(level.area, level.coarser, level.length / level.coarser);
  return nodes;
}

} // namespace anvil::remesh
