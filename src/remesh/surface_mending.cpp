#include "anvil/remesh/surface_mending.h"

#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/field_transfer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>

namespace anvil::remesh {
namespace {

/// Passes over the poor elements: a flip changes the elements around it,
/// and an element next to one flipped in a pass waits for the next.
constexpr int kPasses = 4;

/// The face of `t` opposite its vertex `v`, its normal pointing out of `t`.
mesh::Triangle face_opposite(const mesh::Tet& t, int v) {
  const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
  return mesh::tet_face(t, k);
}

/// One mending, not yet made: elements replaced by others, surface
/// triangles by others.
struct Change {
  std::vector<int> shell;                ///< the tets replaced
  std::vector<mesh::Tet> made;           ///< those that replace them
  std::vector<int> old_faces;            ///< the boundary faces replaced
  std::vector<mesh::Triangle> new_faces; ///< outward, with the tag of the first old face
  int gone = -1;                         ///< a node no tet uses any more (a collapse)
  double worst_shell = 1.0, worst_made = 1.0;
};

/// Appends to each of `fields` (one value a tet of `body`) its values on the
/// tets `change` makes, by Anvil's transfer from the tets it replaces
/// (conservative, peaks kept: field_transfer.h).
void transfer_fields(const mesh::TetMesh& body, const Change& change, const std::vector<std::vector<double>*>& fields) {
  if (change.made.empty() || fields.empty()) return;
  std::vector<mesh::Tet> replaced;
  for (int e : change.shell)
    replaced.push_back(body.tets[e]);
  const mesh::TetMesh shell = mesh::tets_mesh(body.nodes, replaced), made = mesh::tets_mesh(body.nodes, change.made);
  const PointLocator in_shell(shell);
  for (std::vector<double>* field : fields) {
    std::vector<double> values;
    for (int e : change.shell)
      values.push_back((*field)[e]);
    const std::vector<double> on_made = transfer_element(shell, values, in_shell, made);
    field->insert(field->end(), on_made.begin(), on_made.end());
  }
}

/// The body with its adjacency for one pass: changes within a pass touch
/// disjoint nodes, so what it holds stays true for the nodes not touched.
class MendingPass {
public:
  MendingPass(const mesh::TetMesh& body, double most_angle)
      : body_(body), around_(mesh::tets_around_nodes(body)), faces_at_(body.nodes.size()),
        min_cosine_(std::cos(most_angle * std::numbers::pi / 180.0)) {
    for (std::size_t f = 0; f < body.boundary_faces.size(); ++f) {
      const mesh::Triangle& t = body.boundary_faces[f];
      face_of_[mesh::sorted(t)] = static_cast<int>(f);
      for (int v : t)
        faces_at_[v].push_back(static_cast<int>(f));
    }
  }

  /// The boundary face number of triangle (a, b, c), or −1.
  int face(int a, int b, int c) const {
    const auto it = face_of_.find(mesh::sorted({a, b, c}));
    return it == face_of_.end() ? -1 : it->second;
  }

