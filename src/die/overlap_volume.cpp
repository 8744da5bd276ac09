#include "anvil/die/overlap_volume.h"

#include "anvil/core/processes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

namespace anvil::die {

namespace {

constexpr int n = 4; ///< a face is cut into n² sub-triangles

/// The sub-triangles' centroids, in barycentric coordinates (b, c) of a face (a, b, c).
const std::array<Eigen::Vector2d, n* n> samples = [] {
  std::array<Eigen::Vector2d, n * n> at{};
  int k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      at[k++] = Eigen::Vector2d(i + 1.0 / 3.0, j + 1.0 / 3.0) / n;
      if (i + j < n - 1) at[k++] = Eigen::Vector2d(i + 2.0 / 3.0, j + 2.0 / 3.0) / n;
    }
  return at;
}();

/// overlap_volume's share of boundary face `f`.
double overlap_under_face(const mesh::TetMesh& mesh, int f, const DieSurface& surface, const Eigen::Vector3d& shift,
                          double deepest, const SurfaceProjection& near) {
  const mesh::Triangle& face = mesh.boundary_faces[f];
  const mesh::Point &a = mesh.nodes[face[0]], &b = mesh.nodes[face[1]], &c = mesh.nodes[face[2]];
  const mesh::Point centroid = (a + b + c) / 3.0;
  const double radius = std::max({(a - centroid).norm(), (b - centroid).norm(), (c - centroid).norm()});
  const SurfaceProjection middle = surface.project_near(centroid - shift, near);
  if (middle.distance > radius) return 0.0; // the die surface misses the face
  const Eigen::Vector3d area = mesh::area_vector(mesh, face);
  const double area_norm = area.norm();
  if (area_norm == 0.0) return 0.0;
  const Eigen::Vector3d outward = area / area_norm;
  double depth_sum = 0.0;
  for (const Eigen::Vector2d& s : samples) {
    const mesh::Point x = a + s.x() * (b - a) + s.y() * (c - a);
    const SurfaceProjection p = surface.project_near(x - shift, middle);
    if (p.distance >= 0.0 || p.distance < -deepest) continue;
    // Along the face's inward normal down to the die's tangent plane. A die
    // wall more than 60° from facing the face is not below it: a face on a
    // symmetry plane cuts the overlap another face already counts.
    const double facing = -p.normal.dot(outward);
    if (facing >= 0.5) depth_sum += -p.distance / facing;
  }
  return area_norm * depth_sum / (n * n);
}

/// A boundary face by its corners' coordinates, the smallest corner
/// (lexicographically) first and the turn kept: the same face in two meshes,
/// whatever their numbering.
using FaceKey = std::array<double, 9>;
FaceKey face_key(const mesh::TetMesh& mesh, int f) {
  const mesh::Triangle& face = mesh.boundary_faces[f];
  auto less = [&](int a, int b) {
    const mesh::Point &x = mesh.nodes[face[a]], &y = mesh.nodes[face[b]];
    return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
  };
  int first = 0;
  for (int i = 1; i < 3; ++i)
    if (less(i, first)) first = i;
  FaceKey key;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      key[3 * i + k] = mesh.nodes[face[(first + i) % 3]][k];
  return key;
}

/// The boundary faces of `body` in `mesh`, with their keys, sorted by key.
std::vector<std::pair<FaceKey, int>> keyed_faces(const mesh::TetMesh& mesh, const mesh::MeshRange& body) {
  std::vector<std::pair<FaceKey, int>> keyed;
  keyed.reserve(body.face_count);
  for (int k = 0; k < body.face_count; ++k)
    keyed.emplace_back(face_key(mesh, body.first_face + k), body.first_face + k);
  std::sort(keyed.begin(), keyed.end());
  return keyed;
}

} // namespace

