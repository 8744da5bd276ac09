#include "anvil/mesh/TetMesh.h"

#include "anvil/core/error.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace anvil::mesh {

void build_boundary(TetMesh& mesh, const std::vector<Triangle>& tagged, const std::vector<int>& tags) {
  std::map<std::array<int, 3>, std::pair<Triangle, int>> once; // sorted key -> (oriented face, count)
  for (const Tet& t : mesh.tets) {
    for (const auto& fv : kFaceVertices) {
      const Triangle face{t[fv[0]], t[fv[1]], t[fv[2]]};
      auto [it, inserted] = once.try_emplace(sorted(face), face, 0);
      ++it->second.second;
    }
  }
  std::map<std::array<int, 3>, int> tag_of;
  for (std::size_t i = 0; i < tagged.size(); ++i)
    tag_of[sorted(tagged[i])] = tags[i];

  mesh.boundary_faces.clear();
  mesh.boundary_tags.clear();
  for (const auto& [key, face_count] : once) {
    if (face_count.second != 1) continue;
    mesh.boundary_faces.push_back(face_count.first);
    auto it = tag_of.find(key);
    mesh.boundary_tags.push_back(it == tag_of.end() ? 0 : it->second);
  }
}

std::string fault(const TetMesh& mesh) {
  const int n = mesh.node_count();
  if (mesh.tets.empty()) return "the mesh has no tetrahedra";
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const Tet& t = mesh.tets[e];
    for (int v : t) {
      if (v < 0 || v >= n)
        return "tetrahedron " + std::to_string(e + 1) + " refers to node " + std::to_string(v + 1) +
               ", but the mesh has " + std::to_string(n) + " nodes";
      used[v] = 1;
    }
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (t[a] == t[b]) return "tetrahedron " + std::to_string(e + 1) + " repeats node " + std::to_string(t[a] + 1);
    const double q = quality(mesh, e);
    if (!std::isfinite(q) || q <= 0.0)
      return "tetrahedron " + std::to_string(e + 1) +
             (q < 0.0 ? " is inverted (negative volume: det[x1-x0,x2-x0,x3-x0] < 0)" : " is degenerate (zero volume)");
    if (q < 1e-8)
      return "tetrahedron " + std::to_string(e + 1) + " is degenerate (quality " + std::to_string(q) + ", volume " +
             std::to_string(signed_volume(mesh, e)) + " mm3)";
  }
  for (int i = 0; i < n; ++i) {
    if (!used[i]) return "node " + std::to_string(i + 1) + " is not used by any tetrahedron";
    if (!mesh.nodes[i].allFinite()) return "node " + std::to_string(i + 1) + " has a non-finite coordinate";
  }
  return {};
}

std::vector<int> remove_tets(TetMesh& mesh, const std::vector<char>& removed, const std::vector<Triangle>& tagged,
                             const std::vector<int>& tags) {
  std::vector<Tet> tets;
  for (int e = 0; e < mesh.tet_count(); ++e)
    if (!removed[e]) tets.push_back(mesh.tets[e]);
  std::vector<int> number(mesh.nodes.size(), -1);
  for (const Tet& t : tets)
    for (int v : t)
      number[v] = 0;
  std::vector<Point> nodes;
  std::vector<int> old_node;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    if (number[n] == 0) {
      number[n] = static_cast<int>(nodes.size());
      nodes.push_back(mesh.nodes[n]);
      old_node.push_back(static_cast<int>(n));
    }
  for (Tet& t : tets)
    for (int& v : t)
      v = number[v];
  std::vector<Triangle> kept_tagged;
  std::vector<int> kept_tags;
  for (std::size_t f = 0; f < tagged.size(); ++f) {
    const Triangle& face = tagged[f];
    if (number[face[0]] < 0 || number[face[1]] < 0 || number[face[2]] < 0) continue;
    kept_tagged.push_back({number[face[0]], number[face[1]], number[face[2]]});
    kept_tags.push_back(tags[f]);
  }
  mesh.nodes = std::move(nodes);
  mesh.tets = std::move(tets);
  build_boundary(mesh, kept_tagged, kept_tags);
  return old_node;
}

void validate(const TetMesh& mesh, const std::string& source) {
  if (const std::string why = fault(mesh); !why.empty()) throw InputError(source + ": " + why);
}

double volume(const TetMesh& mesh) {
  double v = 0.0;
  for (int e = 0; e < mesh.tet_count(); ++e)
    v += signed_volume(mesh, e);
  return v;
}

double boundary_area(const TetMesh& mesh) {
  double a = 0.0;
  for (const Triangle& f : mesh.boundary_faces)
    a += area_vector(mesh, f).norm();
  return a;
}

std::vector<Point> node_area_vectors(const TetMesh& mesh) {
  std::vector<Point> share(mesh.nodes.size(), Point::Zero());
  for (const Triangle& f : mesh.boundary_faces) {
    const Point third = area_vector(mesh, f) / 3.0;
    for (int v : f)
      share[v] += third;
  }
  return share;
}

