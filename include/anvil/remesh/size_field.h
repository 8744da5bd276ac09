// The adaptive size field of a remesh (remeshing.size: adaptive): small
// elements where the dies squeeze the body thin (the flash), where a die's
// fillet or edge is pressed into it, and where it flows fast; graded so
// that neighbours differ by at most about kGradation.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/remesh/field_transfer.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <functional>
#include <span>
#include <vector>

namespace anvil::remesh {

/// Largest ratio of the sizes wanted at two points one (smaller) element
/// apart: the field grows by at most (kGradation - 1) mm per mm.
inline constexpr double kGradation = 1.5;
/// Elements wanted across the gap between two dies (the flash).
inline constexpr double kAcrossGap = 3.0;
/// Edge over a die's radius of curvature: a chord h on radius r sags by
/// h²/8r, so r/2 keeps a fillet's sag between two nodes to r/32.
inline constexpr double kEdgeOverRadius = 0.5;

/// Radius of curvature (mm) at each vertex of a triangulated die surface:
/// over each edge of two facets, the width of the strip they make (their
/// mean height over the edge) divided by the angle between their normals;
/// the smallest over a vertex's edges; infinite where the surface is flat.
std::vector<double> die_vertex_radii(const std::vector<mesh::Point>& vertices,
                                     const std::vector<std::array<int, 3>>& faces);

/// The edge length wanted at each node of `old` (mm), before the scale of a
/// try: the smallest of `coarse`; the gap between the two nearest dies over
/// kAcrossGap; kEdgeOverRadius times the radius of a die vertex, growing
/// away from it by the gradation; coarse·√(mean ε̄̇ / ε̄̇) of the node's
/// fastest element (`rate`, per element of `old`), so a rate 4 times the
/// body's volume-weighted mean gets half the edge; not below `smallest`;
/// then graded along the mesh's edges (h_j ≤ h_i + (kGradation − 1)·|x_i − x_j|).
/// `die_radii[d]` are die_vertex_radii of die d's triangles; the dies are at `dies_now`.
std::vector<double> wanted_sizes(const mesh::TetMesh& old, std::span<const double> rate, const scene::Scene& scene,
                                 std::span<const scene::DieState> dies_now,
                                 const std::vector<std::vector<double>>& die_radii, double coarse, double smallest);

/// wanted_sizes as a field: at a point, interpolated in the element of `old`
/// that holds it (`in_old` locates it; sampled once, on a grid), lowered to
/// each of the case's size boxes (remeshing.size_boxes, where their dies are
/// in `dies_now`) plus the gradation times the distance to it, times `scale`.
std::function<double(const mesh::Point&, double scale)>
adaptive_size(const mesh::TetMesh& old, const PointLocator& in_old, std::span<const double> rate,
              const scene::Scene& scene, std::span<const scene::DieState> dies_now, double coarse, double smallest);

} // namespace anvil::remesh
