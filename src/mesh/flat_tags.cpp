#include "anvil/mesh/flat_tags.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace anvil::mesh {

namespace {

/// A node off a plane by more than this (mm, relative to the offset) is off it.
double off_plane(double offset) {
  return 1e-9 * (1.0 + std::abs(offset));
}

} // namespace

std::map<int, std::pair<Point, double>> flat_tags(const TetMesh& mesh) {
  std::map<int, std::pair<Point, double>> plane;
  std::set<int> not_flat;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const int tag = mesh.boundary_tags[f];
    const Triangle& t = mesh.boundary_faces[f];
    const Point n = area_vector(mesh, t).normalized();
    const auto [it, first] = plane.try_emplace(tag, n, n.dot(mesh.nodes[t[0]]));
    if (first) continue;
    if (it->second.first.dot(n) < 1.0 - 1e-9 || !in_plane(mesh, t, it->second)) not_flat.insert(tag);
  }
  for (int tag : not_flat)
    plane.erase(tag);
  return plane;
}

bool in_plane(const TetMesh& mesh, const Triangle& face, const std::pair<Point, double>& plane) {
  const auto& [normal, offset] = plane;
  return std::all_of(face.begin(), face.end(),
                     [&](int v) { return std::abs(normal.dot(mesh.nodes[v]) - offset) <= off_plane(offset); });
}

} // namespace anvil::mesh
