// The common part of two tetrahedra: what a conservative transfer between two
// meshes of one body integrates over (the "supermesh" of Farrell et al. 2009,
// built one pair of tets at a time).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <array>

namespace anvil::mesh {

using TetCorners = std::array<Point, 4>;

/// Volume (mm³) of the intersection of two tets and its centroid (the
/// centroid is meaningless when the volume is 0).
struct Overlap {
  double volume = 0.0;
  Point centroid = Point::Zero();
};

/// Clips `a` by the four face planes of `b` (either orientation), keeping the
/// pieces as tets: a tet cut by a plane leaves one tet or a prism of three, so
/// at most 3⁴ pieces. Exact up to rounding; no allocation.
Overlap tet_overlap(const TetCorners& a, const TetCorners& b);

} // namespace anvil::mesh
