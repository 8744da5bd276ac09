// A body's contact surface as the other body of a pair sees it (docs/design.md §3):
// the body's boundary facets but those on its symmetry planes (beyond them
// lies the body's mirror image, and a node on the plane two bodies share,
// pressed a hair into the other body, would otherwise find the other
// body's symmetry face closest), their search tree, and the projections
// onto it of a node (closest point) and of a facet's quadrature points
// (contact/facet_quadrature.h). BodyContact weighs the projections into its
// constraints.
#pragma once
#include "anvil/contact/BodyContact.h"
#include "anvil/contact/SurfaceSearch.h"
#include "anvil/mesh/TetMesh.h"

#include <optional>
#include <vector>

namespace anvil::contact {

/// Where a point projects onto a contact surface.
struct SurfaceProjection {
  int facet;              ///< index into mesh.boundary_faces
  Eigen::Vector3d shape;  ///< N_j(ξ)
  Eigen::Vector3d normal; ///< the surface body's outward normal, towards the point
  double gap;             ///< δ₀ (mm)
};

/// A quadrature point of a facet and its projection.
struct FacetPoint {
  Eigen::Vector3d barycentric; ///< in the facet
  double area_fraction;        ///< of the facet
  SurfaceProjection hit;
};

/// The boundary of a run's mesh as contact sees it: the facets around each
/// node, and which lie on symmetry planes.
class ContactBoundary {
public:
  /// `symmetry_faces`: per boundary face, 1 on a symmetry plane (empty: none).
  ContactBoundary(const mesh::TetMesh& mesh, const std::vector<char>& symmetry_faces);

  const mesh::TetMesh& mesh() const { return mesh_; }
  const std::vector<int>& faces_of(int node) const { return node_faces_[node]; }
  bool on_symmetry_plane(int face) const { return !symmetry_faces_.empty() && symmetry_faces_[face]; }

  /// Outward unit normal of the contact surface at a boundary node: the
  /// area-weighted mean of its faces off the symmetry planes; zero when it
  /// has none (an interior node, or one on symmetry planes only).
  Eigen::Vector3d own_normal(int node) const;

  /// A node's tributary area (mm²) on its faces that look at a body of
  /// outward normal `other_normal` there.
  double tributary_area(int node, const Eigen::Vector3d& other_normal) const;

private:
  const mesh::TetMesh& mesh_;
  const std::vector<char>& symmetry_faces_;
  std::vector<std::vector<int>> node_faces_;
};

class ContactSurface {
public:
  ContactSurface(const ContactBoundary& boundary, const mesh::MeshRange& body);

  /// Projects x, a point of the other body whose outward normal there is
  /// `own`, to the closest point; nothing when it is `search_distance` or
  /// more from the surface.
  std::optional<SurfaceProjection> project(const mesh::Point& x, const Eigen::Vector3d& own,
                                           double search_distance) const;

  /// Self-contact: projects boundary node `node` of this surface's own body
  /// onto the closest facet of the body that faces one of the node's faces
  /// (outward normals opposing, n·n' < −½: across a fold, never the facets
  /// around the node) and does not hold it, the node over that facet, in
  /// front of it within `search_distance` or behind it by less than a tenth
  /// of its edge (a fold's sides pressed together; deeper is the body's
  /// other side across a thin section, not a contact). Nothing when none.
  std::optional<SurfaceProjection> project_self(int node, double search_distance) const;

  /// The quadrature points of facet f of the other body that lie over this
  /// surface within `search_distance`, with their projections, into
  /// `points` (cleared first), grouped by the facet they fall on.
  void facet_points(int f, const PairMethod& method, double search_distance, std::vector<FacetPoint>& points) const;

private:
  std::optional<SurfaceProjection> project_onto(const mesh::Point& x, int facet, double search_distance) const;
  void overlap_points(int f, double search_distance, std::vector<FacetPoint>& points) const;
  void subdivision_points(int f, int levels, double search_distance, std::vector<FacetPoint>& points) const;
  bool holds(int face) const;

  const ContactBoundary& boundary_;
  mesh::MeshRange body_;
  std::vector<int> facets_; ///< the surface's facets, indices into mesh.boundary_faces
  SurfaceSearch search_;
  mutable std::vector<int> near_; ///< scratch: facets near a facet of the other body
};

} // namespace anvil::contact
