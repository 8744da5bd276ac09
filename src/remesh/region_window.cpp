#include "anvil/remesh/region_window.h"

#include "anvil/core/error.h"
#include "anvil/mesh/manifold.h"
#include "anvil/remesh/rebuild_region.h"

#include <algorithm>
#include <set>

namespace anvil::remesh {
namespace {

/// Layers of kept tets tried around a region before it goes with the whole body.
constexpr int kMostLayers = 3;
/// A window over this share of the body saves CGAL too little to be cut out.
constexpr double kMostShare = 0.5;

} // namespace

std::optional<RegionWindow> region_window(const mesh::TetMesh& body, std::span<const char> rebuilt) {
  std::vector<char> in(rebuilt.begin(), rebuilt.end());
  if (std::find(in.begin(), in.end(), 1) == in.end()) return std::nullopt;
  std::set<mesh::Triangle> surface;
  int fresh_tag = 1;
  for (std::size_t f = 0; f < body.boundary_faces.size(); ++f) {
    surface.insert(mesh::sorted(body.boundary_faces[f]));
    fresh_tag = std::max(fresh_tag, body.boundary_tags[f] + 1);
  }
  for (int layer = 0; layer < kMostLayers; ++layer) {
    in = grow_region(body, std::move(in), 1);
    if (static_cast<double>(std::count(in.begin(), in.end(), 1)) > kMostShare * body.tet_count()) return std::nullopt;
    RegionWindow window;
    window.soup = body;
    std::vector<char> out(in.size());
    std::vector<char> used(body.nodes.size(), 0);
    for (std::size_t e = 0; e < in.size(); ++e) {
      out[e] = !in[e];
      if (!in[e]) continue;
      window.rebuilt.push_back(rebuilt[e]);
      for (int v : body.tets[e])
        used[v] = 1;
    }
    for (std::size_t v = 0; v < used.size(); ++v)
      if (used[v]) window.body_node.push_back(static_cast<int>(v));
    mesh::remove_tets(window.soup, out, body.boundary_faces, body.boundary_tags); // keeps the order of both
    // The faces towards the rest of the body: a tag of their own.
    for (std::size_t f = 0; f < window.soup.boundary_faces.size(); ++f) {
      mesh::Triangle in_body;
      for (int k = 0; k < 3; ++k)
        in_body[k] = window.body_node[window.soup.boundary_faces[f][k]];
      if (surface.count(mesh::sorted(in_body)) == 0) window.soup.boundary_tags[f] = fresh_tag;
    }
    if (mesh::is_ball(window.soup)) return window;
  }
  return std::nullopt;
}

RegionRemesh merge_window(const mesh::TetMesh& body, std::span<const char> rebuilt, const RegionWindow& window,
                          const RegionRemesh& inner) {
  // As remesh_region numbers its result on the whole body: the kept part
  // first, then the new nodes and tets.
  std::vector<int> number;
  RegionRemesh out = kept_part(body, rebuilt, RegionSurface::kept, number);
  // The window's new tets; a node CGAL left where it was keeps its body node.
  std::vector<int> inner_number(inner.mesh.nodes.size(), -1);
  for (int e = inner.kept_tets; e < inner.mesh.tet_count(); ++e) {
    mesh::Tet t = inner.mesh.tets[e];
    for (int& v : t) {
      if (inner_number[v] < 0) {
        const int old = inner.old_node[v] >= 0 ? window.body_node[inner.old_node[v]] : -1;
        if (old >= 0 && number[old] >= 0) {
          inner_number[v] = number[old];
        } else {
          inner_number[v] = static_cast<int>(out.mesh.nodes.size());
          out.mesh.nodes.push_back(inner.mesh.nodes[v]);
          out.old_node.push_back(old);
        }
      }
      v = inner_number[v];
    }
    out.mesh.tets.push_back(t);
  }
  // The boundary is the body's, face for face (on staying nodes).
  std::vector<mesh::Triangle> tagged;
  for (const mesh::Triangle& f : body.boundary_faces)
    tagged.push_back({number[f[0]], number[f[1]], number[f[2]]});
  mesh::build_boundary(out.mesh, tagged, body.boundary_tags);
  if (out.mesh.boundary_faces.size() != tagged.size())
    throw RunError("locally remeshed body: its rebuilt region does not fit the kept elements");
  if (const std::string why = mesh::fault(out.mesh); !why.empty()) throw RunError("locally remeshed body: " + why);
  return out;
}

} // namespace anvil::remesh