  /// The flip of surface edge ab of boundary face `f` (abc), if it is one
  /// (a simple shell, an edge cd that does not exist yet, a flat enough
  /// surface) whose new elements all have positive volume.
  std::optional<Change> flip(int f, int a, int b) const {
    const mesh::Triangle& abc = body_.boundary_faces[f];
    const int c = abc[0] + abc[1] + abc[2] - a - b;
    const std::vector<std::pair<int, std::array<int, 2>>> shell = shell_of(a, b);
    // The ring c = w0, w1, ..., wk = d, walked through the shell from abc.
    std::vector<int> ring{c};
    Change out;
    std::vector<char> used(shell.size(), 0);
    for (;;) {
      int next = -1;
      for (std::size_t s = 0; s < shell.size() && next < 0; ++s)
        if (!used[s] && (shell[s].second[0] == ring.back() || shell[s].second[1] == ring.back()))
          next = static_cast<int>(s);
      if (next < 0) break;
      used[next] = 1;
      out.shell.push_back(shell[next].first);
      const auto& w = shell[next].second;
      ring.push_back(w[0] == ring.back() ? w[1] : w[0]);
    }
    const int d = ring.back();
    const int abd = face(a, b, d);
    if (out.shell.size() != shell.size() || abd < 0 || abd == f) return std::nullopt;
    if (body_.boundary_tags[f] != body_.boundary_tags[abd]) return std::nullopt;
    const mesh::Point n1 = mesh::area_vector(body_, abc).normalized(),
                      n2 = mesh::area_vector(body_, body_.boundary_faces[abd]).normalized();
    if (n1.dot(n2) < min_cosine_) return std::nullopt;
    // cd must be a new edge (one shell element: not on the surface yet).
    if (out.shell.size() > 1)
      for (int e : around_[c]) {
        const mesh::Tet& t = body_.tets[e];
        if (std::find(t.begin(), t.end(), d) != t.end()) return std::nullopt;
      }
    for (int g : faces_at_[c]) {
      const mesh::Triangle& t = body_.boundary_faces[g];
      if (std::find(t.begin(), t.end(), d) != t.end()) return std::nullopt;
    }
    const auto& x = body_.nodes;
    // The ring turns positively about a -> b: (a, b, w_i, w_i+1) positive.
    int lo = a, hi = b;
    if (mesh::signed_volume(x[a], x[b], x[ring[0]], x[ring[1]]) < 0.0) std::swap(lo, hi);
    for (int e : out.shell)
      out.worst_shell = std::min(out.worst_shell, mesh::quality(body_, e));
    // The ring closed by cd is triangulated as a fan from the vertex that
    // gives the best elements; each triangle pqr joins hi as (p, q, r, hi)
    // and lo as (p, r, q, lo).
    const int n = static_cast<int>(ring.size());
    double best = -1.0;
    for (int j = 0; j < n; ++j) {
      std::vector<mesh::Tet> made;
      double worst = 1.0;
      for (int i = 0; i < n; ++i) {
        const int i1 = (i + 1) % n;
        if (i == j || i1 == j) continue;
        for (const mesh::Tet& t :
             {mesh::Tet{ring[j], ring[i], ring[i1], hi}, mesh::Tet{ring[j], ring[i1], ring[i], lo}}) {
          made.push_back(t);
          worst = std::min(worst, mesh::quality(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
        }
      }
      if (worst > best) best = worst, out.made = std::move(made);
    }
    out.worst_made = best;
    if (!(best > 0.0)) return std::nullopt;
    out.old_faces = {f, abd};
    out.new_faces.resize(2);
    if (out.made.empty()) {
      // One shell element taken off: acd and bcd become surface, facing
      // where it was.
      const mesh::Tet& t = body_.tets[out.shell[0]];
      for (int k = 0; k < 2; ++k) {
        const mesh::Triangle inner = face_opposite(t, k == 0 ? b : a);
        out.new_faces[k] = {inner[0], inner[2], inner[1]};
      }
    } else {
      for (int k = 0; k < 2; ++k) {
        const int apex = k == 0 ? a : b;
        const auto t = std::find_if(out.made.begin(), out.made.end(), [&](const mesh::Tet& m) {
          return std::count(m.begin(), m.end(), apex) && std::count(m.begin(), m.end(), c) &&
                 std::count(m.begin(), m.end(), d);
        });
        if (t == out.made.end()) return std::nullopt;
        out.new_faces[k] = face_opposite(*t, (*t)[0] + (*t)[1] + (*t)[2] + (*t)[3] - apex - c - d);
      }
    }
    return out;
  }

  /// The collapse of surface edge uv onto v, if u lies inside one flat
  /// patch, the edge's link condition holds (the mesh stays a manifold with
  /// boundary: Dey, Edelsbrunner et al.'s condition with a vertex ω for the
  /// outside) and every reshaped element keeps a positive volume.
  std::optional<Change> collapse(int u, int v) const {
    const mesh::Point first = mesh::area_vector(body_, body_.boundary_faces[faces_at_[u][0]]).normalized();
    for (int g : faces_at_[u])
      if (body_.boundary_tags[g] != body_.boundary_tags[faces_at_[u][0]] ||
          mesh::area_vector(body_, body_.boundary_faces[g]).normalized().dot(first) < min_cosine_)
        return std::nullopt;
    // The links: vertices, edges and triangles opposite u (or v) in its
    // tets, and with ω its surface's edges and vertices.
    struct Link {
      std::set<int> vertices, surface_vertices;
      std::set<std::array<int, 2>> edges, surface_edges;
      std::set<std::array<int, 3>> triangles;
    };
    auto link = [&](int w) {
      Link l;
      for (int e : around_[w]) {
        const mesh::Triangle o = face_opposite(body_.tets[e], w);
        l.triangles.insert(mesh::sorted(o));
        for (int k = 0; k < 3; ++k) {
          l.vertices.insert(o[k]);
          l.edges.insert({std::min(o[k], o[(k + 1) % 3]), std::max(o[k], o[(k + 1) % 3])});
        }
      }
      for (int g : faces_at_[w]) {
        const mesh::Triangle& t = body_.boundary_faces[g];
        std::array<int, 2> opposite{};
        int k = 0;
        for (int x : t)
          if (x != w) l.surface_vertices.insert(x), opposite[k++] = x;
        l.surface_edges.insert({std::min(opposite[0], opposite[1]), std::max(opposite[0], opposite[1])});
      }
      return l;
    };
    const Link lu = link(u), lv = link(v);
    // Lk(uv): the tets holding both, and the surface triangles holding both.
    std::set<int> edge_vertices;
    std::set<std::array<int, 2>> edge_edges;
    Change out;
    for (const auto& [e, o] : shell_of(u, v)) {
      edge_vertices.insert(o.begin(), o.end());
      edge_edges.insert({std::min(o[0], o[1]), std::max(o[0], o[1])});
    }
    std::set<int> surface_edge_vertices; // x with uvx on the surface
    for (int g : faces_at_[u]) {
      const mesh::Triangle& t = body_.boundary_faces[g];
      if (std::find(t.begin(), t.end(), v) != t.end()) surface_edge_vertices.insert(t[0] + t[1] + t[2] - u - v);
    }
    for (int x : lu.vertices)
      if (lv.vertices.count(x) && !edge_vertices.count(x)) return std::nullopt;
    for (const auto& xy : lu.edges)
      if (lv.edges.count(xy) && !edge_edges.count(xy)) return std::nullopt;
    for (const auto& xyz : lu.triangles)
      if (lv.triangles.count(xyz)) return std::nullopt;
    for (int x : lu.surface_vertices)
      if (lv.surface_vertices.count(x) && !surface_edge_vertices.count(x)) return std::nullopt;
    for (const auto& xy : lu.surface_edges)
      if (lv.surface_edges.count(xy)) return std::nullopt;
    const auto& x = body_.nodes;
    for (int e : around_[u]) {
      out.shell.push_back(e);
      out.worst_shell = std::min(out.worst_shell, mesh::quality(body_, e));
      mesh::Tet t = body_.tets[e];
      if (std::find(t.begin(), t.end(), v) != t.end()) continue;
      std::replace(t.begin(), t.end(), u, v);
      out.made.push_back(t);
      out.worst_made = std::min(out.worst_made, mesh::quality(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
    }
    if (!(out.worst_made > 0.0)) return std::nullopt;
    for (int g : faces_at_[u]) {
      out.old_faces.push_back(g);
      mesh::Triangle t = body_.boundary_faces[g];
      if (std::find(t.begin(), t.end(), v) != t.end()) continue;
      std::replace(t.begin(), t.end(), u, v);
      out.new_faces.push_back(t);
    }
    out.gone = u;
    return out;
  }

private:
  /// The tets around edge ab, each with its two other vertices.
  std::vector<std::pair<int, std::array<int, 2>>> shell_of(int a, int b) const {
    std::vector<std::pair<int, std::array<int, 2>>> shell;
    for (int e : around_[a]) {
      const mesh::Tet& t = body_.tets[e];
      if (std::find(t.begin(), t.end(), b) == t.end()) continue;
      std::array<int, 2> other{};
      int k = 0;
      for (int v : t)
        if (v != a && v != b) other[k++] = v;
      shell.emplace_back(e, other);
    }
    return shell;
  }

  const mesh::TetMesh& body_;
  std::vector<std::vector<int>> around_;
  std::vector<std::vector<int>> faces_at_;
  std::map<std::array<int, 3>, int> face_of_;
  double min_cosine_;
};

} // namespace

SurfaceMending mend_surface(mesh::TetMesh& body, const std::vector<std::vector<double>*>& element_fields,
                            double threshold, double most_angle) {
  SurfaceMending out;
  out.changed.assign(body.tets.size(), 0);
  std::vector<char> gone(body.nodes.size(), 0);
  const double volume_before = mesh::volume(body);
  for (int pass = 0; pass < kPasses; ++pass) {
    const MendingPass adjacency(body, most_angle);
    std::vector<std::pair<double, int>> poor; // (quality, tet) of the elements with a surface face
    for (int e = 0; e < body.tet_count(); ++e) {
      const double q = mesh::quality(body, e);
      if (q >= threshold) continue;
      const mesh::Tet& t = body.tets[e];
      for (const auto& fv : mesh::kFaceVertices)
        if (adjacency.face(t[fv[0]], t[fv[1]], t[fv[2]]) >= 0) {
          poor.emplace_back(q, e);
          break;
        }
    }
    std::sort(poor.begin(), poor.end());
    std::vector<char> touched(body.nodes.size(), 0), dead_tet(body.tets.size(), 0),
        dead_face(body.boundary_faces.size(), 0);
    int changes = 0;
    for (const auto& [q, e] : poor) {
      if (dead_tet[e]) continue;
      std::optional<Change> best;
      auto consider = [&](std::optional<Change> change) {
        if (!change || !(change->worst_made > change->worst_shell)) return;
        for (int s : change->shell)
          for (int v : body.tets[s])
            if (touched[v]) return;
        if (!best || change->worst_made > best->worst_made) best = std::move(change);
      };
      const mesh::Tet t = body.tets[e];
      for (const auto& fv : mesh::kFaceVertices) {
        const int f = adjacency.face(t[fv[0]], t[fv[1]], t[fv[2]]);
        if (f < 0) continue;
        for (int k = 0; k < 3; ++k) {
          const int a = t[fv[k]], b = t[fv[(k + 1) % 3]];
          consider(adjacency.flip(f, a, b));
          consider(adjacency.collapse(a, b));
          consider(adjacency.collapse(b, a));
        }
      }
      if (!best) continue;
      transfer_fields(body, *best, element_fields);
      for (int s : best->shell) {
        dead_tet[s] = 1;
        for (int v : body.tets[s])
          touched[v] = 1;
      }
      out.worst_before = std::min(out.worst_before, best->worst_shell);
      body.tets.insert(body.tets.end(), best->made.begin(), best->made.end());
      out.changed.insert(out.changed.end(), best->made.size(), 1);
      dead_tet.insert(dead_tet.end(), best->made.size(), 0);
      const int tag = body.boundary_tags[best->old_faces[0]];
      for (int f : best->old_faces)
        dead_face[f] = 1;
      for (const mesh::Triangle& f : best->new_faces) {
        body.boundary_faces.push_back(f);
        body.boundary_tags.push_back(tag);
        dead_face.push_back(0);
      }
      if (best->gone >= 0)
        gone[best->gone] = 1, ++out.collapses;
      else
        ++out.flips;
      ++changes;
    }
    if (changes == 0) break;
    // Drop what the changes replaced.
    std::size_t kept = 0;
    for (std::size_t e = 0; e < body.tets.size(); ++e) {
      if (dead_tet[e]) continue;
      body.tets[kept] = body.tets[e];
      out.changed[kept] = out.changed[e];
      for (std::vector<double>* field : element_fields)
        (*field)[kept] = (*field)[e];
      ++kept;
    }
    body.tets.resize(kept);
    out.changed.resize(kept);
    for (std::vector<double>* field : element_fields)
      field->resize(kept);
    kept = 0;
    for (std::size_t f = 0; f < body.boundary_faces.size(); ++f) {
      if (dead_face[f]) continue;
      body.boundary_faces[kept] = body.boundary_faces[f];
      body.boundary_tags[kept++] = body.boundary_tags[f];
    }
    body.boundary_faces.resize(kept);
    body.boundary_tags.resize(kept);
  }
  // The collapsed nodes go; the others keep their order.
  std::vector<int> number(body.nodes.size(), -1);
  for (std::size_t n = 0; n < body.nodes.size(); ++n)
    if (!gone[n]) {
      number[n] = static_cast<int>(out.old_node.size());
      out.old_node.push_back(static_cast<int>(n));
      body.nodes[number[n]] = body.nodes[n];
    }
  body.nodes.resize(out.old_node.size());
  for (mesh::Tet& t : body.tets)
    for (int& v : t)
      v = number[v];
  for (mesh::Triangle& f : body.boundary_faces)
    for (int& v : f)
      v = number[v];
  for (int e = 0; e < body.tet_count(); ++e)
    if (out.changed[e]) out.worst_after = std::min(out.worst_after, mesh::quality(body, e));
  out.volume_change = mesh::volume(body) - volume_before;
  return out;
}

} // namespace anvil::remesh
