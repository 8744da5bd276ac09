// The working surface of a rigid die (docs/design.md §3): what contact asks of it is
// the closest point to a body node, with the die's outward normal and the
// signed distance. Geometry is held in the die's own frame; the time loop
// translates queries by the die's displacement.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace anvil::die {

/// Closest point of the die surface to a query point.
struct SurfaceProjection {
  mesh::Point point;      ///< closest point on the surface (mm)
  Eigen::Vector3d normal; ///< unit, out of the die material (towards the body side)
  double distance = 0.0;  ///< signed: > 0 outside the die, < 0 penetrated (mm)
  /// The closest point is inside a facet (the query lies along that facet's
  /// normal), not on an edge or a corner; behind an open surface's border
  /// the side (sign) means little.
  bool on_facet = true;
  int facet = -1; ///< the facet of a triangulated surface the closest point lies on (-1: analytic)
};

/// Triangles of a surface, for output.
struct SurfaceTriangles {
  std::vector<mesh::Point> vertices;
  std::vector<std::array<int, 3>> faces;
};

/// `surface` with its triangles halved across their longest edge until no
/// edge is longer than `longest_edge` (mm), orientation kept. Fields
/// sampled on a die (die wear) need vertices where an STL's flat faces have
/// none.
SurfaceTriangles refine(const SurfaceTriangles& surface, double longest_edge);

class DieSurface {
public:
  virtual ~DieSurface() = default;
  virtual SurfaceProjection project(const mesh::Point& x) const = 0;
  /// project(x) for x close to a point already projected (`near`): a
  /// triangulated surface's search starts from near's closest point instead
  /// of finding a start of its own, which is most of a query's cost.
  virtual SurfaceProjection project_near(const mesh::Point& x, const SurfaceProjection& near) const {
    (void)near;
    return project(x);
  }
  /// project(x) when the surface comes closer to x than `reach` (mm),
  /// nothing otherwise. A triangulated surface bounds its search to that
  /// ball, so a point far from the die costs a few bounding boxes instead of
  /// a whole search (most of a body's nodes, when the question is only
  /// whether the die is near).
  virtual std::optional<SurfaceProjection> project_within(const mesh::Point& x, double reach) const {
    const SurfaceProjection p = project(x);
    if (std::abs(p.distance) < reach) return p;
    return std::nullopt;
  }
  /// The surface as triangles in the die frame (what the VTK series shows).
  virtual const SurfaceTriangles& triangles() const = 0;
  /// One line for the log.
  virtual std::string describe() const = 0;
};

/// The point of `surface` nearest `x` that moves only the free coordinates
/// of x (`free[k]` false: coordinate k stays, as on a symmetry plane): the
/// closest point, restricted, then again from there, which converges onto
/// the surface within the plane or along the axis (a node on the axis under
/// a cone's apex: by cos²α a pass). Passes end when one moves the point less
/// than `tolerance` (mm), or after 20 (an infinite tolerance: one pass).
/// What puts a node onto a die, after an increment and after a remesh.
mesh::Point project_keeping(const DieSurface& surface, mesh::Point x, const std::array<bool, 3>& free,
                            double tolerance);

/// An analytic flat die: the plane through `point` with outward normal
/// `normal`; shown in the output as a square of side 2 × `half_size`.
class PlaneSurface final : public DieSurface {
public:
  PlaneSurface(const mesh::Point& point, const Eigen::Vector3d& normal, double half_size);
  SurfaceProjection project(const mesh::Point& x) const override;
  const SurfaceTriangles& triangles() const override { return triangles_; }
  std::string describe() const override;

private:
  mesh::Point point_;
  Eigen::Vector3d normal_;
  SurfaceTriangles triangles_;
};

} // namespace anvil::die
