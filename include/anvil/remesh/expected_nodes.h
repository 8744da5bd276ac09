// How many nodes a remesh will make, estimated before CGAL runs: for the
// node budget and the line that says a long remesh is still at work
// (docs/remeshing.md).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <functional>

namespace anvil::remesh {

/// Nodes a remesh makes at edge lengths c × size(x): bulk / c³ + surface / c².
struct ExpectedNodes {
  double bulk = 0.0;    ///< a V / size³ summed over the elements (mesh/node_budget.h)
  double surface = 0.0; ///< b A / size² over the boundary faces, and the borders between the size field's levels
  double at(double c) const { return bulk / (c * c * c) + surface / (c * c); }
};

/// The nodes a remesh of `body` makes at edge lengths `size(x)`, taken at
/// each element's and boundary face's centroid, and, where the field asks
/// for less than `edge_length` (mm), the nodes its finer levels' borders add
/// down to `smallest` (mm; at least `edge_length`: uniform). Every length
/// scales with c, so do the levels' borders: they count as surface.
ExpectedNodes expected_nodes(const mesh::TetMesh& body, const std::function<double(const mesh::Point&)>& size,
                             double edge_length, double smallest);

} // namespace anvil::remesh
