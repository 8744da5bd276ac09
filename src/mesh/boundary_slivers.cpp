#include "anvil/mesh/boundary_slivers.h"

#include "anvil/mesh/flat_tags.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace anvil::mesh {

namespace {

using Edge = std::array<int, 2>;

Edge edge(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

/// One pass over the tets: removes those that qualify and touch no node of
/// another removed in the pass (each decision sees the surface as it is).
/// Returns how many it removed; `old_node` becomes, per node left, its
/// number before.
int peel_once(TetMesh& mesh, double below, double ears_below, int frozen, std::vector<int>& old_node) {
  std::map<Triangle, int> face_of; // sorted vertices -> boundary face
  std::set<Edge> boundary_edges;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const Triangle& t = mesh.boundary_faces[f];
    face_of.emplace(sorted(t), static_cast<int>(f));
    for (int k = 0; k < 3; ++k)
      boundary_edges.insert(edge(t[k], t[(k + 1) % 3]));
  }
  std::vector<int> uses(mesh.nodes.size(), 0);
  for (const Tet& t : mesh.tets)
    for (int v : t)
      ++uses[v];

  std::vector<std::vector<int>> around; // the tets at each node, made when an ear asks
  // Whether the tet across face `inner` of tet `e` is below `below`.
  auto covers_poorer = [&](int e, const Triangle& inner) {
    if (around.empty()) around = tets_around_nodes(mesh);
    for (int other : around[inner[0]]) {
      const Tet& o = mesh.tets[other];
      if (other != e && std::count(o.begin(), o.end(), inner[1]) && std::count(o.begin(), o.end(), inner[2]))
        return quality(mesh, other) < below;
    }
    return false;
  };
  std::vector<char> removed(mesh.tets.size(), 0), touched(mesh.nodes.size(), 0);
  std::vector<Triangle> tagged = mesh.boundary_faces;
  std::vector<int> tags = mesh.boundary_tags;
  tags.resize(tagged.size(), 0);
  const std::map<int, std::pair<Point, double>> planes = flat_tags(mesh);
  // `tag` fits `face` unless the tag is flat and the face is off its plane.
  auto fits = [&](int tag, const Triangle& face) {
    const auto plane = planes.find(tag);
    return plane == planes.end() || in_plane(mesh, face, plane->second);
  };
  int count = 0;
  for (int e = frozen; e < mesh.tet_count(); ++e) {
    const Tet& t = mesh.tets[e];
    if (touched[t[0]] || touched[t[1]] || touched[t[2]] || touched[t[3]]) continue;
    const double q = quality(mesh, e);
    if (q >= std::max(below, ears_below)) continue;
    std::array<int, 4> boundary_face{-1, -1, -1, -1}; // per local face k (opposite vertex k)
    int on_boundary = 0;
    for (int k = 0; k < 4; ++k) {
      const auto found = face_of.find(sorted(tet_face(t, k)));
      if (found != face_of.end()) boundary_face[k] = found->second, ++on_boundary;
    }
    int apex = -1; // with three boundary faces: the node they share, opposite the inner face
    if (on_boundary == 3) {
      apex = 0;
      while (boundary_face[apex] >= 0)
        ++apex;
      if (uses[t[apex]] != 1) continue;
      // An ear above `below` (and so below `ears_below`) goes only where it covers a poorer tet.
      if (q >= below && !covers_poorer(e, tet_face(t, apex))) continue;
    } else if (q >= below) {
      continue;
    } else if (on_boundary == 2) {
      // The inner faces share the edge of the two nodes the boundary faces are opposite to.
      std::array<int, 2> ends{};
      for (int k = 0, n = 0; k < 4; ++k)
        if (boundary_face[k] >= 0) ends[n++] = t[k];
      if (boundary_edges.count(edge(ends[0], ends[1])) > 0) continue;
    } else {
      continue;
    }
    // The uncovered faces, each tagged as the removed boundary face whose
    // outward normal is nearest its own (minus its normal out of this tet)
    // among those whose tag fits it; none fits: the tet stays.
    std::array<Triangle, 2> uncovered{};
    std::array<int, 2> uncovered_tag{};
    int n_uncovered = 0;
    bool all_fit = true;
    for (int k = 0; k < 4 && all_fit; ++k) {
      if (boundary_face[k] >= 0) continue;
      const Triangle inner = tet_face(t, k);
      const Point out = -area_vector(mesh, inner);
      int tag = 0;
      double best = -std::numeric_limits<double>::infinity();
      for (int j = 0; j < 4; ++j) {
        if (boundary_face[j] < 0 || !fits(tags[boundary_face[j]], inner)) continue;
        const double facing = area_vector(mesh, mesh.boundary_faces[boundary_face[j]]).normalized().dot(out);
        if (facing > best) best = facing, tag = tags[boundary_face[j]];
      }
      all_fit = best > -std::numeric_limits<double>::infinity();
      uncovered[n_uncovered] = inner;
      uncovered_tag[n_uncovered++] = tag;
    }
    if (!all_fit) continue;
    removed[e] = 1;
    for (int v : t)
      touched[v] = 1;
    ++count;
    for (int k = 0; k < n_uncovered; ++k) {
      tagged.push_back(uncovered[k]);
      tags.push_back(uncovered_tag[k]);
    }
  }
  if (count == 0) return 0;

  old_node = remove_tets(mesh, removed, tagged, tags);
  return count;
}

} // namespace

int peel_boundary_slivers(TetMesh& mesh, double below, double ears_below, int frozen, std::vector<int>* old_node) {
  int peeled = 0;
  if (old_node) {
    old_node->resize(mesh.nodes.size());
    for (std::size_t n = 0; n < old_node->size(); ++n)
      (*old_node)[n] = static_cast<int>(n);
  }
  // A pass uncovers at most the tets under the ones it removed; a few passes
  // reach every sliver stacked on a crease.
  constexpr int kMostPasses = 8;
  for (int pass = 0; pass < kMostPasses; ++pass) {
    std::vector<int> left;
    const int now = peel_once(mesh, below, ears_below, frozen, left);
    if (now == 0) break;
    peeled += now;
    if (!old_node) continue;
    for (std::size_t n = 0; n < left.size(); ++n) // left[n] >= n: read before it is written
      (*old_node)[n] = (*old_node)[left[n]];
    old_node->resize(left.size());
  }
  return peeled;
}

} // namespace anvil::mesh
