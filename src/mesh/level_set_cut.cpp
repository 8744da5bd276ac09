#include "anvil/mesh/level_set_cut.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace anvil::mesh {
namespace {

/// The root of `level` on segment [xa, xb], where it goes from fa < 0 to
/// fb > 0: regula falsi (Illinois), from the linear estimate, exact at once
/// for a plane.
double root_on_edge(const Point& xa, const Point& xb, double fa, double fb,
                    const std::function<double(const Point&)>& level) {
  double lo = 0.0, hi = 1.0;
  double t = fa / (fa - fb);
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double f = level(xa + t * (xb - xa));
    if (f == 0.0) break;
    if (f < 0.0)
      lo = t, fa = f, fb *= 0.5;
    else
      hi = t, fb = f, fa *= 0.5;
    const double next = lo + (hi - lo) * fa / (fa - fb);
    if (std::abs(next - t) < 1e-12) break;
    t = next;
  }
  return t;
}

/// Dompierre's three tets of the prism of node numbers v with triangles
/// (v0 v1 v2), (v3 v4 v5), vertex i joined to i + 3: the prism turned
/// (kTurn) so that its smallest number comes first, each quadrilateral face
/// split along the diagonal through its smallest number.
void split_prism(const std::array<int, 6>& v, std::vector<Tet>& out) {
  static constexpr int kTurn[6][6] = {{0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3}, {2, 0, 1, 5, 3, 4},
                                      {3, 5, 4, 0, 2, 1}, {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0}};
  const int first = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
  std::array<int, 6> p;
  for (int i = 0; i < 6; ++i)
    p[i] = v[kTurn[first][i]];
  if (std::min(p[1], p[5]) < std::min(p[2], p[4])) {
    out.push_back({p[0], p[1], p[2], p[5]});
    out.push_back({p[0], p[1], p[5], p[4]});
  } else {
    out.push_back({p[0], p[1], p[2], p[4]});
    out.push_back({p[0], p[4], p[2], p[5]});
  }
  out.push_back({p[0], p[4], p[5], p[3]});
}

/// The two tets of the pyramid with apex `apex` over the quadrilateral
/// (q0 q1 q2 q3), split along the diagonal through its smallest number.
void split_pyramid(int apex, const std::array<int, 4>& q, std::vector<Tet>& out) {
  const int first = static_cast<int>(std::min_element(q.begin(), q.end()) - q.begin());
  const int a = q[first], b = q[(first + 1) % 4], c = q[(first + 2) % 4], d = q[(first + 3) % 4];
  out.push_back({a, b, c, apex});
  out.push_back({a, c, d, apex});
}

} // namespace

LevelSetCut cut_by_level_set(const TetMesh& mesh, std::span<const double> phi,
                             const std::function<double(const Point&)>& level) {
  const int n = mesh.node_count();
  // Nodes in the input's numbering: the input's, then one a crossed edge.
  std::vector<Point> x = mesh.nodes;
  std::vector<NodeOrigin> origin(n);
  for (int i = 0; i < n; ++i)
    origin[i] = {i, i, 0.0};
  std::map<std::pair<int, int>, int> on_edge;
  auto cut_point = [&](int inside, int outside) { // the node where edge (inside, outside) meets the cut
    const auto [it, added] = on_edge.try_emplace(std::minmax(inside, outside), static_cast<int>(x.size()));
    if (added) {
      const double t = root_on_edge(x[inside], x[outside], phi[inside], phi[outside], level);
      x.push_back(x[inside] + t * (x[outside] - x[inside]));
      origin.push_back({inside, outside, t});
    }
    return it->second;
  };
  LevelSetCut out;
  std::vector<Tet> pieces;
  std::vector<int> in, on, off; // the element's nodes inside, on and beyond the cut
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const Tet& t = mesh.tets[e];
    in.clear(), on.clear(), off.clear();
    for (int v : t)
      (phi[v] < 0.0 ? in : phi[v] > 0.0 ? off : on).push_back(v);
    pieces.clear();
    if (off.empty()) {
      const bool kept = !in.empty() || level(0.25 * (x[t[0]] + x[t[1]] + x[t[2]] + x[t[3]])) < 0.0;
      if (kept) pieces.push_back(t);
    } else if (in.size() == 1) { // a tet: the inside node, the cut's nodes, the cut points of its edges
      std::vector<int> v{in[0]};
      v.insert(v.end(), on.begin(), on.end());
      for (int o : off)
        v.push_back(cut_point(in[0], o));
      pieces.push_back({v[0], v[1], v[2], v[3]});
    } else if (in.size() == 2 && off.size() == 2) {
      split_prism({in[0], cut_point(in[0], off[0]), cut_point(in[0], off[1]), in[1], cut_point(in[1], off[0]),
                   cut_point(in[1], off[1])},
                  pieces);
    } else if (in.size() == 2) { // one on the cut: a pyramid over the face (in, in, off)
      split_pyramid(on[0], {in[0], in[1], cut_point(in[1], off[0]), cut_point(in[0], off[0])}, pieces);
    } else if (in.size() == 3) {
      split_prism({in[0], in[1], in[2], cut_point(in[0], off[0]), cut_point(in[1], off[0]), cut_point(in[2], off[0])},
                  pieces);
    }
    for (Tet& piece : pieces) {
      if (signed_volume(x[piece[0]], x[piece[1]], x[piece[2]], x[piece[3]]) < 0.0) std::swap(piece[2], piece[3]);
      out.mesh.tets.push_back(piece);
      out.parent.push_back(e);
    }
  }
  // The nodes used, renumbered in order.
  std::vector<int> number(x.size(), -1);
  for (const Tet& t : out.mesh.tets)
    for (int v : t)
      number[v] = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (number[i] == 0) {
      number[i] = out.mesh.node_count();
      out.mesh.nodes.push_back(x[i]);
      out.origin.push_back(origin[i]);
    }
  for (Tet& t : out.mesh.tets)
    for (int& v : t)
      v = number[v];
  // A face of a piece lies on a boundary face of the input when each of its
  // nodes is a node of that face or lies on one of its edges: it takes its tag.
  std::unordered_map<std::uint64_t, int> tag_of;
  auto key = [n](std::array<int, 3> f) {
    std::sort(f.begin(), f.end());
    return (std::uint64_t(f[0]) * std::uint64_t(n) + std::uint64_t(f[1])) * std::uint64_t(n) + std::uint64_t(f[2]);
  };
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    if (mesh.boundary_tags[f] != 0) tag_of.emplace(key(mesh.boundary_faces[f]), mesh.boundary_tags[f]);
  std::vector<Triangle> tagged;
  std::vector<int> tags;
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (std::size_t p = 0; p < out.mesh.tets.size(); ++p) {
    const Tet& whole = mesh.tets[out.parent[p]];
    const Tet& piece = out.mesh.tets[p];
    for (const auto& face : kFace) {
      const Triangle f{whole[face[0]], whole[face[1]], whole[face[2]]};
      const auto it = tag_of.find(key(f));
      if (it == tag_of.end()) continue;
      for (const auto& side : kFace) {
        const Triangle g{piece[side[0]], piece[side[1]], piece[side[2]]};
        const bool lies_on = std::all_of(g.begin(), g.end(), [&](int v) {
          const NodeOrigin& o = out.origin[v];
          return std::find(f.begin(), f.end(), o.a) != f.end() && std::find(f.begin(), f.end(), o.b) != f.end();
        });
        if (lies_on) tagged.push_back(g), tags.push_back(it->second);
      }
    }
  }
  build_boundary(out.mesh, tagged, tags);
  return out;
}

} // namespace anvil::mesh
