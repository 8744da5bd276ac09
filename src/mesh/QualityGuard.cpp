#include "anvil/mesh/QualityGuard.h"

#include "anvil/core/DisjointSets.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>

namespace anvil::mesh {

QualityGuard::QualityGuard(const TetMesh& mesh) : tets_of_(tets_around_nodes(mesh)) {}

double QualityGuard::worst_around(const TetMesh& mesh, int node) const {
  double worst = 1.0;
  for (int e : tets_of_[node])
    worst = std::min(worst, quality(mesh, e));
  return worst;
}

bool QualityGuard::move(TetMesh& mesh, int node, const Point& to, double floor) const {
  const double lowest = std::min(worst_around(mesh, node), floor);
  const Point was = mesh.nodes[node];
  mesh.nodes[node] = to;
  if (const double worst = worst_around(mesh, node); worst >= lowest && worst > 0.0) return true;
  mesh.nodes[node] = was;
  return false;
}

std::vector<double> QualityGuard::move_carrying(TetMesh& mesh, std::span<const int> nodes, std::span<const Point> to,
                                                std::span<const char> fixed, int rings, double floor) const {
  std::vector<double> taken(nodes.size(), 0.0);
  // Groups: the nodes that share an element (union-find over `nodes`).
  std::vector<int> slot(mesh.nodes.size(), -1); // a node's index in `nodes`
  for (std::size_t k = 0; k < nodes.size(); ++k)
    slot[nodes[k]] = static_cast<int>(k);
  DisjointSets sets(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k)
    for (int e : tets_of_[nodes[k]])
      for (int other : mesh.tets[e])
        if (slot[other] >= 0) sets.join(slot[other], static_cast<int>(k));
  std::vector<std::vector<int>> groups(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k)
    groups[sets.root(static_cast<int>(k))].push_back(static_cast<int>(k));

  std::vector<int> ring(mesh.nodes.size(), -1);
  std::vector<Eigen::Vector3d> by(mesh.nodes.size(), Eigen::Vector3d::Zero());
  std::vector<char> checked(mesh.tets.size(), 0);
  std::vector<int> zone, elements;
  std::vector<Point> was;
  for (const std::vector<int>& group : groups) {
    if (group.empty()) continue;
    zone.clear();
    for (int k : group) {
      ring[nodes[k]] = 0;
      by[nodes[k]] = to[k] - mesh.nodes[nodes[k]];
      zone.push_back(nodes[k]);
    }
    // Ring by ring into the free interior, each node taking the mean move
    // of its neighbours one ring nearer, lowered by its ring's weight.
    for (int r = 1, first = 0; r <= rings; ++r) {
      const int last = static_cast<int>(zone.size());
      for (int z = first; z < last; ++z)
        for (int e : tets_of_[zone[z]])
          for (int n : mesh.tets[e])
            if (ring[n] < 0 && !fixed[n]) ring[n] = r, zone.push_back(n);
      for (int z = last; z < static_cast<int>(zone.size()); ++z) {
        const int n = zone[z];
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        int count = 0;
        for (int e : tets_of_[n])
          for (int m : mesh.tets[e])
            if (ring[m] == r - 1) sum += by[m], ++count;
        by[n] = sum * (double(rings + 1 - r) / double((rings + 2 - r) * count));
      }
      first = last;
    }
    elements.clear();
    for (int n : zone)
      for (int e : tets_of_[n])
        if (!checked[e]) checked[e] = 1, elements.push_back(e);
    double before = 1.0;
    for (int e : elements)
      before = std::min(before, quality(mesh, e));
    const double lowest = std::min(before, floor);
    was.clear();
    for (int n : zone)
      was.push_back(mesh.nodes[n]);
    double fraction = 1.0;
    for (; fraction >= 0.25; fraction *= 0.5) {
      for (std::size_t z = 0; z < zone.size(); ++z)
        mesh.nodes[zone[z]] = was[z] + fraction * by[zone[z]];
      double worst = 1.0;
      for (int e : elements)
        worst = std::min(worst, quality(mesh, e));
      if (worst >= lowest && worst > 0.0) break;
    }
    if (fraction < 0.25) {
      fraction = 0.0;
      for (std::size_t z = 0; z < zone.size(); ++z)
        mesh.nodes[zone[z]] = was[z];
    }
    for (int k : group)
      taken[k] = fraction;
    for (int n : zone)
      ring[n] = -1;
    for (int e : elements)
      checked[e] = 0;
  }
  return taken;
}

} // namespace anvil::mesh
