#include "anvil/remesh/fit_to_dies.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/mesh/QualityGuard.h"
#include "anvil/mesh/restore_volume.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace anvil::remesh {
namespace {
/// Element rings of interior nodes carried along by a node put onto a die.
constexpr int kCarriedRings = 3;
} // namespace

PutBack put_onto_dies(mesh::TetMesh& fresh, const mesh::TetMesh& old, std::span<const int> touching_die,
                      const scene::Scene& scene, int body, std::span<const scene::DieState> dies_now,
                      double element_size, double quality_floor, std::span<const char> movable) {
  // The new boundary lies on the old one, and nodal contact lets a die
  // corner sink between nodes: new nodes there start inside the die, where
  // the next increment would push them out at once. They are put onto it
  // now, as the update puts contact nodes. Deeper than an element is not
  // this body's contact (the far side of an open die surface). One pass of
  // the projection (the closest point, a symmetry coordinate kept), not the
  // update's passes to the surface: a node on a symmetry plane beside an
  // inclined die wall then moves less, and the next increment's contact
  // closes the rest; moved in full, such a node can be pushed back out in
  // one increment and invert an element.
  const std::vector<char> on_boundary = mesh::boundary_node_flags(fresh);
  const mesh::QualityGuard guard(fresh);
  // The body's symmetry planes, axis-aligned (BoundaryCondition): the axis
  // and the coordinate, from the old mesh, whose faces were checked planar.
  std::vector<std::pair<int, double>> planes;
  for (const scene::BoundaryCondition& bc : scene.bodies[body].conditions) {
    if (bc.kind != scene::BoundaryKind::symmetry) continue;
    const std::vector<int> faces = scene::select_faces(old, bc.faces);
    if (faces.empty()) continue;
    const mesh::Triangle& face = old.boundary_faces[faces.front()];
    int axis = 0;
    mesh::area_vector(old, face).cwiseAbs().maxCoeff(&axis);
    planes.emplace_back(axis, old.nodes[face[0]][axis]);
  }
  const double on_plane = 1e-6 * element_size;
  // What touched a die still does: a node on an old face whose three nodes
  // pressed on a die is put onto it from outside too, rather than leave a
  // gap the next increment must close.
  const contact::SurfaceSearch old_surface(old.nodes, old.boundary_faces);
  auto on_face_touching = [&](const mesh::Point& x, int die) {
    const mesh::Triangle& face = old.boundary_faces[old_surface.closest(x).face];
    return std::all_of(face.begin(), face.end(), [&](int node) { return touching_die[node] == die; });
  };
  const double widest_gap = 0.25 * element_size;
  PutBack done;
  // Nodes inside a die whose own move would crush an element under them
  // (a fine surface layer over a die edge the old coarse chord cut deep).
  std::vector<int> stuck;
  std::vector<mesh::Point> stuck_onto;
  std::vector<double> stuck_depth;
  const double one_pass = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < fresh.nodes.size(); ++i) {
    if (!on_boundary[i] || (!movable.empty() && !movable[i])) continue;
    mesh::Point x = fresh.nodes[i];
    std::array<bool, 3> free{true, true, true};
    for (const auto& [axis, coordinate] : planes)
      if (std::abs(x[axis] - coordinate) <= on_plane) x[axis] = coordinate, free[axis] = false;
    const mesh::Point start = x; // where the node lies on the old surface
    for (std::size_t d = 0; d < scene.dies.size(); ++d) {
      const Eigen::Vector3d& shift = dies_now[d].displacement;
      const die::DieSurface& surface = *scene.dies[d].surface;
      const die::SurfaceProjection p = surface.project(fresh.nodes[i] - shift);
      const bool inside = p.distance < 0.0 && p.distance >= -element_size;
      const bool across_gap = p.distance > 0.0 && p.distance <= widest_gap && on_face_touching(start, int(d));
      if (!inside && !across_gap) continue;
      const mesh::Point onto = shift + die::project_keeping(surface, x - shift, free, one_pass);
      if (!guard.move(fresh, int(i), onto, quality_floor)) {
        if (inside && (stuck.empty() || stuck.back() != int(i)))
          stuck.push_back(int(i)), stuck_onto.push_back(onto), stuck_depth.push_back(-p.distance);
        continue;
      }
      x = onto; // a later die projects the node from where it now is
      if (inside)
        ++done.nodes, done.deepest = std::max(done.deepest, -p.distance);
      else
        ++done.closed, done.widest = std::max(done.widest, p.distance);
    }
  }
  // Under an adaptive size field, moved with the interior under them: the
  // elements between keep their shape; what is still inside after a part
  // of the move is left to the next increment's contact. A uniform remesh
  // samples its surface at the old spacing and leaves few such nodes, and
  // shallow ones (1-16 a whole remesh on the connecting rod, against 40-199
  // under the adaptive field): carried too, they moved the hub flange's
  // path onto one whose overlap remesh near closure jumps 10 %.
  std::vector<double> taken(stuck.size(), 0.0);
  if (scene.input.remeshing.adaptive) {
    std::vector<char> fixed = on_boundary;
    if (!movable.empty())
      for (std::size_t i = 0; i < fixed.size(); ++i)
        fixed[i] = fixed[i] || !movable[i];
    taken = guard.move_carrying(fresh, stuck, stuck_onto, fixed, kCarriedRings, quality_floor);
  }
  for (std::size_t k = 0; k < stuck.size(); ++k) {
    if (taken[k] == 1.0) {
      ++done.nodes, ++done.carried, done.deepest = std::max(done.deepest, stuck_depth[k]);
      continue;
    }
    ++done.left;
    done.deepest_left = std::max(done.deepest_left, (1.0 - taken[k]) * stuck_depth[k]);
  }
  return done;
}

