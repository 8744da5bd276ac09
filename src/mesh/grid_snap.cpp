#include "anvil/mesh/grid_snap.h"

#include "anvil/mesh/tet_geometry.h"

#include <cmath>
#include <vector>

namespace anvil::mesh {
namespace {

/// Grid steps per element length at most. Runs on 1 and 2 processes carry
/// the nodes apart by round-off, under a nanometre, until the contact's
/// active set takes another side at one node (docs/remeshing.md): a step of
/// h/64 (16 µm) is seldom crossed by the first, and rounding by half a step
/// spoils only a tet flatter than about quality 0.02. A grid of h/32 parted
/// the hub flange's runs as early.
constexpr double kCellsPerElement = 64.0;
/// Share of its own volume a tet keeps when its nodes move to or from the grid.
constexpr double kKeptVolume = 0.5;

std::array<double, 3> key(const Point& x) {
  return {x.x(), x.y(), x.z()};
}

/// Nodes of `mesh` moved from `before` that leave one of their tets below
/// kKeptVolume of its volume `was` there (one per tet).
std::vector<char> spoiling(const TetMesh& mesh, const std::vector<Point>& before, const std::vector<double>& was) {
  std::vector<char> out(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet& t = mesh.tets[e];
    const double now = signed_volume(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
    if (now < kKeptVolume * was[e])
      for (int v : t)
        if (mesh.nodes[v] != before[v]) out[v] = 1;
  }
  return out;
}

/// Moves the nodes of `mesh` to `to` where they may, back to `from` where
/// a tet would be spoiled, until none is. Returns the nodes moved.
int move_where_possible(TetMesh& mesh, const std::vector<Point>& from, const std::vector<Point>& to,
                        const std::vector<char>& wanted) {
  std::vector<double> was(mesh.tets.size());
  for (std::size_t e = 0; e < was.size(); ++e)
    was[e] = signed_volume(mesh, static_cast<int>(e)); // mesh.nodes are `from` here
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (wanted[i]) mesh.nodes[i] = to[i];
  for (bool again = true; again;) {
    again = false;
    const std::vector<char> back = spoiling(mesh, from, was);
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
      if (back[i]) {
        mesh.nodes[i] = from[i];
        again = true;
      }
  }
  int moved = 0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    moved += mesh.nodes[i] != from[i];
  return moved;
}

} // namespace

double snap_spacing(double h) {
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(h / kCellsPerElement))));
}

double grid_offset(std::size_t k) {
  // The midpoints of grid j lie frac((k − j) φ)/2 of a step from the half
  // steps of grid k: at least 0.07 of a step for the three grids before.
  constexpr double kShift = 0.30901699437494745; // (φ − 1)/2
  const double share = static_cast<double>(k) * kShift;
  return share - std::floor(share);
}

Grid remesh_grid(double h, std::size_t k) {
  return {snap_spacing(h), grid_offset(k)};
}

GridSnap::GridSnap(const TetMesh& body, Grid grid) : snapped_(body) {
  const auto [spacing, offset] = grid;
  if (!(spacing > 0.0)) return; // no grid: the nodes as they are, nothing to give back
  const std::size_t n = body.nodes.size();
  std::vector<Point> rounded(n);
  std::map<std::array<double, 3>, int> on_point;
  for (std::size_t i = 0; i < n; ++i) {
    rounded[i] = ((body.nodes[i] / spacing).array() - offset).round().matrix() * spacing;
    rounded[i].array() += offset * spacing;
    ++on_point[key(rounded[i])];
  }
  std::vector<char> wanted(n);
  for (std::size_t i = 0; i < n; ++i)
    wanted[i] = on_point[key(rounded[i])] == 1;
  move_where_possible(snapped_, body.nodes, rounded, wanted);
  for (std::size_t i = 0; i < n; ++i)
    exact_.emplace(key(snapped_.nodes[i]), body.nodes[i]);
}

int GridSnap::restore(TetMesh& remeshed) const {
  const std::vector<Point> before = remeshed.nodes;
  std::vector<Point> exact = before;
  std::vector<char> wanted(before.size(), 0);
  for (std::size_t i = 0; i < before.size(); ++i)
    if (const auto at = exact_.find(key(before[i])); at != exact_.end()) {
      exact[i] = at->second;
      wanted[i] = 1;
    }
  return move_where_possible(remeshed, before, exact, wanted);
}

} // namespace anvil::mesh
