// Geometry of one linear tetrahedron: volume, shape-function gradients, quality.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace anvil::mesh {

/// Signed volume: det[x1-x0, x2-x0, x3-x0] / 6 (> 0 for positive orientation).
double signed_volume(const Point& x0, const Point& x1, const Point& x2, const Point& x3);

inline double signed_volume(const TetMesh& mesh, int tet) {
  const Tet& t = mesh.tets[tet];
  return signed_volume(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
}

inline Point centroid(const TetMesh& mesh, int tet) {
  const Tet& t = mesh.tets[tet];
  return 0.25 * (mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]] + mesh.nodes[t[3]]);
}

/// The smallest axis-aligned box holding the tet.
inline Eigen::AlignedBox3d bounding_box(const TetMesh& mesh, int tet) {
  Eigen::AlignedBox3d out(mesh.nodes[mesh.tets[tet][0]]);
  for (int k = 1; k < 4; ++k)
    out.extend(mesh.nodes[mesh.tets[tet][k]]);
  return out;
}

/// Volume-edge ratio 6√2 V / l_rms³: 1 for the regular tet, → 0 when flat,
/// negative when inverted. Scale invariant. This is the quality measure Anvil reports.
double quality(const Point& x0, const Point& x1, const Point& x2, const Point& x3);

inline double quality(const TetMesh& mesh, int tet) {
  const Tet& t = mesh.tets[tet];
  return quality(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
}

/// Gradients of the barycentric (P1) shape functions as rows of a 4×3 matrix
/// (1/mm), and the volume. Requires a non-degenerate tet.
struct P1Gradients {
  Eigen::Matrix<double, 4, 3> grad;
  double volume;
};
P1Gradients p1_gradients(const Point& x0, const Point& x1, const Point& x2, const Point& x3);

} // namespace anvil::mesh
