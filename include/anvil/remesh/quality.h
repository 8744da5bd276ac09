// Mesh quality watch: the measure is the volume-edge ratio
// q = 6√2 V / l_rms³ of mesh::quality (1 for the regular tet, 0 flat,
// negative inverted), on the current mesh and on the mesh the next increment
// would give if the nodes kept their velocity.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>

namespace anvil::remesh {

struct QualityReport {
  double worst = 1.0;                         ///< smallest q now
  int worst_tet = -1;                         ///< its index in the body (0-based)
  mesh::Point worst_at = mesh::Point::Zero(); ///< its centroid (mm)
  int below = 0;                              ///< elements with q under the threshold
  double predicted_worst = 1.0;               ///< smallest q after x += Δt v (≤ 0: an inversion is coming)
  int predicted_tet = -1;
};

/// Quality of the tets of `range` in `mesh`, now and after `time_step` (s)
/// at the nodal velocities of `nodal` (4 values per node: v, p).
QualityReport assess_quality(const mesh::TetMesh& mesh, const mesh::MeshRange& range, const Eigen::VectorXd& nodal,
                             double time_step, double threshold);

/// Smallest quality over all tets of `m`.
double worst_quality(const mesh::TetMesh& m);

} // namespace anvil::remesh
