#include "anvil/remesh/remesh_body.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace anvil::remesh {

std::vector<int> boundary_patches(const mesh::TetMesh& body, double feature_angle, double smallest_area) {
  const std::size_t faces = body.boundary_faces.size();
  std::vector<mesh::Point> normal(faces);
  std::vector<double> area(faces);
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (std::size_t f = 0; f < faces; ++f) {
    const mesh::Triangle& t = body.boundary_faces[f];
    const mesh::Point a = mesh::area_vector(body, t);
    area[f] = a.norm();
    normal[f] = a.normalized();
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
  // A patch smaller than `smallest_area` is a crumple of a few faces (a die
  // edge pressed into a crease), not a feature the new mesh can resolve: its
  // border would make CGAL corners, which no smoothing moves, and every
  // remesh would remake the poor elements between them. It joins the
  // neighbour of its tag it shares the longest border with, the smallest
  // patches first.
  if (smallest_area > 0.0) {
    // across[3 f + k]: the face beyond edge k (nodes k, k + 1) of face f, −1 at a non-manifold edge.
    std::vector<int> across(3 * faces, -1);
    for (std::size_t f = 0; f < faces; ++f)
      for (int k = 0; k < 3; ++k) {
        const mesh::Triangle& t = body.boundary_faces[f];
        const std::vector<int>& adjacent = faces_of_edge.at(std::minmax(t[k], t[(k + 1) % 3]));
        if (adjacent.size() == 2) across[3 * f + k] = adjacent[0] == int(f) ? adjacent[1] : adjacent[0];
      }
    std::vector<double> patch_area(faces, 0.0);
    std::vector<std::vector<int>> members(faces);
    for (std::size_t f = 0; f < faces; ++f) {
      const int r = root(static_cast<int>(f));
      patch_area[r] += area[f];
      members[r].push_back(static_cast<int>(f));
    }
    std::vector<int> small;
    for (std::size_t f = 0; f < faces; ++f)
      if (!members[f].empty() && patch_area[f] < smallest_area) small.push_back(static_cast<int>(f));
    std::stable_sort(small.begin(), small.end(), [&](int a, int b) { return patch_area[a] < patch_area[b]; });
    for (int p : small) {
      const int r = root(p);
      if (patch_area[r] >= smallest_area) continue; // grown by a smaller one that joined it
      std::map<int, double> border;                 // neighbour patch → length of the border shared with it
      for (int f : members[r])
        for (int k = 0; k < 3; ++k) {
          const int g = across[3 * f + k];
          if (g < 0 || root(g) == r || body.boundary_tags[g] != body.boundary_tags[f]) continue;
          const mesh::Triangle& t = body.boundary_faces[f];
          border[root(g)] += (body.nodes[t[k]] - body.nodes[t[(k + 1) % 3]]).norm();
        }
      if (border.empty()) continue;
      const int into = std::max_element(border.begin(), border.end(), [](const auto& a, const auto& b) {
                         return a.second < b.second;
                       })->first;
      parent[r] = into;
      patch_area[into] += patch_area[r];
      members[into].insert(members[into].end(), members[r].begin(), members[r].end());
      members[r].clear();
    }
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
