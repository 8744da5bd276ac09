#include "anvil/mesh/QualityGuard.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>

namespace anvil::mesh {

QualityGuard::QualityGuard(TetMesh& mesh) : mesh_(mesh), tets_of_(tets_around_nodes(mesh)) {}

double QualityGuard::worst_around(int node) const {
  double worst = 1.0;
  for (int e : tets_of_[node]) worst = std::min(worst, quality(mesh_, e));
  return worst;
}

bool QualityGuard::move(int node, const Point& to, double floor) {
  const double lowest = std::min(worst_around(node), floor);
  const Point was = mesh_.nodes[node];
  mesh_.nodes[node] = to;
  if (worst_around(node) >= lowest) return true;
  mesh_.nodes[node] = was;
  return false;
}

} // namespace anvil::mesh
