#include "anvil/mesh/restore_volume.h"

#include "anvil/mesh/tet_geometry.h"

namespace anvil::mesh {

double restore_volume(TetMesh& mesh, double target, const std::vector<char>& movable) {
  const std::vector<Point> normal = node_area_vectors(mesh);
  // A tet the move would invert keeps its nodes where they are and the
  // others move further: a flat tet on the surface, its nodes' normals
  // apart across a crease (CGAL leaves some at quality 1e-3), turns inside
  // out under a move of a hundredth of its edge, and the remesher refuses
  // the mesh (on a trial path of the connecting rod, every try of a whole
  // remesh was refused for such a tet, and the run stalled).
  std::vector<char> moves = movable;
  std::vector<Point> unit(normal.size());
  for (std::size_t v = 0; v < normal.size(); ++v)
    unit[v] = normal[v].normalized();
  std::vector<int> moving_tets;
  for (int e = 0; e < mesh.tet_count(); ++e)
    for (int v : mesh.tets[e])
      if (moves[v]) {
        moving_tets.push_back(e);
        break;
      }
  double distance = 0.0;
  for (int pass = 0; pass < 2; ++pass) { // the second pass removes the second-order rest
    const double missing = target - volume(mesh);
    for (;;) {
      double area = 0.0;
      for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
        if (moves[v]) area += normal[v].norm();
      if (area <= 0.0) return distance;
      const double shift = missing / area;
      auto moved = [&](int v) -> Point { return moves[v] ? Point(mesh.nodes[v] + shift * unit[v]) : mesh.nodes[v]; };
      std::vector<int> held; // judged on this round's move, then held together
      for (int e : moving_tets) {
        const Tet& t = mesh.tets[e];
        if (signed_volume(mesh, e) <= 0.0 || signed_volume(moved(t[0]), moved(t[1]), moved(t[2]), moved(t[3])) > 0.0)
          continue;
        for (int v : t)
          if (moves[v]) held.push_back(v);
      }
      if (!held.empty()) { // again without them (each round holds at least one node)
        for (int v : held)
          moves[v] = 0;
        continue;
      }
      for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
        if (moves[v]) mesh.nodes[v] += shift * unit[v];
      distance += shift;
      break;
    }
  }
  return distance;
}

} // namespace anvil::mesh
