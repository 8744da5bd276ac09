#include "anvil/mesh/QualityGuard.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>

namespace anvil::mesh {

QualityGuard::QualityGuard(const TetMesh& mesh) : tets_of_(tets_around_nodes(mesh)) {}

double QualityGuard::worst_around(const TetMesh& mesh, int node) const {
  double worst = 1.0;
  for (int e : tets_of_[node])
    worst = std::min(worst, quality(mesh, e));
  return worst;
}

bool QualityGuard::move(TetMesh& mesh, int node, const Point& to, double floor) const {
  const double lowest = std::min(worst_around(mesh, node), floor);
  const Point was = mesh.nodes[node];
  mesh.nodes[node] = to;
  if (const double worst = worst_around(mesh, node); worst >= lowest && worst > 0.0) return true;
  mesh.nodes[node] = was;
  return false;
}

} // namespace anvil::mesh