std::vector<InnerFace> inner_faces(const TetMesh& mesh) {
  std::vector<std::pair<Triangle, int>> faces; // (sorted face, tet)
  faces.reserve(4 * mesh.tets.size());
  for (int e = 0; e < mesh.tet_count(); ++e)
    for (const auto& fv : kFaceVertices)
      faces.emplace_back(sorted({mesh.tets[e][fv[0]], mesh.tets[e][fv[1]], mesh.tets[e][fv[2]]}), e);
  std::sort(faces.begin(), faces.end());
  std::vector<InnerFace> inner;
  for (std::size_t k = 0; k + 1 < faces.size(); ++k)
    if (faces[k].first == faces[k + 1].first) {
      inner.push_back({faces[k].first, {faces[k].second, faces[k + 1].second}});
      ++k;
    }
  return inner;
}

std::vector<char> boundary_node_flags(const TetMesh& mesh) {
  std::vector<char> on_boundary(mesh.nodes.size(), 0);
  for (const Triangle& f : mesh.boundary_faces)
    for (int node : f)
      on_boundary[node] = 1;
  return on_boundary;
}

std::vector<std::vector<int>> tets_around_nodes(const TetMesh& mesh) {
  std::vector<std::vector<int>> around(mesh.nodes.size());
  for (int e = 0; e < mesh.tet_count(); ++e)
    for (int v : mesh.tets[e])
      around[v].push_back(e);
  return around;
}

std::vector<int> connected_parts(const TetMesh& mesh) {
  // Union-find over the tets' nodes, each root the smallest node of its set.
  std::vector<int> root(mesh.nodes.size());
  for (std::size_t v = 0; v < root.size(); ++v)
    root[v] = static_cast<int>(v);
  auto find = [&root](int v) {
    while (root[v] != v)
      v = root[v] = root[root[v]];
    return v;
  };
  for (const Tet& t : mesh.tets)
    for (int k = 1; k < 4; ++k) {
      const int a = find(t[0]), b = find(t[k]);
      if (a != b) root[std::max(a, b)] = std::min(a, b);
    }
  std::vector<int> part(root.size(), -1);
  int parts = 0;
  for (std::size_t v = 0; v < root.size(); ++v) {
    const int r = find(static_cast<int>(v));
    part[v] = r == static_cast<int>(v) ? parts++ : part[r];
  }
  return part;
}

Eigen::AlignedBox3d bounding_box(std::span<const Point> points) {
  Eigen::AlignedBox3d box;
  for (const Point& x : points)
    box.extend(x);
  return box;
}

MeshRange whole_range(const TetMesh& mesh) {
  return {0, mesh.node_count(), 0, mesh.tet_count(), 0, static_cast<int>(mesh.boundary_faces.size())};
}

MeshRange append(TetMesh& mesh, const TetMesh& part) {
  const MeshRange range{mesh.node_count(),
                        part.node_count(),
                        mesh.tet_count(),
                        part.tet_count(),
                        static_cast<int>(mesh.boundary_faces.size()),
                        static_cast<int>(part.boundary_faces.size())};
  mesh.nodes.insert(mesh.nodes.end(), part.nodes.begin(), part.nodes.end());
  for (Tet t : part.tets) {
    for (int& v : t)
      v += range.first_node;
    mesh.tets.push_back(t);
  }
  for (Triangle f : part.boundary_faces) {
    for (int& v : f)
      v += range.first_node;
    mesh.boundary_faces.push_back(f);
  }
  mesh.boundary_tags.insert(mesh.boundary_tags.end(), part.boundary_tags.begin(), part.boundary_tags.end());
  return range;
}

TetMesh tets_mesh(const std::vector<Point>& nodes, const std::vector<Tet>& tets) {
  TetMesh out;
  std::vector<int> number(nodes.size(), -1);
  for (Tet t : tets) {
    for (int& v : t) {
      if (number[v] < 0) number[v] = static_cast<int>(out.nodes.size()), out.nodes.push_back(nodes[v]);
      v = number[v];
    }
    out.tets.push_back(t);
  }
  return out;
}

TetMesh extract(const TetMesh& mesh, const MeshRange& range) {
  TetMesh part;
  part.nodes.assign(mesh.nodes.begin() + range.first_node, mesh.nodes.begin() + range.first_node + range.node_count);
  for (int e = range.first_tet; e < range.first_tet + range.tet_count; ++e) {
    Tet t = mesh.tets[e];
    for (int& v : t)
      v -= range.first_node;
    part.tets.push_back(t);
  }
  for (int f = range.first_face; f < range.first_face + range.face_count; ++f) {
    Triangle t = mesh.boundary_faces[f];
    for (int& v : t)
      v -= range.first_node;
    part.boundary_faces.push_back(t);
    part.boundary_tags.push_back(mesh.boundary_tags[f]);
  }
  return part;
}

double volume(const TetMesh& mesh, const MeshRange& range) {
  double v = 0.0;
  for (int e = range.first_tet; e < range.first_tet + range.tet_count; ++e)
    v += signed_volume(mesh, e);
  return v;
}

} // namespace anvil::mesh
