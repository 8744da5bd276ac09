#include "anvil/scene/BoundaryCondition.h"

#include "anvil/core/error.h"

#include <algorithm>
#include <cmath>

namespace anvil::scene {
namespace {

/// Axis (0, 1, 2) of an axis-aligned normal, or −1.
int axis_of(const mesh::Point& normal) {
  const mesh::Point n = normal.normalized();
  for (int a = 0; a < 3; ++a)
    if (std::abs(std::abs(n[a]) - 1.0) < 1e-9) return a;
  return -1;
}

/// Outward unit normal common to the selected faces, if they are coplanar.
std::optional<mesh::Point> common_normal(const mesh::TetMesh& mesh, const std::vector<int>& faces) {
  std::optional<mesh::Point> normal;
  for (int f : faces) {
    const mesh::Point n = mesh::area_vector(mesh, mesh.boundary_faces[f]).normalized();
    if (!normal)
      normal = n;
    else if (normal->dot(n) < 1.0 - 1e-6)
      return std::nullopt;
  }
  return normal;
}

} // namespace

std::vector<int> select_faces(const mesh::TetMesh& mesh, const FaceSelection& s) {
  std::vector<int> faces;
  const mesh::Point n = s.plane_normal.normalized();
  for (int f = 0; f < static_cast<int>(mesh.boundary_faces.size()); ++f) {
    if (s.tag >= 0) {
      if (mesh.boundary_tags[f] == s.tag) faces.push_back(f);
      continue;
    }
    const auto& t = mesh.boundary_faces[f];
    if (std::all_of(t.begin(), t.end(),
                    [&](int v) { return std::abs((mesh.nodes[v] - s.plane_point).dot(n)) <= s.tolerance; }))
      faces.push_back(f);
  }
  return faces;
}

std::string condition_losing_faces(const std::vector<BoundaryCondition>& conditions, const mesh::TetMesh& before,
                                   const mesh::TetMesh& after) {
  for (const BoundaryCondition& bc : conditions)
    if (select_faces(after, bc.faces).empty() && !select_faces(before, bc.faces).empty())
      return "condition '" + bc.name + "'";
  return {};
}

std::vector<int> face_nodes(const mesh::TetMesh& mesh, const std::vector<int>& faces) {
  std::vector<int> nodes;
  for (int f : faces)
    nodes.insert(nodes.end(), mesh.boundary_faces[f].begin(), mesh.boundary_faces[f].end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

ImposedConditions impose(const mesh::TetMesh& mesh, const std::vector<BoundaryCondition>& conditions) {
  using fem::kDofsPerNode;
  const int n = mesh.node_count();
  ImposedConditions out;
  out.prescribed.assign(static_cast<std::size_t>(kDofsPerNode * n), 0);
  out.values = Eigen::VectorXd::Zero(kDofsPerNode * n);
  out.nodal_forces = Eigen::VectorXd::Zero(kDofsPerNode * n);
  auto prescribe = [&](int node, int component, double value) {
    out.prescribed[kDofsPerNode * node + component] = 1;
    out.values[kDofsPerNode * node + component] = value;
  };
  for (const BoundaryCondition& bc : conditions) {
    const std::vector<int> faces = select_faces(mesh, bc.faces);
    if (faces.empty())
      throw InputError(bc.source + ": boundary condition '" + bc.name + "' selects no boundary face" +
                       (bc.faces.tag >= 0 ? " (no face has tag " + std::to_string(bc.faces.tag) + ")"
                                          : " (no face lies on the plane)"));
    const std::vector<int> nodes = face_nodes(mesh, faces);
    out.nodes_of_condition.push_back(nodes);
    out.symmetry_axis.push_back(-1);
    switch (bc.kind) {
    case BoundaryKind::velocity:
    case BoundaryKind::sticking_plate:
      for (int v : nodes)
        for (int c = 0; c < 3; ++c)
          if (bc.velocity[c]) prescribe(v, c, *bc.velocity[c]);
      break;
    case BoundaryKind::symmetry:
    case BoundaryKind::frictionless_plate: {
      // Only the normal component is imposed: the plane must be axis-aligned,
      // since velocities are Cartesian (skew planes need local frames).
      const auto normal = common_normal(mesh, faces);
      const int axis = normal ? axis_of(*normal) : -1;
      if (axis < 0)
        throw InputError(bc.source + ": '" + bc.name + "' needs its faces on one plane normal to x, y or z");
      const double value = bc.kind == BoundaryKind::symmetry ? 0.0 : bc.velocity[axis].value_or(0.0);
      if (bc.kind == BoundaryKind::symmetry) out.symmetry_axis.back() = axis;
      for (int v : nodes)
        prescribe(v, axis, value);
      break;
    }
    case BoundaryKind::traction:
    case BoundaryKind::pressure:
      // Constant traction on a linear triangle: ∫ T N_a dA = T A / 3 per vertex.
      for (int f : faces) {
        const auto& t = mesh.boundary_faces[f];
        const mesh::Point area_normal = mesh::area_vector(mesh, t);
        const Eigen::Vector3d force = bc.kind == BoundaryKind::traction
                                          ? Eigen::Vector3d(bc.traction * area_normal.norm())
                                          : Eigen::Vector3d(-bc.pressure * area_normal);
        for (int v : t)
          out.nodal_forces.segment<3>(kDofsPerNode * v) += force / 3.0;
      }
      break;
    }
  }
  return out;
}

Eigen::Vector3d reaction(const ImposedConditions& imposed, int c, const Eigen::VectorXd& residual) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (int v : imposed.nodes_of_condition[c])
    force += residual.segment<3>(fem::kDofsPerNode * v);
  return force;
}

} // namespace anvil::scene