std::vector<SunkEdge> edges_over_die_features(const mesh::TetMesh& mesh, const mesh::MeshRange& range,
                                              const scene::Scene& scene, std::span<const scene::DieState> dies_now,
                                              double depth, double shortest, double deepest) {
  std::map<std::array<int, 2>, mesh::Point> edges; // a node pair once, from either of its faces
  for (int f = range.first_face; f < range.first_face + range.face_count; ++f) {
    const mesh::Triangle& face = mesh.boundary_faces[f];
    const Eigen::Vector3d area = mesh::area_vector(mesh, face);
    if (area.squaredNorm() == 0.0) continue;
    const Eigen::Vector3d outward = area.normalized();
    for (int k = 0; k < 3; ++k) {
      const int a = face[k], c = face[(k + 1) % 3];
      const mesh::Point &xa = mesh.nodes[a], &xc = mesh.nodes[c];
      if ((xa - xc).norm() <= shortest) continue;
      const mesh::Point middle = 0.5 * (xa + xc);
      for (std::size_t d = 0; d < scene.dies.size(); ++d) {
        const Eigen::Vector3d& shift = dies_now[d].displacement;
        const die::SurfaceProjection p = scene.dies[d].surface->project(middle - shift);
        if (p.distance < -depth && p.distance >= -deepest && -p.normal.dot(outward) >= 0.5) {
          edges.emplace(std::array<int, 2>{std::min(a, c) - range.first_node, std::max(a, c) - range.first_node},
                        shift + p.point);
          break;
        }
      }
    }
  }
  std::vector<SunkEdge> sunk;
  sunk.reserve(edges.size());
  for (const auto& [nodes, on_die] : edges)
    sunk.push_back({nodes, on_die});
  return sunk;
}

double keep_material(mesh::TetMesh& fresh, const scene::Scene& scene, int body,
                     std::span<const scene::DieState> dies_now, double material, double element_size,
                     std::span<const char> movable) {
  // CGAL's mesh keeps the old mesh's volume (restore_volume) but not its
  // material: its chords cut across die fillets, the restoration pushes
  // nodes on the dies into them, and the put-back then cuts off more than
  // the old overlap. Left to the next increment's volume compensation, that
  // material would come back within one step as a jump of the press load.
  // It is given back here, on the free surface, where the material a die
  // displaces goes. Assumes the free surface is a fair share of the body's
  // boundary: a body wholly enclosed by dies has none (distance 0).
  if (scene.dies.empty()) return 0.0;
  std::vector<char> free_node = mesh::boundary_node_flags(fresh);
  for (const scene::BoundaryCondition& bc : scene.bodies[body].conditions)
    if (bc.kind == scene::BoundaryKind::symmetry)
      for (int f : scene::select_faces(fresh, bc.faces))
        for (int v : fresh.boundary_faces[f])
          free_node[v] = 0;
  if (!movable.empty())
    for (std::size_t i = 0; i < fresh.nodes.size(); ++i)
      free_node[i] = free_node[i] && movable[i];
  const double off_die = 0.1 * element_size;
  for (std::size_t i = 0; i < fresh.nodes.size(); ++i)
    for (std::size_t d = 0; d < scene.dies.size() && free_node[i]; ++d)
      free_node[i] = scene.dies[d].surface->project(fresh.nodes[i] - dies_now[d].displacement).distance > off_die;
  // The volume wanted: the material, and the overlap the new mesh has (the
  // free nodes moved stay off the dies).
  return mesh::restore_volume(
      fresh, material + scene::inside_dies(scene, fresh, mesh::whole_range(fresh), body, dies_now), free_node);
}

} // namespace anvil::remesh
