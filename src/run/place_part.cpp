#include "anvil/run/place_part.h"

#include "anvil/core/error.h"
#include "anvil/scene/Die.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace anvil::run {
namespace {

/// Mirrors `part` in the axes flagged, about `centre`; an odd number of
/// mirrors reverses every tet and face so that they stay positive.
void mirror(scene::RunState& part, const std::array<bool, 3>& axes, const Eigen::Vector3d& centre) {
  for (mesh::Point& x : part.mesh.nodes)
    for (int a = 0; a < 3; ++a)
      if (axes[a]) x[a] = 2.0 * centre[a] - x[a];
  if ((axes[0] + axes[1] + axes[2]) % 2 == 0) return;
  for (mesh::Tet& t : part.mesh.tets)
    std::swap(t[0], t[1]);
  for (mesh::Triangle& f : part.mesh.boundary_faces)
    std::swap(f[0], f[1]);
}

} // namespace

std::vector<SymmetryPlane> symmetry_planes(const scene::Case& c, const mesh::TetMesh& mesh) {
  std::vector<SymmetryPlane> planes;
  for (const scene::BoundaryCondition& bc : c.boundary) {
    if (bc.kind != scene::BoundaryKind::symmetry) continue;
    Eigen::Vector3d normal = bc.faces.plane_normal;
    mesh::Point on = bc.faces.plane_point;
    if (bc.faces.tag != 0) {
      normal.setZero();
      for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
        if (mesh.boundary_tags[f] == bc.faces.tag)
          normal += mesh::area_vector(mesh, mesh.boundary_faces[f]), on = mesh.nodes[mesh.boundary_faces[f][0]];
    }
    for (int a = 0; a < 3; ++a)
      if (normal.norm() > 0.0 && std::abs(normal.normalized()[a]) > 1.0 - 1e-6) planes.push_back({a, on[a]});
  }
  return planes;
}

double height_above_die(const scene::RunState& part, const die::SurfaceTriangles& s) {
  const std::vector<char> boundary = mesh::boundary_node_flags(part.mesh);
  double height = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < part.mesh.nodes.size(); ++n) {
    if (!boundary[n]) continue;
    const mesh::Point& x = part.mesh.nodes[n];
    for (const auto& f : s.faces) {
      const mesh::Point &a = s.vertices[f[0]], &b = s.vertices[f[1]], &c = s.vertices[f[2]];
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      if (!(normal.z() > 0.0)) continue; // a facet that faces up carries the part
      // Barycentric coordinates of x's foot in the facet's projection on z = 0.
      const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
      const double u = ((x.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (x.y() - a.y())) / det;
      const double v = ((b.x() - a.x()) * (x.y() - a.y()) - (x.x() - a.x()) * (b.y() - a.y())) / det;
      if (u < -1e-12 || v < -1e-12 || u + v > 1.0 + 1e-12) continue;
      const double surface = a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z());
      height = std::min(height, x.z() - surface);
    }
  }
  return height;
}

void place_part(const scene::Placement& place, const scene::Case& next, scene::RunState& part,
                const std::string& where) {
  if (!place.moves()) return;
  std::array<bool, 3> planes = {false, false, false};
  for (const SymmetryPlane& p : symmetry_planes(next, part.mesh))
    planes[p.axis] = true;
  if ((place.flip || place.turn != 0.0) && !part.elastic_stress.empty())
    throw InputError(where + ": key 'place': an elastic body's stress is not turned with it: place moves only "
                             "flowing bodies by a translation");
  if (place.flip) {
    std::array<bool, 3> axes = {false, false, true};
    if (!planes[1])
      axes[1] = true; // half a turn about x
    else if (!planes[0])
      axes[0] = true; // about y
    mirror(part, axes, mesh::bounding_box(part.mesh).center());
  }
  if (place.turn != 0.0) {
    if (planes[0] || planes[1])
      throw InputError(where + ": key 'place.turn': a model cut by a symmetry plane through the press axis cannot be "
                               "turned about it");
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(place.turn * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (mesh::Point& x : part.mesh.nodes)
      x = turn * x;
  }
  for (int a = 0; a < 2; ++a)
    if (planes[a] && place.move[a] != 0.0)
      throw InputError(where + ": key 'place.move': the model's symmetry plane normal to " + "xy"[a] +
                       " stays where it is: move it along z (and along the other axis) only");
  for (mesh::Point& x : part.mesh.nodes)
    x += place.move;
  if (!place.rest) return;
  // The lowest die (the one whose lowest point is lowest) at its start, a
  // plane's display square larger than the part and its distance from the axis.
  const Eigen::AlignedBox3d box = mesh::bounding_box(part.mesh);
  const double size = box.diagonal().norm() + box.max().cwiseAbs().maxCoeff() + box.min().cwiseAbs().maxCoeff();
  std::optional<scene::Die> lowest;
  double lowest_z = std::numeric_limits<double>::infinity();
  for (const scene::DieSpec& spec : next.dies) {
    scene::Die die = scene::build_die(spec, size, size);
    double z = std::numeric_limits<double>::infinity();
    for (const mesh::Point& p : die.surface->triangles().vertices)
      z = std::min(z, p.z());
    if (z < lowest_z) lowest_z = z, lowest = std::move(die);
  }
  const double drop = height_above_die(part, lowest->surface->triangles());
  if (!std::isfinite(drop))
    throw InputError(where + ": key 'place.rest': no facet of die '" + lowest->name +
                     "' lies under the part: move it over the die first (place.move)");
  for (mesh::Point& x : part.mesh.nodes)
    x.z() -= drop;
}

} // namespace anvil::run