double overlap_change(const mesh::TetMesh& before, const mesh::TetMesh& after, const DieSurface& surface,
                      const Eigen::Vector3d& shift, double deepest) {
  const auto old_faces = keyed_faces(before, mesh::whole_range(before));
  const auto new_faces = keyed_faces(after, mesh::whole_range(after));
  auto by_key = [](const auto& a, const auto& b) { return a.first < b.first; };
  std::vector<std::pair<FaceKey, int>> gone, added;
  std::set_difference(old_faces.begin(), old_faces.end(), new_faces.begin(), new_faces.end(), std::back_inserter(gone),
                      by_key);
  std::set_difference(new_faces.begin(), new_faces.end(), old_faces.begin(), old_faces.end(), std::back_inserter(added),
                      by_key);
  // Each face's share as overlap_volume takes it, searched for from its centroid.
  double change = 0.0;
  for (const auto& [key, f] : added)
    change += overlap_under_face(after, f, surface, shift, deepest, {});
  for (const auto& [key, f] : gone)
    change -= overlap_under_face(before, f, surface, shift, deepest, {});
  return change;
}

double overlap_volume(const mesh::TetMesh& mesh, const mesh::MeshRange& body, const DieSurface& surface,
                      const Eigen::Vector3d& shift, double deepest) {
  // The distance to the die is 1-Lipschitz: a face with a corner farther
  // from the die than the face's diameter plus `deepest` has no point within
  // `deepest` of it, and adds nothing (every sample would be outside or past
  // the far side). One projection per corner node tells most faces away from
  // the die apart, where the face's own test needs one per face; it looks
  // for the die only as far as the largest such bound of the corner's faces
  // (project_within), and what it finds starts the search of the faces'
  // centroids.
  // Per face: the distance beyond which a corner rules it out.
  constexpr double kMargin = 1.001; // the bound's own rounding
  std::vector<double> bound(body.face_count);
  std::vector<int> corner_of(mesh.nodes.size(), -1);
  std::vector<int> corners;
  std::vector<double> reach; // per corner: the largest bound of its faces
  for (int k = 0; k < body.face_count; ++k) {
    const mesh::Triangle& face = mesh.boundary_faces[body.first_face + k];
    double diameter = 0.0;
    for (int i = 0; i < 3; ++i)
      diameter = std::max(diameter, (mesh.nodes[face[i]] - mesh.nodes[face[(i + 1) % 3]]).norm());
    bound[k] = kMargin * (diameter + deepest);
    for (const int v : face) {
      if (corner_of[v] < 0) corner_of[v] = static_cast<int>(corners.size()), corners.push_back(v), reach.push_back(0.0);
      reach[corner_of[v]] = std::max(reach[corner_of[v]], bound[k]);
    }
  }
  // Per corner: its distance to the die (infinite beyond its reach), the facet and closest point found.
  constexpr int kWidth = 5;
  const std::vector<double> found =
      processes::share_out(static_cast<int>(corners.size()), kWidth, [&](int k, double* out) {
        out[0] = std::numeric_limits<double>::infinity(), out[1] = -1.0;
        const std::optional<SurfaceProjection> p = surface.project_within(mesh.nodes[corners[k]] - shift, reach[k]);
        if (!p) return;
        out[0] = std::abs(p->distance), out[1] = p->facet;
        Eigen::Map<Eigen::Vector3d>(out + 2) = p->point;
      });
  const std::vector<double> under = processes::share_out(body.face_count, 1, [&](int k, double* volume) {
    const mesh::Triangle& face = mesh.boundary_faces[body.first_face + k];
    int nearest = corner_of[face[0]];
    double farthest = 0.0;
    for (const int v : face) {
      const int c = corner_of[v];
      farthest = std::max(farthest, found[kWidth * c]);
      if (found[kWidth * c] < found[kWidth * nearest]) nearest = c;
    }
    if (farthest > bound[k]) return;
    SurfaceProjection near;
    near.point = Eigen::Map<const Eigen::Vector3d>(&found[kWidth * nearest + 2]);
    near.facet = static_cast<int>(found[kWidth * nearest + 1]);
    *volume = overlap_under_face(mesh, body.first_face + k, surface, shift, deepest, near);
  });
  double volume = 0.0;
  for (const double v : under) // in face order: the same sum on any number of processes
    volume += v;
  return volume;
}

} // namespace anvil::die
