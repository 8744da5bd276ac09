#include "anvil/fem/Partition.h"

#include <algorithm>
#include <numeric>

namespace anvil::fem {
namespace {

/// Gives the elements [first, last) of `order` (their `centroids`) to parts
/// part … part + parts − 1: split at the centroid that leaves each side
/// elements in proportion to its parts, across the longest extent.
void bisect(std::vector<int>::iterator first, std::vector<int>::iterator last, int part, int parts,
            const std::vector<mesh::Point>& centroids, std::vector<int>& element_part) {
  if (parts == 1) {
    for (auto e = first; e != last; ++e)
      element_part[*e] = part;
    return;
  }
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), high = -low;
  for (auto e = first; e != last; ++e)
    low = low.cwiseMin(centroids[*e]), high = high.cwiseMax(centroids[*e]);
  int axis = 0;
  (high - low).maxCoeff(&axis);
  const int left_parts = parts / 2;
  const auto middle = first + (last - first) * left_parts / parts;
  // Ties broken by element number: the same split on every process.
  std::nth_element(first, middle, last, [&](int a, int b) {
    return centroids[a][axis] < centroids[b][axis] || (centroids[a][axis] == centroids[b][axis] && a < b);
  });
  bisect(first, middle, part, left_parts, centroids, element_part);
  bisect(middle, last, part + left_parts, parts - left_parts, centroids, element_part);
}

} // namespace

Partition partition_mesh(const mesh::TetMesh& mesh, int processes, int process) {
  Partition p;
  p.processes = processes;
  p.process = process;
  const int nodes = mesh.node_count();
  if (processes == 1) {
    p.elements.resize(mesh.tets.size());
    std::iota(p.elements.begin(), p.elements.end(), 0);
    p.number.resize(nodes);
    std::iota(p.number.begin(), p.number.end(), 0);
    p.node = p.number;
    p.end = nodes;
    return p;
  }
  std::vector<mesh::Point> centroids(mesh.tets.size());
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    centroids[e].setZero();
    for (int v : mesh.tets[e])
      centroids[e] += 0.25 * mesh.nodes[v];
  }
  std::vector<int> order(mesh.tets.size()), element_part(mesh.tets.size());
  std::iota(order.begin(), order.end(), 0);
  bisect(order.begin(), order.end(), 0, processes, centroids, element_part);

  std::vector<int> node_part(nodes, processes);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    for (int v : mesh.tets[e])
      node_part[v] = std::min(node_part[v], element_part[e]);
    if (element_part[e] == process) p.elements.push_back(static_cast<int>(e));
  }
  // Part by part, each part's nodes in mesh order.
  p.node.resize(nodes);
  std::iota(p.node.begin(), p.node.end(), 0);
  std::stable_sort(p.node.begin(), p.node.end(), [&](int a, int b) { return node_part[a] < node_part[b]; });
  p.number.resize(nodes);
  for (int k = 0; k < nodes; ++k)
    p.number[p.node[k]] = k;
  p.first = static_cast<int>(
      std::lower_bound(p.node.begin(), p.node.end(), process, [&](int n, int part) { return node_part[n] < part; }) -
      p.node.begin());
  p.end = static_cast<int>(std::lower_bound(p.node.begin(), p.node.end(), process + 1,
                                            [&](int n, int part) { return node_part[n] < part; }) -
                           p.node.begin());
  return p;
}

} // namespace anvil::fem
