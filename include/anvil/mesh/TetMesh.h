// A linear tetrahedral mesh as a plain value (docs/design.md §1).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry> // cross products on Point
#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

namespace anvil::mesh {

using Point = Eigen::Vector3d;
using Tet = std::array<int, 4>;
using Triangle = std::array<int, 3>;

/// Coordinates (mm), connectivity (0-based node indices) and the boundary.
/// Invariants once `validate` has passed: every tet has positive orientation,
/// det[x1-x0, x2-x0, x3-x0] > 0; every node is used by a tet; boundary_faces
/// are exactly the tet faces used once, ordered so their normal
/// (x1-x0)×(x2-x0) points out of the body; boundary_tags[i] is the tag of
/// boundary_faces[i] (0 = untagged).
struct TetMesh {
  std::vector<Point> nodes;
  std::vector<Tet> tets;
  std::vector<Triangle> boundary_faces;
  std::vector<int> boundary_tags;

  int node_count() const { return static_cast<int>(nodes.size()); }
  int tet_count() const { return static_cast<int>(tets.size()); }
};

/// The faces of a positively oriented tet (local vertex numbers), each
/// ordered with its normal pointing out; face k is opposite vertex k.
inline constexpr int kFaceVertices[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// Face k of `t` (opposite its vertex k), its normal pointing out of `t`.
inline Triangle tet_face(const Tet& t, int k) {
  return {t[kFaceVertices[k][0]], t[kFaceVertices[k][1]], t[kFaceVertices[k][2]]};
}

/// A face's vertices in increasing order: the same key for any order or
/// orientation of its vertices.
inline Triangle sorted(Triangle f) {
  std::sort(f.begin(), f.end());
  return f;
}

/// Area vector of a face: ½ (x1−x0)×(x2−x0), along the outward normal of a
/// boundary face, of length its area (mm²).
inline Point area_vector(const TetMesh& mesh, const Triangle& face) {
  return 0.5 * (mesh.nodes[face[1]] - mesh.nodes[face[0]]).cross(mesh.nodes[face[2]] - mesh.nodes[face[0]]);
}

/// Fills mesh.boundary_faces from the tets (outward orientation) and gives each
/// face the tag of the matching triangle in `tagged` (any vertex order), else 0.
/// Triangles of `tagged` that are not on the boundary (internal surfaces) are ignored.
void build_boundary(TetMesh& mesh, const std::vector<Triangle>& tagged = {}, const std::vector<int>& tags = {});

/// What is wrong with `mesh`, naming the first offending element or node
/// (1-based numbers, as in mesh files): indices out of range, repeated
/// vertices, inverted or degenerate tets, unreferenced nodes, no tets;
/// empty when nothing is.
std::string fault(const TetMesh& mesh);

/// Throws InputError "`source`: fault(mesh)" when the mesh has a fault.
void validate(const TetMesh& mesh, const std::string& source);

/// Sum of tet volumes (mm³).
double volume(const TetMesh& mesh);
/// Sum of the boundary faces' areas (mm²).
double boundary_area(const TetMesh& mesh);
/// Each node's share of the surface (mm²): a third of the area vectors of
/// its boundary faces, summed, pointing out; zero off the surface.
std::vector<Point> node_area_vectors(const TetMesh& mesh);

/// 1 for each node on a boundary face of `mesh`, else 0.
std::vector<char> boundary_node_flags(const TetMesh& mesh);

/// A face two tets share: its nodes (sorted) and the two tets.
struct InnerFace {
  Triangle face;
  std::array<int, 2> tets;
};
/// Every face two tets of `mesh` share, in the order of their sorted nodes.
std::vector<InnerFace> inner_faces(const TetMesh& mesh);

/// For each node, the tets that have it as a vertex (in increasing order).
std::vector<std::vector<int>> tets_around_nodes(const TetMesh& mesh);

/// Where one body's entities sit in a mesh that holds several (see append).
struct MeshRange {
  int first_node = 0, node_count = 0;
  int first_tet = 0, tet_count = 0;
  int first_face = 0, face_count = 0;
  bool has_node(int node) const { return node >= first_node && node < first_node + node_count; }
};

/// For each node, the connected part of `mesh` it lies in (tets joined
/// through shared nodes), numbered from 0 in the order of their first nodes:
/// a scene's bodies, solved as one mesh, are its parts. A node no tet uses
/// is a part of its own.
std::vector<int> connected_parts(const TetMesh& mesh);

/// The smallest box holding every point of `points` (mm).
Eigen::AlignedBox3d bounding_box(std::span<const Point> points);
/// The smallest box holding every node of `mesh` (mm).
inline Eigen::AlignedBox3d bounding_box(const TetMesh& mesh) {
  return bounding_box(std::span<const Point>(mesh.nodes));
}

/// The range of a mesh that is one body: all of it.
MeshRange whole_range(const TetMesh& mesh);

/// Appends `part` to `mesh` (indices shifted) and returns where it went: the
/// bodies of a scene are solved as one mesh of disjoint parts.
MeshRange append(TetMesh& mesh, const TetMesh& part);

/// The part of `mesh` that `range` names, renumbered from 0 (inverse of append).
TetMesh extract(const TetMesh& mesh, const MeshRange& range);

/// Removes the tets `removed` flags and the nodes no tet uses then (the
/// others keep their order), and rebuilds the boundary with the tags of
/// `tagged` (build_boundary; triangles on a dropped node are left out).
/// Returns, per node left, its number before.
std::vector<int> remove_tets(TetMesh& mesh, const std::vector<char>& removed, const std::vector<Triangle>& tagged,
                             const std::vector<int>& tags);

/// The mesh of `tets` (node indices into `nodes`) with only the nodes they
/// use, numbered in their order of first use; no boundary.
TetMesh tets_mesh(const std::vector<Point>& nodes, const std::vector<Tet>& tets);

/// Sum of the volumes of the tets of `range` (mm³).
double volume(const TetMesh& mesh, const MeshRange& range);

} // namespace anvil::mesh
