#include "anvil/mesh/manifold.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace anvil::mesh {

namespace {

std::string nodes_text(std::initializer_list<int> nodes) {
  std::string text;
  for (int v : nodes)
    text += (text.empty() ? "" : ", ") + std::to_string(v + 1);
  return text;
}

} // namespace

std::string manifold_fault(const TetMesh& mesh) {
  // Faces used once are the boundary; twice, inner; more, not a manifold.
  std::vector<Triangle> faces;
  faces.reserve(4 * mesh.tets.size());
  for (const Tet& t : mesh.tets)
    for (const auto& local : kFaceVertices)
      faces.push_back(sorted({t[local[0]], t[local[1]], t[local[2]]}));
  std::sort(faces.begin(), faces.end());
  std::vector<Triangle> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i])
      ++j;
    if (j - i > 2)
      return "the face of nodes " + nodes_text({faces[i][0], faces[i][1], faces[i][2]}) + " is in " +
             std::to_string(j - i) + " tetrahedra";
    if (j - i == 1) boundary.push_back(faces[i]);
    i = j;
  }
  // Every boundary edge on exactly two boundary faces.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * boundary.size());
  for (const Triangle& f : boundary)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    if (j - i != 2)
      return "the boundary edge of nodes " + nodes_text({edges[i].first, edges[i].second}) + " is on " +
             std::to_string(j - i) + " boundary faces";
    i = j;
  }
  // Around a boundary node its faces' far edges (the link) then form closed
  // loops; more than one loop is a pinch.
  std::vector<std::vector<std::pair<int, int>>> link(mesh.nodes.size());
  for (const Triangle& f : boundary)
    for (int k = 0; k < 3; ++k)
      link[f[k]].emplace_back(f[(k + 1) % 3], f[(k + 2) % 3]);
  for (std::size_t v = 0; v < link.size(); ++v) {
    std::vector<std::pair<int, int>>& around = link[v];
    if (around.empty()) continue;
    // Walk the loop through the first link edge; count the edges it passes.
    const int start = around[0].first;
    int at = around[0].second, from = 0;
    std::size_t walked = 1;
    while (at != start && walked <= around.size()) {
      std::size_t next = 0;
      while (next < around.size() &&
             (next == std::size_t(from) || (around[next].first != at && around[next].second != at)))
        ++next;
      if (next == around.size()) break;
      at = around[next].first == at ? around[next].second : around[next].first;
      from = static_cast<int>(next);
      ++walked;
    }
    if (walked != around.size())
      return "the boundary faces around node " + std::to_string(v + 1) +
             " form more than one fan (two parts of the body touch there)";
  }
  return {};
}

} // namespace anvil::mesh
