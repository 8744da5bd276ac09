#include "anvil/remesh/quality.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>

namespace anvil::remesh {

QualityReport assess_quality(const mesh::TetMesh& mesh, const mesh::MeshRange& range, const Eigen::VectorXd& nodal,
                             double time_step, double threshold) {
  QualityReport r;
  auto moved = [&](int node) -> mesh::Point { return mesh.nodes[node] + time_step * nodal.segment<3>(4 * node); };
  for (int e = range.first_tet; e < range.first_tet + range.tet_count; ++e) {
    const mesh::Tet& t = mesh.tets[e];
    const double q = mesh::quality(mesh, e);
    if (q < threshold) ++r.below;
    if (q < r.worst) r.worst = q, r.worst_tet = e - range.first_tet, r.worst_at = mesh::centroid(mesh, e);
    const double next = mesh::quality(moved(t[0]), moved(t[1]), moved(t[2]), moved(t[3]));
    if (next < r.predicted_worst) r.predicted_worst = next, r.predicted_tet = e - range.first_tet;
  }
  return r;
}

double worst_quality(const mesh::TetMesh& m) {
  double worst = 1.0;
  for (int e = 0; e < m.tet_count(); ++e)
    worst = std::min(worst, mesh::quality(m, e));
  return worst;
}

} // namespace anvil::remesh
