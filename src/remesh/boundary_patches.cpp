#include "anvil/remesh/remesh_body.h"

#include <cmath>
#include <map>
#include <numeric>

namespace anvil::remesh {

std::vector<int> boundary_patches(const mesh::TetMesh& body, double feature_angle) {
  const std::size_t faces = body.boundary_faces.size();
  std::vector<mesh::Point> normal(faces);
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (std::size_t f = 0; f < faces; ++f) {
    const mesh::Triangle& t = body.boundary_faces[f];
    normal[f] = mesh::area_vector(body, t).normalized();
    for (int k = 0; k < 3; ++k)
      faces_of_edge[std::minmax(t[k], t[(k + 1) % 3])].push_back(static_cast<int>(f));
  }
  // Union-find over faces: one set per patch.
  std::vector<int> parent(faces);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int f) {
    while (parent[f] != f)
      f = parent[f] = parent[parent[f]];
    return f;
  };
  const double smooth = std::cos(feature_angle * M_PI / 180.0);
  for (const auto& [edge, adjacent] : faces_of_edge) {
    if (adjacent.size() != 2) continue;
    const int a = adjacent[0], b = adjacent[1];
    if (body.boundary_tags[a] == body.boundary_tags[b] && normal[a].dot(normal[b]) >= smooth) parent[root(a)] = root(b);
  }
  std::vector<int> patch(faces), number(faces, 0);
  int patches = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    int& n = number[root(static_cast<int>(f))];
    if (n == 0) n = ++patches;
    patch[f] = n;
  }
  return patch;
}

} // namespace anvil::remesh
