#include "anvil/remesh/rebuild_region.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>

namespace anvil::remesh {

std::vector<char> rebuild_region(const mesh::TetMesh& part, const Eigen::Ref<const Eigen::VectorXd>& nodal,
                                 double time_step, double threshold, int layers) {
  auto moved = [&](int node) -> mesh::Point { return part.nodes[node] + time_step * nodal.segment<3>(4 * node); };
  std::vector<char> flagged(part.tets.size(), 0);
  for (int e = 0; e < part.tet_count(); ++e) {
    const mesh::Tet& t = part.tets[e];
    flagged[e] = mesh::quality(part, e) < threshold ||
                 mesh::quality(moved(t[0]), moved(t[1]), moved(t[2]), moved(t[3])) < threshold;
  }
  return grow_region(part, std::move(flagged), layers);
}

std::vector<char> region_around(const mesh::TetMesh& part, std::span<const mesh::Point> points, double radius,
                                int layers) {
  std::vector<char> flagged(part.tets.size(), 0);
  for (int e = 0; e < part.tet_count(); ++e)
    for (const mesh::Point& x : points)
      for (int v : part.tets[e])
        flagged[e] = flagged[e] || (part.nodes[v] - x).norm() <= radius;
  return grow_region(part, std::move(flagged), layers);
}

std::vector<char> grow_region(const mesh::TetMesh& part, std::vector<char> flagged, int layers) {
  std::vector<char> touched(part.nodes.size(), 0);
  for (int layer = 0; layer < layers; ++layer) {
    for (int e = 0; e < part.tet_count(); ++e)
      if (flagged[e])
        for (int v : part.tets[e])
          touched[v] = 1;
    for (int e = 0; e < part.tet_count(); ++e)
      for (int v : part.tets[e])
        flagged[e] = flagged[e] || touched[v];
  }
  return flagged;
}

std::vector<std::array<int, 2>> long_border_edges(const mesh::TetMesh& part, const std::vector<char>& region,
                                                  double longest) {
  std::vector<char> in_kept(part.nodes.size(), 0);
  for (int e = 0; e < part.tet_count(); ++e)
    if (!region[e])
      for (int v : part.tets[e])
        in_kept[v] = 1;
  std::vector<std::array<int, 2>> edges;
  for (int e = 0; e < part.tet_count(); ++e) {
    if (!region[e]) continue;
    const mesh::Tet& t = part.tets[e];
    for (int a = 0; a < 4; ++a)
      for (int c = a + 1; c < 4; ++c)
        if (in_kept[t[a]] && in_kept[t[c]] && (part.nodes[t[a]] - part.nodes[t[c]]).norm() > longest)
          edges.push_back({std::min(t[a], t[c]), std::max(t[a], t[c])});
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

double mean_edge_length(const mesh::TetMesh& part, const std::vector<char>& region) {
  double sum = 0.0;
  int count = 0;
  for (int e = 0; e < part.tet_count(); ++e)
    if (region[e])
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
          sum += (part.nodes[part.tets[e][a]] - part.nodes[part.tets[e][b]]).norm(), ++count;
  return count > 0 ? sum / count : 0.0;
}

} // namespace anvil::remesh
