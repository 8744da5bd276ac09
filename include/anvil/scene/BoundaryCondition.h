// Boundary conditions: prescribed velocity components, symmetry
// planes, flat sticking or frictionless plates (as velocity conditions; real
// dies come later), tractions and pressures. Faces are chosen by boundary
// tag or by a plane.
#pragma once
#include "anvil/fem/DofMap.h"
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace anvil::scene {

struct FaceSelection {
  int tag = -1; ///< boundary tag, or −1 to select by plane
  mesh::Point plane_point = mesh::Point::Zero();
  mesh::Point plane_normal = mesh::Point::UnitZ();
  double tolerance = 1e-6; ///< mm, distance to the plane
};

enum class BoundaryKind { velocity, symmetry, sticking_plate, frictionless_plate, traction, pressure };

struct BoundaryCondition {
  std::string name;
  BoundaryKind kind = BoundaryKind::velocity;
  FaceSelection faces;
  std::array<std::optional<double>, 3> velocity;      ///< mm/s per component (velocity, plates); empty = free
  Eigen::Vector3d traction = Eigen::Vector3d::Zero(); ///< MPa (traction)
  double pressure = 0.0;                              ///< MPa, positive pushes inwards (pressure)
  std::string source;                                 ///< "file:line" for error messages

  /// True when the condition prescribes velocities (its reaction goes to loads.csv).
  bool prescribes_velocity() const { return kind != BoundaryKind::traction && kind != BoundaryKind::pressure; }
};

/// Boundary faces (indices into mesh.boundary_faces) selected by `s`.
std::vector<int> select_faces(const mesh::TetMesh& mesh, const FaceSelection& s);

/// The first of `conditions` that selects faces of `before` but none of
/// `after` (a new mesh of the same body), as "condition 'name'"; empty
/// when every condition keeps its faces.
std::string condition_losing_faces(const std::vector<BoundaryCondition>& conditions, const mesh::TetMesh& before,
                                   const mesh::TetMesh& after);

/// Nodes of the selected faces, sorted and unique.
std::vector<int> face_nodes(const mesh::TetMesh& mesh, const std::vector<int>& faces);

/// What the conditions impose on one body's unknowns.
struct ImposedConditions {
  std::vector<char> prescribed;                     ///< 4 × nodes (DofMap convention)
  Eigen::VectorXd values;                           ///< 4 × nodes, imposed values at prescribed dofs
  Eigen::VectorXd nodal_forces;                     ///< 4 × nodes, external forces from tractions (N)
  std::vector<std::vector<int>> nodes_of_condition; ///< per condition, its nodes
  /// Per condition: 0, 1 or 2 for a symmetry plane normal to x, y or z; −1 otherwise.
  std::vector<int> symmetry_axis;
};

/// Applies the conditions in order (later ones override earlier ones on shared
/// dofs). Throws InputError when a condition selects no face or needs an axis-
/// aligned plane (symmetry, frictionless plate) and gets another.
ImposedConditions impose(const mesh::TetMesh& mesh, const std::vector<BoundaryCondition>& conditions);

/// Sum over the nodes of condition `c` of the nodal residual (N). At
/// prescribed dofs the residual is the internal force, i.e. the force the
/// constraint (plate, die) exerts on the body; the die load is its opposite.
Eigen::Vector3d reaction(const ImposedConditions& imposed, int c, const Eigen::VectorXd& residual);

} // namespace anvil::scene
