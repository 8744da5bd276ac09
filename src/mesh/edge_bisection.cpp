#include "anvil/mesh/edge_bisection.h"

#include <algorithm>
#include <numeric>

namespace anvil::mesh {
namespace {

/// Replaces `element`'s vertex `from` by `to` (an element on edge from-to's
/// line keeps its orientation: the new vertex lies on an edge it had).
template <class Element> Element with(Element element, int from, int to) {
  std::replace(element.begin(), element.end(), from, to);
  return element;
}

template <class Element> bool holds(const Element& element, int a, int b) {
  return std::find(element.begin(), element.end(), a) != element.end() &&
         std::find(element.begin(), element.end(), b) != element.end();
}

} // namespace

Bisection bisect_edges(TetMesh& mesh, const std::vector<std::array<int, 2>>& edges) {
  Bisection done;
  done.parent.resize(mesh.tets.size());
  std::iota(done.parent.begin(), done.parent.end(), 0);
  for (const auto& [a, b] : edges) {
    const int m = mesh.node_count();
    bool on_mesh = false;
    for (std::size_t e = 0, count = mesh.tets.size(); e < count; ++e) {
      if (!holds(mesh.tets[e], a, b)) continue;
      on_mesh = true;
      mesh.tets.push_back(with(mesh.tets[e], a, m));
      done.parent.push_back(done.parent[e]);
      mesh.tets[e] = with(mesh.tets[e], b, m);
    }
    if (!on_mesh) continue;
    mesh.nodes.push_back(0.5 * (mesh.nodes[a] + mesh.nodes[b]));
    done.midpoint_of.push_back({a, b});
    for (std::size_t f = 0, count = mesh.boundary_faces.size(); f < count; ++f) {
      if (!holds(mesh.boundary_faces[f], a, b)) continue;
      mesh.boundary_faces.push_back(with(mesh.boundary_faces[f], a, m));
      mesh.boundary_tags.push_back(mesh.boundary_tags[f]);
      mesh.boundary_faces[f] = with(mesh.boundary_faces[f], b, m);
    }
  }
  return done;
}

} // namespace anvil::mesh
