// Where a local remesh rebuilds a body (docs/design.md §4): the elements of poor
// quality now or after the next increment, and a few layers of elements
// around them, so that the rebuilt region has room to make good elements.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

namespace anvil::remesh {

/// Flags (one per tet of `part`) of the tets whose quality is below
/// `threshold` now or after `time_step` (s) at the nodal velocities of
/// `nodal` (4 values per node of `part`: v, p), and of `layers` layers of
/// tets around them (tets that share a node with a flagged one).
std::vector<char> rebuild_region(const mesh::TetMesh& part, const Eigen::Ref<const Eigen::VectorXd>& nodal,
                                 double time_step, double threshold, int layers);

/// Flags of the tets of `part` with a node within `radius` (mm) of one of
/// `points` (a die corner sunk into the body), and of `layers` layers around them.
std::vector<char> region_around(const mesh::TetMesh& part, std::span<const mesh::Point> points, double radius,
                                int layers);

/// `flagged` (one flag per tet of `part`) with `layers` layers of tets
/// around it (tets that share a node with a flagged one).
std::vector<char> grow_region(const mesh::TetMesh& part, std::vector<char> flagged, int layers);

/// The edges longer than `longest` (mm) between two nodes of the tets
/// `region` flags that kept tets share too (the region's border), as node
/// pairs, smaller first: CGAL would split them, and a region's remesh must
/// keep its border.
std::vector<std::array<int, 2>> long_border_edges(const mesh::TetMesh& part, const std::vector<char>& region,
                                                  double longest);

/// The mean length of the edges of the tets of `part` that `region` flags
/// (mm; each edge once per tet): the resolution a region has.
double mean_edge_length(const mesh::TetMesh& part, const std::vector<char>& region);

} // namespace anvil::remesh
