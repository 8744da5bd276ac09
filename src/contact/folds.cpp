#include "anvil/contact/folds.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/core/DisjointSets.h"
#include "anvil/mesh/triangle_geometry.h"

#include <algorithm>

namespace anvil::contact {
namespace {

/// The body `face` (an index into mesh.boundary_faces) belongs to.
int body_of(std::span<const mesh::MeshRange> bodies, int face) {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (face >= bodies[b].first_face && face < bodies[b].first_face + bodies[b].face_count) return int(b);
  return -1;
}

} // namespace

FoldScan find_folds(const mesh::TetMesh& mesh, std::span<const mesh::MeshRange> bodies, const std::vector<char>& skip,
                    double edge) {
  const double reach = 0.1 * edge, depth = 0.5 * edge;
  const std::vector<mesh::Triangle>& faces = mesh.boundary_faces;
  FoldScan scan;
  scan.faces.assign(faces.size(), 0);
  // Union-find over nodes: a fold's faces, and the faces they meet, are one fold.
  DisjointSets sets(mesh.nodes.size());
  const SurfaceSearch search(mesh.nodes, faces);
  std::vector<int> near;
  const double around = std::max(reach, depth);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    if (!skip.empty() && skip[f]) continue;
    const mesh::Triangle& t = faces[f];
    const mesh::Point centre = (mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]]) / 3.0;
    const Eigen::Vector3d normal = mesh::area_vector(mesh, t).normalized();
    search.overlapping(Eigen::AlignedBox3d(centre.array() - around, centre.array() + around), near);
    const int body = body_of(bodies, f);
    for (const int g : near) {
      if (g == f || (!skip.empty() && skip[g]) || body_of(bodies, g) != body) continue;
      const mesh::Triangle& u = faces[g];
      if (std::any_of(t.begin(), t.end(), [&](int n) { return std::find(u.begin(), u.end(), n) != u.end(); })) continue;
      const Eigen::Vector3d other = mesh::area_vector(mesh, u).normalized();
      if (normal.dot(other) >= -0.5) continue;
      const mesh::Point on = mesh::nearest_on_triangle(centre, mesh.nodes[u[0]], mesh.nodes[u[1]], mesh.nodes[u[2]]);
      const double distance = (centre - on).norm();
      const bool behind = (centre - on).dot(other) < 0.0;
      if (distance <= reach || (behind && distance <= depth)) {
        scan.faces[f] = scan.faces[g] = 1;
        sets.join(t[0], u[0]);
      }
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (scan.faces[f])
      for (int k = 1; k < 3; ++k)
        sets.join(faces[f][k], faces[f][0]);
  std::vector<int> fold_of(mesh.nodes.size(), -1);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!scan.faces[f]) continue;
    const mesh::Triangle& t = faces[f];
    int& index = fold_of[sets.root(t[0])];
    if (index < 0) {
      index = static_cast<int>(scan.folds.size());
      scan.folds.push_back({body_of(bodies, int(f)), mesh::Point::Zero(), 0.0, 0});
    }
    Fold& fold = scan.folds[index];
    const double area = mesh::area_vector(mesh, t).norm();
    fold.centre += area * (mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]]) / 3.0;
    fold.area += area;
    ++fold.faces;
  }
  for (Fold& fold : scan.folds)
    fold.centre /= fold.area;
  std::stable_sort(scan.folds.begin(), scan.folds.end(), [](const Fold& a, const Fold& b) { return a.area > b.area; });
  return scan;
}

} // namespace anvil::contact
