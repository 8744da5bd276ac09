// Closest facet of a triangulated body surface to a point, and the facets
// near a box: the search of contact between bodies (docs/design.md §3), a CGAL AABB tree
// (docs/libraries.md §2) rebuilt once per increment, when the surface has moved.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace anvil::contact {

class SurfaceSearch {
public:
  /// The triangles `faces` (node indices into `nodes`); both are copied.
  SurfaceSearch(const std::vector<mesh::Point>& nodes, const std::vector<mesh::Triangle>& faces);
  ~SurfaceSearch();
  SurfaceSearch(SurfaceSearch&&) noexcept;
  SurfaceSearch& operator=(SurfaceSearch&&) noexcept;

  struct Closest {
    int face;          ///< index into the `faces` given
    mesh::Point point; ///< closest point on that face (mm)
  };
  Closest closest(const mesh::Point& x) const;

  /// The faces (indices into the `faces` given) whose bounding boxes meet
  /// `box`, into `found` (cleared first).
  void overlapping(const Eigen::AlignedBox3d& box, std::vector<int>& found) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

} // namespace anvil::contact
