#include "anvil/mesh/manifold.h"

#include "anvil/core/DisjointSets.h"
#include "anvil/mesh/flat_tags.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <map>
#include <utility>
#include <vector>

namespace anvil::mesh {

namespace {

using Edge = std::pair<int, int>;

std::string nodes_text(std::initializer_list<int> nodes) {
  std::string text;
  for (int v : nodes)
    text += (text.empty() ? "" : ", ") + std::to_string(v + 1);
  return text;
}

/// Runs of equal values in the sorted `values`: calls `run(value, count)` for each.
template <class T, class Run> void for_each_run(const std::vector<T>& values, Run run) {
  for (std::size_t i = 0; i < values.size();) {
    std::size_t j = i;
    while (j < values.size() && values[j] == values[i])
      ++j;
    run(values[i], j - i);
    i = j;
  }
}

/// The tets' faces used once (sorted vertices), and those used more than twice.
struct FaceUse {
  std::vector<Triangle> boundary;
  std::vector<std::pair<Triangle, std::size_t>> crowded;
};

FaceUse face_use(const TetMesh& mesh) {
  std::vector<Triangle> faces;
  faces.reserve(4 * mesh.tets.size());
  for (const Tet& t : mesh.tets)
    for (const auto& local : kFaceVertices)
      faces.push_back(sorted({t[local[0]], t[local[1]], t[local[2]]}));
  std::sort(faces.begin(), faces.end());
  FaceUse use;
  for_each_run(faces, [&](const Triangle& f, std::size_t count) {
    if (count == 1) use.boundary.push_back(f);
    if (count > 2) use.crowded.emplace_back(f, count);
  });
  return use;
}

/// Boundary edges on other than two of the faces `boundary`, with how many.
std::vector<std::pair<Edge, std::size_t>> odd_edges(const std::vector<Triangle>& boundary) {
  std::vector<Edge> edges;
  edges.reserve(3 * boundary.size());
  for (const Triangle& f : boundary)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<Edge, std::size_t>> odd;
  for_each_run(edges, [&](const Edge& e, std::size_t count) {
    if (count != 2) odd.emplace_back(e, count);
  });
  return odd;
}

/// Nodes whose faces of `boundary` form more than one fan. Every boundary
/// edge must be on two faces: around a node the faces' far edges (its link)
/// then form closed loops, one unless the node is a pinch.
std::vector<int> pinched_nodes(const std::vector<Triangle>& boundary, std::size_t node_count) {
  std::vector<std::vector<Edge>> link(node_count);
  for (const Triangle& f : boundary)
    for (int k = 0; k < 3; ++k)
      link[f[k]].emplace_back(f[(k + 1) % 3], f[(k + 2) % 3]);
  std::vector<int> pinched;
  for (std::size_t v = 0; v < link.size(); ++v) {
    const std::vector<Edge>& around = link[v];
    if (around.empty()) continue;
    // Walk the loop through the first link edge; count the edges it passes.
    const int start = around[0].first;
    int at = around[0].second;
    std::size_t from = 0, walked = 1;
    while (at != start && walked <= around.size()) {
      std::size_t next = 0;
      while (next < around.size() && (next == from || (around[next].first != at && around[next].second != at)))
        ++next;
      if (next == around.size()) break;
      at = around[next].first == at ? around[next].second : around[next].first;
      from = next;
      ++walked;
    }
    if (walked != around.size()) pinched.push_back(static_cast<int>(v));
  }
  return pinched;
}

/// The tets in `star`, which all hold some nodes, grouped into sets joined
/// through faces that hold those nodes too (two such tets share three
/// nodes); flags in `remove` all but the group of largest volume.
void keep_largest_group(const TetMesh& mesh, const std::vector<int>& star, std::vector<char>& remove) {
  DisjointSets group(star.size());
  for (std::size_t i = 0; i < star.size(); ++i)
    for (std::size_t j = i + 1; j < star.size(); ++j) {
      int common = 0;
      for (int v : mesh.tets[star[i]])
        common += static_cast<int>(std::count(mesh.tets[star[j]].begin(), mesh.tets[star[j]].end(), v));
      if (common == 3) group.join(int(i), int(j));
    }
  std::vector<double> volume(star.size(), 0.0);
  for (std::size_t i = 0; i < star.size(); ++i)
    volume[group.root(int(i))] += signed_volume(mesh, star[i]);
  const int keep = static_cast<int>(std::max_element(volume.begin(), volume.end()) - volume.begin());
  for (std::size_t i = 0; i < star.size(); ++i)
    if (group.root(int(i)) != keep) remove[star[i]] = 1;
}

/// Removes the tets `remove` flags (mesh::remove_tets). A face
/// they uncover takes the tag of the removed tet's boundary face that faces
/// most the same way among those whose tag fits it (a flat tag only on its
/// plane), else 0.
void remove_with_tags(TetMesh& mesh, const std::vector<char>& remove) {
  std::vector<Triangle> tagged = mesh.boundary_faces;
  std::vector<int> tags = mesh.boundary_tags;
  tags.resize(tagged.size(), 0);
  std::vector<std::pair<Triangle, int>> boundary_key; // sorted vertices, boundary face
  for (std::size_t f = 0; f < tagged.size(); ++f)
    boundary_key.emplace_back(sorted(tagged[f]), static_cast<int>(f));
  std::sort(boundary_key.begin(), boundary_key.end());
  auto boundary_face = [&](const Triangle& face) {
    const Triangle key = sorted(face);
    const auto at = std::lower_bound(boundary_key.begin(), boundary_key.end(), std::make_pair(key, -1));
    return at != boundary_key.end() && at->first == key ? at->second : -1;
  };
  const std::map<int, std::pair<Point, double>> planes = flat_tags(mesh);
  for (int e = 0; e < mesh.tet_count(); ++e) {
    if (!remove[e]) continue;
    const Tet& t = mesh.tets[e];
    std::array<Triangle, 4> faces;
    for (int k = 0; k < 4; ++k)
      faces[k] = tet_face(t, k);
    for (const Triangle& face : faces) {
      if (boundary_face(face) >= 0) continue; // goes with the tet
      // Uncovered (unless another removed tet is behind it: build_boundary
      // then ignores it); its outward normal is minus this tet's.
      const Point out = -area_vector(mesh, face).normalized();
      int tag = 0;
      double best = -2.0;
      for (const Triangle& other : faces) {
        const int b = boundary_face(other);
        if (b < 0) continue;
        const auto plane = planes.find(tags[b]);
        if (plane != planes.end() && !in_plane(mesh, face, plane->second)) continue;
        const double facing = area_vector(mesh, tagged[b]).normalized().dot(out);
        if (facing > best) best = facing, tag = tags[b];
      }
      tagged.push_back(face);
      tags.push_back(tag);
    }
  }
  remove_tets(mesh, remove, tagged, tags);
}

/// manifold_fault of a mesh of `node_count` nodes whose faces are `use`.
std::string manifold_fault(const FaceUse& use, std::size_t node_count) {
  if (!use.crowded.empty()) {
    const auto& [f, count] = use.crowded.front();
    return "the face of nodes " + nodes_text({f[0], f[1], f[2]}) + " is in " + std::to_string(count) + " tetrahedra";
  }
  if (const auto odd = odd_edges(use.boundary); !odd.empty()) {
    const auto& [e, count] = odd.front();
    return "the boundary edge of nodes " + nodes_text({e.first, e.second}) + " is on " + std::to_string(count) +
           " boundary faces";
  }
  if (const auto pinched = pinched_nodes(use.boundary, node_count); !pinched.empty())
    return "the boundary faces around node " + std::to_string(pinched.front() + 1) +
           " form more than one fan (two parts of the body touch there)";
  return {};
}

} // namespace

std::string manifold_fault(const TetMesh& mesh) {
  return manifold_fault(face_use(mesh), mesh.nodes.size());
}

bool is_ball(const TetMesh& mesh) {
  const FaceUse use = face_use(mesh);
  if (mesh.tets.empty() || !manifold_fault(use, mesh.nodes.size()).empty()) return false;
  // A manifold's boundary is closed surfaces; one sphere (connected, Euler
  // characteristic V − E + F = 2) bounds a ball: a second part, a hole
  // through or a cavity would add a surface or lower the characteristic.
  const std::vector<Triangle>& boundary = use.boundary;
  std::vector<int> root(mesh.nodes.size(), -1);
  auto find = [&](int v) {
    while (root[v] != v)
      v = root[v] = root[root[v]];
    return v;
  };
  long vertices = 0;
  for (const Triangle& f : boundary)
    for (int v : f)
      if (root[v] < 0) root[v] = v, ++vertices;
  for (const Triangle& f : boundary)
    root[find(f[1])] = find(f[0]), root[find(f[2])] = find(f[0]);
  long parts = 0;
  for (std::size_t v = 0; v < root.size(); ++v)
    parts += root[v] == static_cast<int>(v);
  // Every boundary edge is on two faces (manifold_fault): E = 3F/2.
  const long faces = static_cast<long>(boundary.size()), edges = 3 * faces / 2;
  return parts == 1 && vertices - edges + faces == 2;
}

int cut_pinches(TetMesh& mesh) {
  int removed = 0;
  // Each pass cuts the pinches it sees; a cut can leave a pinch at a node of
  // the removed tets, which the next pass sees.
  constexpr int kMostPasses = 8;
  for (int pass = 0; pass < kMostPasses; ++pass) {
    const FaceUse use = face_use(mesh);
    if (!use.crowded.empty()) break; // not a pinch: no cut mends it
    const auto odd = odd_edges(use.boundary);
    const std::vector<int> pinched = odd.empty() ? pinched_nodes(use.boundary, mesh.nodes.size()) : std::vector<int>{};
    if (odd.empty() && pinched.empty()) break;
    const std::vector<std::vector<int>> around = tets_around_nodes(mesh);
    std::vector<char> remove(mesh.tets.size(), 0);
    for (const auto& [e, count] : odd) {
      std::vector<int> star;
      for (int t : around[e.first])
        if (std::count(mesh.tets[t].begin(), mesh.tets[t].end(), e.second) > 0) star.push_back(t);
      keep_largest_group(mesh, star, remove);
    }
    for (int v : pinched)
      keep_largest_group(mesh, around[v], remove);
    const int now = static_cast<int>(std::count(remove.begin(), remove.end(), 1));
    if (now == 0 || now == mesh.tet_count()) break;
    remove_with_tags(mesh, remove);
    removed += now;
  }
  return removed;
}

} // namespace anvil::mesh
