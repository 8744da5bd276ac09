// Closest facet of a triangulated body surface to a point: the search of
// node-to-facet contact between bodies (DESIGN §3), a CGAL AABB tree
// (TECH-NOTES §2) rebuilt once per increment, when the surface has moved.
#pragma once
#include "anvil/mesh/TetMesh.h"

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

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

} // namespace anvil::contact
